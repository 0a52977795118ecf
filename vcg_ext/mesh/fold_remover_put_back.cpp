// Vertices put back after D-32 (fold_remover.h): those its fills took out and those given with
// no face (D-37), each into a standing face near it, across a border edge or closing a border
// corner (D-41), where the new triangles fit.
#include "mesh/fold_remover.h"

#include "geometry.h"
#include "mesh/triangle_against_faces.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace hrsr::folds {

namespace {

// A removed vertex goes back over a face at most this many of the face's longest sides off its
// plane (the lion's put back lie at a median of 0.13, 90 % under 0.38; a few reached 0.98).
constexpr double kMaxPutBackHeight = 0.5;
// D-60: a point whose normal is against the faces near it goes over one it lies this flat on, in
// the face's longest sides (at 0.03, 0.05, 0.1, 0.2 the lion keeps 35, 28, 21, 18 points in
// folds; a sheet of the other side closer than a tenth of a face is within the noise of this one).
constexpr double kMaxFlatAgainstHeight = 0.1;
// D-62: in that last pass a face is against a point's normal only beyond this angle: 180° less
// the 60° within which RsR takes two normals to agree (θ's default), i.e. within 60° of opposed.
constexpr double kMinAgainstAngle = 120.0 * M_PI / 180.0;
// A vertex at the border goes back as triangles that close its corner, or as one triangle across
// a border edge (D-41), only if no angle of them is smaller (a sliver hanging off the border is
// worse than a point left out).
constexpr double kMinBorderPutBackAngle = 15.0 * M_PI / 180.0;
// D-57: the points still out go back in at most this many rounds (the last placements on the
// lion come in the third, on the dragon vertices and the LMS400 table in the second).
constexpr std::size_t kPutBackRounds = 4;
// A walk around a vertex's fan gives up after this many faces (a fan is far smaller).
constexpr std::size_t kMaxFanWalk = 1024;

} // namespace

std::size_t Remover::reinsert(const std::vector<std::uint32_t>& removed,
                              const std::vector<std::uint32_t>& corners) {
    std::size_t back = 0;
    for (std::uint32_t r : removed) {
        if (!faces_of(r).empty()) continue; // not removed after all
        std::vector<std::uint32_t> faces;
        for (std::uint32_t w : corners)
            for (std::uint32_t f : faces_of(w)) faces.push_back(f);
        std::sort(faces.begin(), faces.end());
        faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
        std::vector<std::pair<double, std::uint32_t>> candidates; // (−angle, face)
        for (std::uint32_t f : faces) {
            double smallest = 4;
            bool proper_split = true;
            for (const Triangle& t : split_around(triangles_[f], r)) {
                proper_split = proper_split && proper(t, true) && !repeats_a_face(t);
                smallest = std::min(smallest, angle(t));
            }
            if (proper_split) candidates.emplace_back(-smallest, f);
        }
        std::sort(candidates.begin(), candidates.end());
        for (const auto& [negative_angle, f] : candidates) {
            const std::array<Triangle, 3> split = split_around(triangles_[f], r);
            alive_[f] = 0;
            bool fits = true;
            for (std::size_t k = 0; k < 3 && fits; ++k) {
                fits = !intersects_standing(welded(split[k]));
                for (std::size_t l = 0; l < k && fits; ++l)
                    fits = !geometry_.intersect(welded(split[k]), welded(split[l]));
            }
            alive_[f] = 1;
            if (!fits) continue;
            retire(f);
            for (const Triangle& t : split) add(t);
            ++back;
            break;
        }
    }
    return back;
}

void Remover::put_back_the_rest(PutBack how) {
    // D-57: the points still out, in rounds while the last one placed any (at most
    // kPutBackRounds): a split may leave a face that another point fits into.
    std::vector<std::uint32_t> waiting;
    for (std::uint32_t v = 0; v + 1 < at_.start.size(); ++v)
        if (representative_[v] == v && (lost_all_faces(v) || never_had_a_face(v)) &&
            !point_has_standing_face(v)) // not a copy D-55 left out where another stands
            waiting.push_back(v);
    for (std::size_t round = 0; round < kPutBackRounds && !waiting.empty(); ++round) {
        const std::size_t before = waiting.size();
        waiting.erase(std::remove_if(waiting.begin(), waiting.end(),
                                     [&](std::uint32_t v) {
                                         const bool had_faces = at_.begin(v) != at_.end(v);
                                         // D-57: a split that turns as the face it replaces
                                         // does but does not face its corners' normals, as
                                         // D-55 takes one, where no facing split fits (and
                                         // D-60's, last, where neither fits).
                                         const bool back = put_back(v, how);
                                         (had_faces ? reinserted_ : placed_) += back;
                                         return back;
                                     }),
                      waiting.end());
        if (waiting.size() == before) break;
    }
}

