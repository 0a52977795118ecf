// Consistent orientation of unoriented normals by propagation over a minimum spanning tree
// (Hoppe et al. 1992; ALGORITHM.md §4.5).
#pragma once

#include "graph/neighbour_graph.h"
#include "knn.h"

#include <vector>

namespace hrsr {

struct OrientationResult {
    std::size_t flips = 0;      ///< normals whose sign was changed
    std::size_t components = 0; ///< connected pieces of the graph, each with its own arbitrary sign
};

/// Per connected component of `graph` (root: its smallest index), grows the minimum spanning
/// tree under the cost below (ties broken by the smaller, then the larger endpoint, D-10) and
/// flips every vertex whose normal disagrees with its tree parent's final normal.
/// Deterministic; the global sign of each component is whatever its root had.
///
/// Cost of edge {i, j}, d = p_i − p_j:  1 − |n_i · n_j| + (|d · n_i| + |d · n_j|) / ρ,
/// ρ = (ρ_i + ρ_j) / 2 with ρ_i = `neighbourhood_radius[i]` (distance to the k-th neighbour).
/// The second term is GEL's legacy one (§4.5 item 2), kept here as deviation D-21: without it
/// an edge straight through a thin wall (antiparallel normals) costs nothing, so the tree
/// crosses walls instead of going around sharp edges and flips whole regions.
OrientationResult orient_normals(const CsrGraph& graph, const std::vector<Vec3>& positions,
                                 const std::vector<double>& neighbourhood_radius,
                                 std::vector<Vec3>& normals);

/// Input normals are trusted to be oriented (§4.1). Counts the points whose nearest neighbour's
/// normal points the other way (n_i · n_j < 0): the mark of unoriented or partly flipped input
/// normals, or of two sheets closer than the sampling spacing. `index` is built on the points.
std::size_t opposed_nearest_normals(const KnnIndex& index, const std::vector<Vec3>& normals,
                                    const Execution& exec);

} // namespace hrsr
