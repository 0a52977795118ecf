// Face-split phase of RsR (ALGORITHM.md §5.5): candidate edges in ascending length are inserted
// when they split a face, pass the geometry check, and close valid triangles.
#pragma once

#include "parallel.h"
#include "rsr/candidate_graph.h"
#include "rsr/embedding.h"

#include <vector>

namespace hrsr::rsr {

struct FaceSplitStats {
    std::size_t inserted = 0;
    std::size_t rejected_topology = 0;  ///< endpoints' wedges in different faces
    std::size_t rejected_geometry = 0;  ///< crossing a nearby edge
    std::size_t rejected_triangles = 0; ///< would close an invalid triangle
    std::size_t deferred = 0; ///< D-51: left by their tile's pass until after the step's tiles
};

/// Candidates whose fate threads work out ahead, in parallel, from the rotation before them.
inline constexpr std::size_t kFaceSplitLookAhead = 4096;

/// D-50: the face split takes its candidates in kFaceSplitSteps steps of equal count along the
/// length order; inside a step, tile by tile (2^kFaceSplitTileBits consecutive points of the
/// spatial order, D-40), then the candidates joining two tiles, each group in length order.
inline constexpr std::size_t kFaceSplitSteps = 8;
inline constexpr int kFaceSplitTileBits = 14;

/// `by_length` (face_split_candidates' order) in D-50's order; the same for any thread count.
/// A cloud of at most 2^kFaceSplitTileBits points keeps the length order.
std::vector<CandidateEdge> in_tile_order(std::vector<CandidateEdge> by_length,
                                         const Execution& exec);

/// Runs the phase on `candidates` (each pair once, as face_split_candidates gives them, in
/// in_tile_order()'s order; a component of one tile may take them in length order); records the
/// triangles it closes. One tile's candidates are taken as one by one, for any thread count and
/// look-ahead (1 = none): threads only work out answers that the edges inserted meanwhile cannot
/// change. With more tiles, each step's tiles run at once, each deferring what reaches outside
/// it, then the deferred and those across tiles in that order (D-51): the same for any thread
/// count.
FaceSplitStats split_faces(Embedding& embedding, const std::vector<CandidateEdge>& candidates,
                           const Execution& exec, std::size_t look_ahead = kFaceSplitLookAhead);

/// Adds one to the triangle counter of edge {u, w} (both darts).
void count_triangle_edge(RotationSystem& rotation, std::uint32_t u, std::uint32_t w);

/// Triangle count of edge {u, w} (which must exist).
std::uint8_t triangles_on_edge(const RotationSystem& rotation, std::uint32_t u, std::uint32_t w);

/// Every edge at v (at least three) holds two recorded triangles: during the face split, no
/// vertex not adjacent to v has a wedge in the face of any of v's wedges (the look-ahead rejects
/// its candidates without their angles).
bool surrounded_by_triangles(const RotationSystem& rotation, std::uint32_t v);

} // namespace hrsr::rsr
