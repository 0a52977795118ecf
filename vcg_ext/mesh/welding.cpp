#include "mesh/welding.h"

#include <algorithm>
#include <numeric>
#include <tuple>

namespace hrsr {

std::vector<std::uint32_t> same_position_representatives(const std::vector<Vec3>& p) {
    std::vector<std::uint32_t> order(p.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto key = [&](std::uint32_t i) { return std::make_tuple(p[i][0], p[i][1], p[i][2], i); };
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    std::vector<std::uint32_t> representative(p.size());
    for (std::size_t s = 0; s < order.size(); ++s) {
        const bool same = s > 0 && p[order[s]] == p[order[s - 1]];
        representative[order[s]] = same ? representative[order[s - 1]] : order[s];
    }
    return representative;
}

std::vector<Triangle> welded_triangles(const std::vector<Triangle>& triangles,
                                       const std::vector<std::uint32_t>& representative) {
    std::vector<Triangle> w(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) w[t][k] = representative[triangles[t][k]];
    return w;
}

} // namespace hrsr
