// How far RsR on the full cloud could join a point to another: its candidate edges end at the
// ⌊2k/3⌋-th neighbour (§5.1). HRsR's coarse cloud asks this of the input points (D-31).
#pragma once

#include "index_types.h"
#include "knn.h"
#include "parallel.h"
#include "point_set.h"

#include <cstdint>
#include <vector>

namespace hrsr {

/// For each point i of `at`: the distance from that point of `points` (the pre-processed cloud)
/// to its `rank`-th nearest other point, or infinity when the cloud has fewer. Deterministic
/// whatever the thread count.
std::vector<double> input_reach(const std::vector<Vec3>& points, const std::vector<PointIndex>& at,
                                int rank, const Execution& exec);

/// The same at several ranks, from one kd-tree and one query per point: result[r][i] is the
/// reach of point at[i] at ranks[r].
std::vector<std::vector<double>> input_reach(const std::vector<Vec3>& points,
                                             const std::vector<PointIndex>& at,
                                             const std::vector<int>& ranks, const Execution& exec);

/// The same from an index built over `points` (KnnIndex(points)).
std::vector<std::vector<double>> input_reach(const KnnIndex& index,
                                             const std::vector<PointIndex>& at,
                                             const std::vector<int>& ranks, const Execution& exec);

} // namespace hrsr
