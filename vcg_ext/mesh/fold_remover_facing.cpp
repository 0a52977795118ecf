// D-64 and D-65 (fold_remover.h): faces winding against their corners' normals, turned by edge
// flips once the folds are out and every point is placed, then refilled around a corner.
#include "mesh/fold_remover.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace hrsr::folds {

namespace {

// Passes of each kind: a face that could not turn may after its neighbour has (a chain along a
// fold).
constexpr int kMaxFacingPasses = 4;
// D-65: an edge is a sharp fold when its two faces' normals are more than this apart (the
// measure of D-64's table: such edges are folds that shading shows as creases).
constexpr double kSharpFoldDegrees = 170;

} // namespace

std::vector<std::uint32_t> Remover::turn_faces_against_normals(FoldRemovalStats& stats) {
    std::vector<std::uint32_t> against;
    for (std::uint32_t f = 0; f < triangles_.size(); ++f)
        if (alive_[f] && !faces_its_normals(triangles_[f]) &&
            !geometry_.degenerate(welded(triangles_[f])))
            against.push_back(f);
    stats.faces_against_normals = against.size();
    for (const bool strict : {true, false})
        for (int pass = 0; pass < kMaxFacingPasses; ++pass) {
            std::vector<std::uint32_t> next;
            bool flipped = false;
            for (std::uint32_t f : against) {
                if (!alive_[f] || faces_its_normals(triangles_[f]))
                    continue; // turned by a neighbour's flip
                const std::vector<std::uint32_t> made = turn(f, strict);
                if (made.empty()) {
                    next.push_back(f);
                    continue;
                }
                flipped = true;
                ++stats.facing_flips;
                for (std::uint32_t h : made)
                    if (!faces_its_normals(triangles_[h])) next.push_back(h);
            }
            against.swap(next);
            if (!flipped) break;
        }
    return against;
}

void Remover::refill_faces_against_normals(const std::vector<std::uint32_t>& against,
                                           FoldRemovalStats& stats) {
    // A corner that failed is not tried again before a refill is kept: an undone attempt leaves
    // the mesh as it was, so the outcome would be the same (the output is that of trying).
    std::unordered_map<std::uint32_t, std::size_t> failed_after; // corner → refills kept then
    std::size_t kept_refills = 0;
    for (std::uint32_t f : against) {
        if (!alive_[f] || faces_its_normals(triangles_[f])) continue; // refilled with another
        const Triangle t = triangles_[f];
        for (std::uint32_t v : t) {
            const auto failed = failed_after.find(v);
            if (failed != failed_after.end() && failed->second == kept_refills) continue;
            if (!inner_vertex(v)) continue;
            // No more sharp folds than before: a corner put back far off its fill's plane (noise
            // deeper than the spacing) turns a gentle fold into a sharp one (without this test
            // the bunny's edges between faces over 170° apart went 191 → 269; session 54).
            const std::size_t sharp_before = sharp_edges(faces_of(v));
            const Undo undo = begin_undo();
            // The fill faces its normals (refill's `facing`), and so does the put-back's split
            // of a face into three around v (reinsert(): v comes back as an inner vertex).
            // The fill best by its angles only: the search around crossings found 0.6–3 % more
            // refills at about three times the step's time (ALGORITHM.md D-65).
            bool kept = refill(v, true, FillSearch::by_angle) && point_has_standing_face(v);
            if (kept) {
                std::vector<std::uint32_t> made;
                for (auto g = std::uint32_t(undo.faces); g < triangles_.size(); ++g)
                    if (alive_[g]) made.push_back(g);
                kept = sharp_edges(made) <= sharp_before;
            }
            end_undo(undo, kept);
            if (kept) {
                ++kept_refills;
                break;
            }
            failed_after[v] = kept_refills;
        }
    }
    stats.facing_refills += kept_refills;
    stats.faces_against_normals_left =
        std::size_t(std::count_if(against.begin(), against.end(), [&](std::uint32_t f) {
            return alive_[f] && !faces_its_normals(triangles_[f]);
        }));
}

std::size_t Remover::sharp_edges(const std::vector<std::uint32_t>& faces) const {
    static const double cos_sharp = std::cos(kSharpFoldDegrees * M_PI / 180.0);
    std::size_t sharp = 0;
    for (std::uint32_t f : faces)
        for (int k = 0; k < 3; ++k) {
            const std::optional<std::uint32_t> g = across(f, k);
            if (!g || (*g < f && std::find(faces.begin(), faces.end(), *g) != faces.end()))
                continue; // the border, or an edge counted from g
            const Vec3 a = normal_of(triangles_[f]), b = normal_of(triangles_[*g]);
            sharp += a.dot(b) < cos_sharp * a.Norm() * b.Norm();
        }
    return sharp;
}

// f = (a, b, c) and g = (b, a, d) across f's edge k become (c, a, d) and (d, b, c).
std::vector<std::uint32_t> Remover::turn(std::uint32_t f, bool strict) {
    const Triangle t = triangles_[f];
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
        std::uint32_t g = kNoFace;
        std::size_t across = 0;
        any_face_index(b, [&](std::uint32_t h) {
            const Triangle& s = triangles_[h];
            for (int i = 0; i < 3; ++i)
                if (s[i] == b && s[(i + 1) % 3] == a) {
                    g = h;
                    ++across;
                }
            return false;
        });
        if (across != 1 || g == f) continue; // the border, or an edge held twice
        const Triangle& s = triangles_[g];
        const auto at = std::size_t(std::find(s.begin(), s.end(), b) - s.begin());
        const std::uint32_t d = s[(at + 2) % 3];
        if (d == c || has_edge(c, d)) continue;
        const Triangle first{c, a, d}, second{d, b, c};
        const int before = 1 + !faces_its_normals(s),
                  after = !faces_its_normals(first) + !faces_its_normals(second);
        if (strict ? after > 0 : after >= before) continue;
        if (geometry_.degenerate(welded(first)) || geometry_.degenerate(welded(second)) ||
            repeats_a_face(first) || repeats_a_face(second))
            continue;
        alive_[f] = alive_[g] = 0; // while the new faces are tested
        const bool crosses = geometry_.intersect(welded(first), welded(second)) ||
                             intersects_standing(welded(first)) ||
                             intersects_standing(welded(second));
        alive_[f] = alive_[g] = 1;
        if (crosses) continue;
        retire(f);
        retire(g);
        add(first);
        add(second);
        const auto n = std::uint32_t(triangles_.size());
        return {n - 2, n - 1};
    }
    return {};
}

} // namespace hrsr::folds
