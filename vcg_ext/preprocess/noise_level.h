// How noisy a cloud is, in units of its point spacing (D-33): HRsR decides on it whether its
// collapse and re-expansion see smoothed positions.
#pragma once

#include "knn.h"
#include "parallel.h"

#include <vector>

namespace hrsr {

/// The median distance of the points from a quadric fitted to their nearest neighbours (within
/// 30° of their normal, weights falling linearly with the tangential distance, as in §4.4),
/// divided by the median distance to the sixth nearest neighbour, on an evenly spaced sample of
/// at most kNoiseSample points. A quadric, unlike §4.4's plane, follows the curvature of a clean
/// surface, so what is left is noise: measured 0–0.07 on clean samples and on the owl and lion,
/// 0.1 on the merged bunny range scans, 0.17 on the LMS400 table scan, 0.13 / 0.33 / 0.46 on
/// spheres with Gaussian noise of 0.1 / 0.3 / 0.5 % of the diagonal (100k points). Signs of the
/// normals do not matter. `index` is built on `positions`. Deterministic; 0 for fewer than 1,000
/// points, where 48 neighbours are too much of the surface for one quadric.
double relative_noise(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                      const KnnIndex& index, const Execution& exec);

} // namespace hrsr
