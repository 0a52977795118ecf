#include "mesh/welding.h"

#include <algorithm>
#include <functional>
#include <parallel/algorithm>
#include <tuple>

namespace hrsr {

std::vector<std::uint32_t> same_position_representatives(const std::vector<Vec3>& p) {
    return same_position_representatives(p, Execution{1, nullptr});
}

std::vector<std::uint32_t> same_position_representatives(const std::vector<Vec3>& p,
                                                         const Execution& exec) {
    // Sorted as values next to their index: the comparisons then read memory in order (sorting
    // indices that look their positions up was a tenth of the fold search on the lion).
    struct Keyed {
        double x, y, z;
        std::uint32_t i;
        bool operator<(const Keyed& o) const {
            return std::tie(x, y, z, i) < std::tie(o.x, o.y, o.z, o.i);
        }
    };
    // (position, index) orders every vertex, so any sort gives this one order.
    std::vector<Keyed> order(p.size());
    parallel_for_blocks(without_progress(exec), p.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t i = first; i < end; ++i)
                                order[i] = {p[i][0], p[i][1], p[i][2], std::uint32_t(i)};
                        });
    __gnu_parallel::sort(order.begin(), order.end(), std::less<Keyed>(),
                         __gnu_parallel::balanced_quicksort_tag(thread_count(exec)));
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
    return welded_triangles(triangles, representative, Execution{1, nullptr});
}

std::vector<Triangle> welded_triangles(const std::vector<Triangle>& triangles,
                                       const std::vector<std::uint32_t>& representative,
                                       const Execution& exec) {
    std::vector<Triangle> w(triangles.size());
    parallel_for_blocks(without_progress(exec), triangles.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t t = first; t < end; ++t)
                                for (int k = 0; k < 3; ++k)
                                    w[t][k] = representative[triangles[t][k]];
                        });
    return w;
}

} // namespace hrsr
