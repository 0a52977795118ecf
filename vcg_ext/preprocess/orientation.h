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

/// Points whose normal opposes a near neighbour's (n_i · n_j < 0).
struct OpposedNormals {
    /// Opposed to the nearest neighbour's: the mark of unoriented or partly flipped input
    /// normals, or of two sheets closer than the sampling spacing (§4.1 trusts input normals).
    std::size_t to_nearest = 0;
    /// Opposed to one of the kOpposedScreen nearest (a flipped pair's points are each other's
    /// nearest), in increasing order: D-54's candidates.
    std::vector<std::uint32_t> to_a_near_one;
};
inline constexpr int kOpposedScreen = 3;

/// The points whose normal opposes a near neighbour's. `index` is built on the points.
OpposedNormals opposed_normals(const KnnIndex& index, const std::vector<Vec3>& normals,
                               const Execution& exec);

/// D-54: neighbours asked, and how many of them must face the other way, for a lone flip.
inline constexpr int kLoneFlipNeighbours = 16;
inline constexpr int kLoneFlipOpposed = 12;

/// D-54: turns the input normals that face against their neighbourhood: of `candidates` (points
/// opposed to a near neighbour), those with at least kLoneFlipOpposed of their
/// kLoneFlipNeighbours nearest neighbours' normals opposed. Decided on the normals as given, then
/// turned; returns the points turned, in increasing order. The same for any thread count.
std::vector<std::uint32_t> turn_lone_flipped_normals(const KnnIndex& index,
                                                     std::vector<Vec3>& normals,
                                                     const std::vector<std::uint32_t>& candidates,
                                                     const Execution& exec);

} // namespace hrsr
