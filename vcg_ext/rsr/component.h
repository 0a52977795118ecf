// One connected component as RsR sees it: local indices 0 … M−1 (ALGORITHM.md §5).
#pragma once

#include "point_set.h"

#include <array>
#include <cstdint>
#include <vector>

namespace hrsr::rsr {

struct ComponentCloud {
    std::vector<Vec3> positions; ///< normalised input positions (used for output only)
    std::vector<Vec3> smoothed;  ///< positions for neighbourhoods, angles and geometry tests
    std::vector<Vec3> normals;   ///< unit, oriented
    /// Input points the component stands for (= its point count unless HRsR collapsed it).
    std::size_t represented_points = 0;
    /// Longest handle edge at each point (D-31: HRsR's coarse cloud); empty = no such limit.
    std::vector<double> handle_reach;
};

using LocalTriangle = std::array<std::uint32_t, 3>;

} // namespace hrsr::rsr
