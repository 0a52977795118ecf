// One connected component as RsR sees it: local indices 0 … M−1 (ALGORITHM.md §5).
#pragma once

#include "knn.h"
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
    /// The kNN rows of the whole cloud, when its maker has them (HRsR's coarse cloud, whose
    /// hand-off queried them): local point i's row is table->row(cloud_index[i]); a row whose
    /// entries all lie in this component (component_of[e] == component) is local point i's
    /// neighbours in the component, at local indices local_index[e]. Null table = none known.
    struct KnownNeighbours {
        const KnnTable* table = nullptr;
        const std::uint32_t* cloud_index = nullptr;
        const std::uint32_t* component_of = nullptr;
        const std::uint32_t* local_index = nullptr;
        std::uint32_t component = 0;
    } known_neighbours;
};

using LocalTriangle = std::array<std::uint32_t, 3>;

} // namespace hrsr::rsr