bool Remover::never_had_a_face(std::uint32_t v) const {
    return at_.begin(v) == at_.end(v) && !has_standing_face(v);
}

bool Remover::lost_all_faces(std::uint32_t v) const {
    if (at_.begin(v) == at_.end(v)) return false;
    for (std::uint32_t e = at_.begin(v); e < at_.end(v); ++e)
        if (alive_[at_.corner[e] / 3]) return false;
    return !has_standing_face(v);
}

double Remover::fan_reach(std::uint32_t v) const {
    if (at_.begin(v) == at_.end(v)) return grid_.cell_size();
    double sum = 0;
    std::size_t edges = 0;
    for (std::uint32_t e = at_.begin(v); e < at_.end(v); ++e)
        for (std::uint32_t w : triangles_[at_.corner[e] / 3])
            if (w != v) {
                sum += (positions_[w] - positions_[v]).Norm();
                ++edges;
            }
    return edges ? sum / double(edges) : 0;
}

std::optional<std::uint32_t> Remover::across(std::uint32_t f, int k) const {
    const std::uint32_t a = triangles_[f][k], b = triangles_[f][(k + 1) % 3];
    std::optional<std::uint32_t> found;
    any_face_index(b, [&](std::uint32_t g) {
        const Triangle& t = triangles_[g];
        for (int j = 0; j < 3; ++j)
            if (g != f && t[j] == b && t[(j + 1) % 3] == a) found = g;
        return found.has_value();
    });
    return found;
}

std::vector<Remover::Split> Remover::splits_near(std::uint32_t v, PutBack how) {
    const double r = fan_reach(v);
    gather_standing(Box{positions_[v] - Vec3(r, r, r), positions_[v] + Vec3(r, r, r)});
    std::vector<std::uint32_t> faces;
    for (const auto& [f, b] : near_.found()) faces.push_back(f);
    std::sort(faces.begin(), faces.end());
    std::vector<Split> splits;
    for (std::uint32_t f : faces) {
        // Every split below goes over f: none is taken where f is not (put_back's test).
        if (!goes_over(v, f, how) || of_a_small_piece(f)) continue;
        const Triangle t = triangles_[f];
        const std::array<Triangle, 3> three = split_around(t, v);
        splits.push_back({{f}, {three.begin(), three.end()}, {f, f, f}});
        for (int k = 0; k < 3; ++k) {
            const std::optional<std::uint32_t> g = across(f, k);
            const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
            if (!g) {
                // D-41: next to the border edge a → b (beyond it, on it, or over f near it),
                // one triangle across the edge (not a sliver) or f split in two at v; the
                // border then runs a → v → b.
                const Triangle ear{b, a, v};
                if (angle(ear) >= kMinBorderPutBackAngle) splits.push_back({{}, {ear}, {f}, true});
                splits.push_back({{f}, {{a, v, c}, {v, b, c}}, {f, f}, true});
                add_corner_fill(f, k, v, splits);
                continue;
            }
            if (*g < f) continue; // each edge once
            std::uint32_t d = a;
            for (std::uint32_t w : triangles_[*g])
                if (w != a && w != b) d = w;
            splits.push_back(
                {{f, *g}, {{a, v, c}, {v, b, c}, {b, v, d}, {v, a, d}}, {f, f, *g, *g}});
        }
    }
    return splits;
}

void Remover::add_corner_fill(std::uint32_t f, int k, std::uint32_t v,
                              std::vector<Split>& splits) const {
    const std::uint32_t a = triangles_[f][k], b = triangles_[f][(k + 1) % 3];
    std::uint32_t g = f;
    int j = (k + 1) % 3; // g's edge b → next
    for (std::size_t steps = 0;; ++steps) {
        const std::optional<std::uint32_t> next = across(g, j);
        if (!next) break;
        if (*next == f || steps > kMaxFanWalk) return; // a closed fan: no corner here
        g = *next;
        j = int(std::find(triangles_[g].begin(), triangles_[g].end(), b) - triangles_[g].begin());
    }
    const std::uint32_t c = triangles_[g][(j + 1) % 3];
    const Triangle first{b, a, v}, second{c, b, v};
    if (c != a && std::min(angle(first), angle(second)) >= kMinBorderPutBackAngle)
        splits.push_back({{}, {first, second}, {f, g}});
}

