// Small pieces that lie on another surface join it (D-55, fold_remover.h): RsR on a noisy cloud
// leaves bubbles of a few points and scraps beside the surface they belong to.
#include "mesh/fold_remover.h"

#include <algorithm>

namespace hrsr::folds {

namespace {

// A larger piece is a surface of its own, not a scrap: 200 faces are about 100 points, RsR's
// smallest component (`min_component_size`).
constexpr std::size_t kMaxAbsorbedPieceFaces = 200;

} // namespace

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
    for (const std::vector<std::uint32_t>& piece : small_pieces(kMaxAbsorbedPieceFaces)) {
        // A piece that took points of one before it is no longer the faces it was: it stays.
        if (!std::all_of(piece.begin(), piece.end(), [&](std::uint32_t f) { return alive_[f]; }))
            continue;
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
        // A point whose copy stands elsewhere (a bubble pinched off the surface at it) is in
        // the mesh still; every other goes back over a face near it, or the piece stays.
        std::size_t placed = 0;
        for (std::size_t i = 0; i < points.size() && absorbed; ++i) {
            const std::uint32_t v = points[i];
            if (point_has_standing_face(v)) continue;
            // The noise of the written coordinates may turn the faces there every way: a split
            // that faces away from the corners' normals but turns as the face it replaces does
            // and crosses nothing is kept too (the bubbles of the 1M graded triple torus).
            absorbed = put_back(v) || put_back(v, false);
            placed += absorbed;
        }
        if (absorbed) {
            ++stats.pieces_absorbed;
            stats.points_absorbed += placed;
        } else {
            rewind(undo);
            joined_border_ = undo.joined_border;
        }
        retired_log_.reset();
    }
}

} // namespace hrsr::folds
