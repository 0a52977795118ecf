#include "mesh/welding.h"

#include <algorithm>
#include <tuple>

namespace hrsr {

std::vector<std::uint32_t> same_position_representatives(const std::vector<Vec3>& p) {
    // Sorted as values next to their index: the comparisons then read memory in order (sorting
    // indices that look their positions up was a tenth of the fold search on the lion).
    struct Keyed {
        double x, y, z;
        std::uint32_t i;
        bool operator<(const Keyed& o) const {
            return std::tie(x, y, z, i) < std::tie(o.x, o.y, o.z, o.i);
        }
    };
    std::vector<Keyed> order(p.size());
    for (std::uint32_t i = 0; i < p.size(); ++i) order[i] = {p[i][0], p[i][1], p[i][2], i};
    std::sort(order.begin(), order.end());
    std::vector<std::uint32_t> representative(p.size());
    for (std::size_t s = 0; s < order.size(); ++s) {
        const Keyed& k = order[s];
        const bool same =
            s > 0 && k.x == order[s - 1].x && k.y == order[s - 1].y && k.z == order[s - 1].z;
        representative[k.i] = same ? representative[order[s - 1].i] : k.i;
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
