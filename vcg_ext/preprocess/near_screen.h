// A screen for near-coincident points (D-25): the few points that may have another point within
// a tolerance, found in parallel, so that the exact search runs on those alone.
#pragma once

#include "parallel.h"
#include "point_set.h"

#include <cstdint>
#include <vector>

namespace hrsr {

/// The points (ascending indices) that may have another point within `tolerance` (> 0) of them:
/// every such pair is in, together with a few points that have none. The same list for any
/// thread count.
std::vector<std::uint32_t> near_point_candidates(const std::vector<Vec3>& positions,
                                                 double tolerance, const Execution& exec);

} // namespace hrsr
