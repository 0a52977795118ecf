// Near-coincident points (D-25): points closer than a tolerance are merged like exact duplicates.
#pragma once

#include "parallel.h"
#include "point_set.h"

#include <cstdint>
#include <vector>

namespace hrsr {

/// For each point, the earliest point within `tolerance` of it that is itself not merged
/// (its representative), or the point itself. Points are visited in order, so a representative
/// always precedes the points merged into it. Expected O(N) through a hash grid of cells twice
/// `tolerance` wide, over the points a parallel screen (near_screen.h) keeps; the same result
/// for any thread count.
std::vector<std::uint32_t>
near_duplicate_representatives(const std::vector<Vec3>& positions, double tolerance,
                               const Execution& exec = Execution{1, nullptr});

} // namespace hrsr
