// Small pieces that lie on another surface join it (D-55, fold_remover.h): RsR on a noisy cloud
// leaves bubbles of a few points and scraps beside the surface they belong to.
#include "mesh/fold_remover.h"

#include <algorithm>
#include <cmath>

namespace hrsr::folds {

namespace {

// A larger piece is a surface of its own, not a scrap: 200 faces are about 100 points, RsR's
// smallest component (`min_component_size`).
constexpr std::size_t kMaxAbsorbedPieceFaces = 200;
// D-56: a piece inside a loop of at most kMaxOptimisedHole (48) edges covers at most about a
// disc of that perimeter, 48² / 4π ≈ 183 spacings², some 370 faces; twice that for the folds
// of noise.
constexpr std::size_t kMaxPieceInHoleFaces = 800;
// D-56: at most one point in kMaxLostInHole of such a piece may stay out.
constexpr std::size_t kMaxLostInHole = 8;
// D-56: a piece closes a hole only if it has at least this share of the points a surface over
// the hole would have (a vertex per √3/2 spacings² of a mesh of equilateral triangles). Without
// it the RsR lion closed loops of up to 42 edges around scraps of 3 points.
constexpr double kMinHoleFill = 0.5;

} // namespace

Vec3 Remover::area_vector(const std::vector<std::uint32_t>& loop) const {
    Vec3 twice(0, 0, 0);
    for (std::size_t i = 0; i < loop.size(); ++i)
        twice += positions_[loop[i]] ^ positions_[loop[(i + 1) % loop.size()]];
    return twice / 2;
}

bool Remover::is_a_hole(const std::vector<std::uint32_t>& loop) const {
    Vec3 normals(0, 0, 0);
    for (std::uint32_t c : loop) normals += normals_[c];
    return area_vector(loop).dot(normals) > 0;
}

bool Remover::surrounds(const std::vector<std::uint32_t>& loop, const Vec3& p) const {
    // The loop's plane: Newell's normal (its area vector) through the corners' mean.
    Vec3 normal = area_vector(loop), mean(0, 0, 0);
    double perimeter = 0;
    const std::size_t m = loop.size();
    for (std::size_t i = 0; i < m; ++i) {
        mean += positions_[loop[i]];
        perimeter += (positions_[loop[(i + 1) % m]] - positions_[loop[i]]).Norm();
    }
    mean /= double(m);
    if (normal.Norm() == 0) return false;
    normal.Normalize();
    // A piece further off the plane than the loop's radius is not in the hole.
    if (std::abs((p - mean).dot(normal)) > perimeter / (2 * M_PI)) return false;
    // Winding number of the loop around p, in the plane.
    Vec3 u = normal ^ (std::abs(normal[0]) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
    u.Normalize();
    const Vec3 w = normal ^ u;
    double turned = 0;
    for (std::size_t i = 0; i < m; ++i) {
        const Vec3 a = positions_[loop[i]] - p, b = positions_[loop[(i + 1) % m]] - p;
        turned += std::atan2(a.dot(u) * b.dot(w) - a.dot(w) * b.dot(u),
                             a.dot(u) * b.dot(u) + a.dot(w) * b.dot(w));
    }
    return std::abs(turned) > M_PI; // 2π around, 0 outside
}

ConcurrentSets Remover::standing_pieces() const {
    ConcurrentSets sets(positions_.size(), exec_);
    parallel_for_blocks(exec_, triangles_.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t f = first; f < end; ++f)
                                if (alive_[f]) {
                                    const Triangle& t = triangles_[f];
                                    sets.unite(t[0], t[1]);
                                    sets.unite(t[1], t[2]);
                                }
                        });
    return sets;
}

std::vector<std::vector<std::uint32_t>> Remover::small_pieces(std::size_t max_faces) const {
    ConcurrentSets sets = standing_pieces();
    std::size_t count = 0;
    const std::vector<std::uint32_t> label = sets.labels(exec_, count);
    std::vector<std::size_t> faces(count, 0);
    for (std::size_t f = 0; f < triangles_.size(); ++f)
        if (alive_[f]) ++faces[label[triangles_[f][0]]];
    const std::size_t pieces =
        std::size_t(std::count_if(faces.begin(), faces.end(), [](std::size_t c) { return c > 0; }));
    std::vector<std::vector<std::uint32_t>> small;
    if (pieces < 2) return small;
    // The largest piece stays (the first of several as large).
    const auto largest = std::size_t(std::max_element(faces.begin(), faces.end()) - faces.begin());
    std::vector<std::int32_t> slot(count, -1);
    for (std::size_t p = 0; p < count; ++p)
        if (p != largest && faces[p] > 0 && faces[p] <= max_faces) {
            slot[p] = std::int32_t(small.size());
            small.emplace_back();
        }
    for (std::size_t f = 0; f < triangles_.size(); ++f)
        if (alive_[f] && slot[label[triangles_[f][0]]] >= 0)
            small[std::size_t(slot[label[triangles_[f][0]]])].push_back(std::uint32_t(f));
    return small;
}

