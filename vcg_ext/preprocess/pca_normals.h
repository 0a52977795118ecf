// Unoriented normals by principal component analysis (Hoppe et al. 1992; ALGORITHM.md §4.3, D-5).
#pragma once

#include "knn.h"

#include <vector>

namespace hrsr {

struct PcaNormals {
    std::vector<Vec3> normals; ///< unit, unoriented; empty when no point had a defined normal
    std::size_t degenerate =
        0; ///< points whose neighbourhood is (nearly) collinear or a single point
};

/// Neighbourhood size for a cloud of n points: `requested` if > 0, else clamp(n / 2000, 16, 192)
/// (D-5 for PCA, D-20 for smoothing); never more than n − 1.
int neighbour_count(std::size_t n, int requested);

/// The smoothing neighbourhood of HRsR's coarse cloud of `coarse_points` that stands for
/// `input_points`: `requested` if > 0, else the count whose neighbourhood spans the share of the
/// surface the input's automatic neighbourhood would (D-44): neighbour_count(coarse_points, 0)
/// below 384,000 input points, 192 · coarse_points / input_points above; same clamps.
int coarse_neighbour_count(std::size_t input_points, std::size_t coarse_points, int requested);

/// For each point: the smallest-eigenvalue eigenvector of the covariance of the point and its
/// `neighbours` nearest neighbours. A point whose covariance is degenerate takes the normal of
/// the nearest point that has a defined one (D-5). When no point has one, `normals` is empty.
/// `reach`, if given, carries the neighbourhoods' radii between rounds (knn.h).
PcaNormals estimate_normals(const std::vector<Vec3>& positions, const KnnIndex& index,
                            int neighbours, const Execution& exec, NeighbourReach* reach = nullptr);

} // namespace hrsr
