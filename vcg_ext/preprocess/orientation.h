// Consistent orientation of unoriented normals by propagation over a minimum spanning tree
// (Hoppe et al. 1992; ALGORITHM.md §4.5).
#pragma once

#include "graph/neighbour_graph.h"

#include <vector>

namespace hrsr {

struct OrientationResult {
    std::size_t flips = 0;      ///< normals whose sign was changed
    std::size_t components = 0; ///< connected pieces of the graph, each with its own arbitrary sign
};

/// Per connected component of `graph` (root: its smallest index), grows the minimum spanning
/// tree under the cost 1 − |n_i · n_j| (ties broken by the smaller, then the larger endpoint,
/// D-10) and flips every vertex whose normal disagrees with its tree parent's final normal.
/// Deterministic; the global sign of each component is whatever its root had.
OrientationResult orient_normals(const CsrGraph& graph, std::vector<Vec3>& normals);

} // namespace hrsr