bool Remover::point_has_standing_face(std::uint32_t v) const {
    if (has_standing_face(v)) return true;
    const auto copies = copies_.find(representative_[v]);
    return copies != copies_.end() &&
           std::any_of(copies->second.begin(), copies->second.end(),
                       [&](std::uint32_t c) { return has_standing_face(c); });
}

void Remover::absorb_small_pieces(FoldRemovalStats& stats) {
    // Largest first: a scrap beside a piece in a hole can go over the fill that piece makes.
    std::vector<std::vector<std::uint32_t>> pieces = small_pieces(kMaxPieceInHoleFaces);
    std::stable_sort(pieces.begin(), pieces.end(),
                     [](const auto& a, const auto& b) { return a.size() > b.size(); });
    in_small_piece_.assign(triangles_.size(), 0);
    const auto mark = [&](const std::vector<std::uint32_t>& piece, std::uint8_t in) {
        for (std::uint32_t f : piece) in_small_piece_[f] = in;
    };
    for (const std::vector<std::uint32_t>& piece : pieces) mark(piece, 1);
    for (const std::vector<std::uint32_t>& piece : pieces) {
        // A piece that took points of one before it is no longer the faces it was: it stays.
        if (!std::all_of(piece.begin(), piece.end(), [&](std::uint32_t f) { return alive_[f]; }))
            continue;
        mark(piece, 0);
        // In a hole, the hole closes under it (D-56), even leaving a few of its points out,
        // rather than its points lengthening the hole's border (D-41); else its points go over
        // the surface near them (D-55), and only where that fails over another small piece
        // (scraps of noise become one).
        const bool small_enough_to_place = piece.size() <= kMaxAbsorbedPieceFaces;
        scraps_take_points_ = false;
        bool absorbed = absorb_piece(piece, true, stats) ||
                        (small_enough_to_place && absorb_piece(piece, false, stats));
        scraps_take_points_ = true;
        if (!absorbed && small_enough_to_place && absorb_piece(piece, false, stats)) {
            absorbed = true;
            mark_faces_made_on_small_pieces();
        }
        if (!absorbed) mark(piece, 1);
    }
    in_small_piece_.clear();
}

bool Remover::ever_in_a_small_piece(std::uint32_t v) const {
    const auto marked = [&](std::uint32_t f) { return marked_small(f); };
    for (std::uint32_t e = at_.begin(v); e < at_.end(v); ++e)
        if (marked(at_.corner[e] / 3)) return true;
    const auto it = added_at_.find(v);
    return it != added_at_.end() && std::any_of(it->second.begin(), it->second.end(), marked);
}

void Remover::mark_faces_made_on_small_pieces() {
    // The faces made since the marks were last sized: those at another small piece's vertices
    // are that piece's (a split of one of its faces, or an ear on its border); the rest lie on
    // the surface. The placed piece's own faces were unmarked before it was tried.
    const std::size_t marked_before = in_small_piece_.size();
    std::vector<std::uint32_t> on_small;
    for (std::size_t f = marked_before; f < triangles_.size(); ++f)
        if (alive_[f] && std::any_of(triangles_[f].begin(), triangles_[f].end(),
                                     [&](std::uint32_t c) { return ever_in_a_small_piece(c); }))
            on_small.push_back(std::uint32_t(f));
    in_small_piece_.resize(triangles_.size(), 0);
    for (std::uint32_t f : on_small) in_small_piece_[f] = 1;
}

