// What the face split's two ways of taking candidates share (rsr/face_split.cpp: the length
// order with a parallel look-ahead; rsr/face_split_tiles.cpp: the tiles of a step in parallel,
// D-51): the triangles a new edge closes, which vertices a pass may touch, and the per-vertex
// summary that answers most candidates without their rotations. Internal to the face split.
#pragma once

#include "rsr/candidate_graph.h"
#include "rsr/embedding.h"
#include "rsr/face_split.h"

#include <limits>
#include <vector>

namespace hrsr::rsr {

inline std::uint32_t split_tile(std::uint32_t v) {
    return v >> kFaceSplitTileBits;
}

/// The vertices whose rotations a pass may read and change: all of them, or one tile's (D-51).
struct Region {
    static constexpr std::uint32_t kEverywhere = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t tile = kEverywhere;
    bool holds(std::uint32_t v) const { return tile == kEverywhere || split_tile(v) == tile; }
};

/// The tile of both ends, or Region::kEverywhere for a candidate across tiles.
inline std::uint32_t candidate_tile(const CandidateEdge& c) {
    const std::uint32_t t = split_tile(c.i);
    return t == split_tile(c.j) ? t : Region::kEverywhere;
}

enum class Closing : std::uint8_t { Valid, Invalid, Outside };

/// §5.5.2 step 4, with the rotation as it is *before* inserting {v1, v2}: the triangles the new
/// edge closes go to `found`. Invalid rejects the candidate; Outside: the test would read the
/// rotation of a vertex outside `region` (v1 and v2 must be inside).
Closing register_triangles(const RotationSystem& rotation, std::uint32_t v1, std::uint32_t v2,
                           std::vector<LocalTriangle>& found, Region region = {});

/// What the face split reads of a vertex before its rotation, in arrays small enough to stay in
/// the cache: the candidates come from all over the cloud, and from about 400k points (the 3.2M
/// sample's coarse cloud) a rotation read is a miss to memory. Most candidates end at a vertex
/// surrounded by triangles (1.8M of 2.1M at 800k points); their answer needs only whether the
/// pair was an edge before the phase, since no candidate pair comes twice (the candidates are
/// the pairs i < j of a graph's rows). Threads of D-51 update their own tiles' vertices.
class VertexSummary {
public:
    VertexSummary(const RotationSystem& rotation, const Execution& exec);

    bool surrounded(std::uint32_t v) const { return surrounded_[v] != 0; }
    /// Kept as the rotation changes. A vertex once surrounded gains no edge (no face at it
    /// splits); the update on insertion says so.
    void triangle_recorded(const RotationSystem& rotation, const LocalTriangle& t) {
        for (std::uint32_t v : t) surrounded_[v] = surrounded_by_triangles(rotation, v);
    }
    void edge_inserted(std::uint32_t v, std::uint32_t w) { surrounded_[v] = surrounded_[w] = 0; }
    bool adjacent_before_the_phase(std::uint32_t v, std::uint32_t w) const;

private:
    std::vector<std::uint8_t> surrounded_;
    std::vector<std::uint32_t> first_;   ///< offsets into initial_
    std::vector<std::uint32_t> initial_; ///< each vertex's neighbours before the phase
};

/// One tile's share of a step (D-51): its candidates, the labels it may give new faces, and what
/// it did.
struct TileSplit {
    std::uint32_t tile = 0;
    std::size_t first = 0, last = 0; ///< its candidates' positions in the list
    std::uint32_t next_label = 0;    ///< the next of the labels reserved for it
    std::size_t labels = 0;          ///< how many of them are left
    FaceSplitStats stats;
    std::vector<LocalTriangle> triangles; ///< in the order recorded
    std::vector<CandidateEdge> deferred;  ///< reading or changing outside the tile, in order
};

/// Takes the tile's candidates one by one, changing only the rotations, face labels and summary
/// entries of the tile's vertices: tiles of one step can run at once. A candidate whose geometry
/// ball, closed triangles or face walks reach outside the tile is deferred instead. Edges and
/// faces are left uncounted (RotationSystem::count_edges, Faces::count_splits). With `observe`
/// (one tile at a time) the counts and the embedding's triangle list are kept current and the
/// observer hears of each insertion, as in the length order.
void split_in_tile(Embedding& embedding, VertexSummary& summary,
                   const std::vector<CandidateEdge>& candidates, TileSplit& work, bool observe);

} // namespace hrsr::rsr