bool Remover::goes_over(std::uint32_t v, std::uint32_t f, PutBack how) const {
    if (!within_height(v, f, kMaxPutBackHeight)) return false;
    const Vec3 n = normal_of(triangles_[f]);
    const double cosine = n.dot(normals_[v]);
    if (cosine > 0) return true;
    if (how != PutBack::or_flat_against) return false;
    // D-62: a normal less than kMinAgainstAngle off the face says nothing of the side the point
    // is on (estimated in noise, at a rim); only one nearer opposed marks the other sheet.
    if (cosine > std::cos(kMinAgainstAngle) * n.Norm() * normals_[v].Norm()) return true;
    // D-60: a normal turned against the surface it lies on (a clump of flipped normals, the
    // noise of a crumpled patch) keeps no point out once nothing else takes it.
    return within_height(v, f, kMaxFlatAgainstHeight);
}

bool Remover::within_height(std::uint32_t v, std::uint32_t f, double sides) const {
    const Triangle& t = triangles_[f];
    const Vec3 n = normal_of(t);
    double longest = 0;
    for (int k = 0; k < 3; ++k)
        longest = std::max(longest, (positions_[t[k]] - positions_[t[(k + 1) % 3]]).Norm());
    return std::abs((positions_[v] - positions_[t[0]]).dot(n)) <= sides * longest * n.Norm();
}

bool Remover::put_back(std::uint32_t v, PutBack how) {
    // The splits `how` allows, found once; those over faces facing v's normal tried first
    // (facing their corners' normals, then turned), those over faces against it (D-60) after.
    const std::vector<Split> splits = splits_near(v, how);
    if (fit_split(v, splits, true, PutBack::or_turned) ||
        fit_split(v, splits, false, PutBack::or_turned))
        return true;
    return how == PutBack::or_flat_against &&
           (fit_split(v, splits, true, how) || fit_split(v, splits, false, how));
}

bool Remover::fit_split(std::uint32_t v, const std::vector<Split>& splits, bool facing,
                        PutBack how) {
    // (lengthens the border, −smallest angle, split): a longer border only where nothing else
    // fits
    std::vector<std::tuple<bool, double, std::size_t>> candidates;
    Box reach{positions_[v], positions_[v]}; // of every candidate's triangles
    for (std::size_t i = 0; i < splits.size(); ++i) {
        const Split& split = splits[i];
        double smallest = 4;
        bool proper_split = std::all_of(split.source.begin(), split.source.end(),
                                        [&](std::uint32_t f) { return goes_over(v, f, how); });
        for (std::size_t k = 0; k < split.triangles.size() && proper_split; ++k) {
            const Triangle& t = split.triangles[k];
            proper_split = normal_of(t).dot(normal_of(triangles_[split.source[k]])) > 0 &&
                           proper(t, facing) && !repeats_a_face(t);
            smallest = std::min(smallest, angle(t));
        }
        if (!proper_split) continue;
        candidates.emplace_back(split.lengthens_border, -smallest, i);
        for (const Triangle& t : split.triangles)
            for (std::uint32_t w : t) reach.add(positions_[w]);
    }
    if (candidates.empty()) return false;
    std::sort(candidates.begin(), candidates.end());
    gather_standing(reach); // one search for all candidates
    for (const auto& [lengthens, negative_angle, i] : candidates) {
        const Split& split = splits[i];
        for (std::uint32_t f : split.faces) alive_[f] = 0;
        bool fits = true;
        for (std::size_t k = 0; k < split.triangles.size() && fits; ++k) {
            fits = !intersects_gathered_standing(welded(split.triangles[k]));
            for (std::size_t l = 0; l < k && fits; ++l)
                fits = !geometry_.intersect(welded(split.triangles[k]), welded(split.triangles[l]));
        }
        for (std::uint32_t f : split.faces) alive_[f] = 1;
        if (!fits) continue;
        for (std::uint32_t f : split.faces) retire(f);
        for (const Triangle& t : split.triangles) add(t);
        if (lengthens) ++joined_border_;
        return true;
    }
    return false;
}

bool Remover::intersects_gathered_standing(const Triangle& t) const {
    const Box box = geometry_.box(t);
    const TriangleAgainstFaces against(geometry_, t);
    for (const auto& [f, b] : near_.found())
        if (alive_[f] && box.overlaps(b) && against.intersects(geometry_.triangle(f))) return true;
    return false;
}

} // namespace hrsr::folds