bool Remover::absorb_piece(const std::vector<std::uint32_t>& piece, bool close_holes_around,
                           FoldRemovalStats& stats) {
    const Undo undo = begin_undo();
    std::vector<std::uint32_t> points;
    for (std::uint32_t f : piece) {
        retire(f);
        points.insert(points.end(), triangles_[f].begin(), triangles_[f].end());
    }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    // Points of an earlier piece joined this one's border without splitting its faces (a
    // corner closed, a triangle across an edge): its vertices stand in those new faces, and
    // the piece is not what was counted either.
    bool absorbed = std::none_of(points.begin(), points.end(),
                                 [&](std::uint32_t v) { return has_standing_face(v); });
    if (absorbed && close_holes_around) absorbed = close_holes_under(piece, points);
    // A point whose copy stands elsewhere (a bubble pinched off the surface at it) is in
    // the mesh still; every other goes back over a face near it, or the piece stays.
    std::size_t placed = 0;
    const auto place = [&](std::uint32_t v) {
        if (point_has_standing_face(v)) return true;
        // The noise of the written coordinates may turn the faces there every way: a split
        // that faces away from the corners' normals but turns as the face it replaces does
        // and crosses nothing is kept too (the bubbles of the 1M graded triple torus). D-63: a
        // scrap's normals, estimated in that noise, may lie nearly in the surface's plane; they
        // go as D-60's last pass takes points (D-62: a face is against them only beyond
        // 120°; D-60: or they lie flat on it).
        const bool back = put_back(v, PutBack::or_flat_against);
        placed += back && std::binary_search(points.begin(), points.end(), v);
        return back;
    };
    std::size_t lost = 0;
    if (!close_holes_around) {
        for (std::size_t i = 0; i < points.size() && absorbed; ++i) absorbed = place(points[i]);
    } else if (absorbed) {
        // Into a closed hole the points go in rounds (one that crossed a face may fit once its
        // neighbours split it), with the fans the closing took out; where the noise stacks
        // them 1–2 spacings deep, a few fit nowhere, and up to an eighth of the piece's
        // points may stay out.
        std::vector<std::uint32_t> out = taken_out();
        for (std::size_t before = out.size() + 1; !out.empty() && out.size() < before;) {
            before = out.size();
            out.erase(std::remove_if(out.begin(), out.end(), place), out.end());
        }
        // Only the piece's own points may stay out: a point of the surface that a closing's fan
        // took out goes back, or the closing is not worth it (D-38).
        lost = out.size();
        absorbed = std::all_of(out.begin(), out.end(),
                               [&](std::uint32_t v) {
                                   return std::binary_search(points.begin(), points.end(), v);
                               }) &&
                   lost <= points.size() / kMaxLostInHole;
    }
    if (absorbed) {
        ++stats.pieces_absorbed;
        stats.points_absorbed += placed;
        stats.vertices_removed += lost;
        stats.piece_holes_closed += close_holes_around;
    }
    end_undo(undo, absorbed);
    return absorbed;
}

bool Remover::close_holes_under(const std::vector<std::uint32_t>& piece,
                                const std::vector<std::uint32_t>& points) {
    const Box box = corners_box(points);
    Vec3 centre(0, 0, 0);
    for (std::uint32_t v : points) centre += positions_[v];
    centre /= double(points.size());
    double edge = 0;
    for (std::uint32_t f : piece)
        edge += (positions_[triangles_[f][0]] - positions_[triangles_[f][1]]).Norm();
    edge /= double(piece.size());
    gather_standing(Box{box.lo - Vec3(edge, edge, edge), box.hi + Vec3(edge, edge, edge)});
    std::vector<std::uint32_t> starts;
    for (const auto& [f, b] : near_.found())
        if (!of_a_small_piece(f))
            for (std::uint32_t v : triangles_[f]) starts.push_back(v);
    std::sort(starts.begin(), starts.end());
    starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
    // One walk per border loop (each walk gives its outcome to the vertices it passes).
    const std::vector<std::size_t> loop_edges = border_loops_at(starts, kMaxOptimisedHole);
    std::vector<Hole> holes;
    std::vector<std::uint32_t> tried;
    for (std::size_t i = 0; i < starts.size(); ++i) {
        const std::uint32_t v = starts[i];
        if (loop_edges[i] < 3 || loop_edges[i] > kMaxOptimisedHole ||
            std::find(tried.begin(), tried.end(), v) != tried.end())
            continue;
        const std::optional<Hole> hole = small_hole(v, false, kMaxOptimisedHole);
        if (!hole) continue;
        tried.insert(tried.end(), hole->corners.begin(), hole->corners.end());
        if (is_a_hole(hole->corners) && surrounds(hole->corners, centre)) holes.push_back(*hole);
    }
    if (holes.empty()) return false;
    for (const Hole& hole : holes) {
        const double spacing = spacing_around(hole.corners);
        const double points_over_it =
            area_vector(hole.corners).Norm() / (std::sqrt(3.0) / 2 * spacing * spacing);
        if (spacing == 0 || double(points.size()) < kMinHoleFill * points_over_it) return false;
    }
    // A closing may take out faces at another loop's corners (a fan filled with it): each loop
    // closes only while it is still the border loop it was.
    return std::all_of(holes.begin(), holes.end(), [&](const Hole& hole) {
        const std::optional<Hole> now = small_hole(hole.corners.back(), false, kMaxOptimisedHole);
        return now && now->corners == hole.corners && close_small_hole(hole, kMaxOptimisedHole);
    });
}

} // namespace hrsr::folds
