#include "mesh/triangle_mesh.h"

#include <numeric>

namespace hrsr {

VertexCorners corners_by_vertex(std::size_t n, const std::vector<Triangle>& triangles) {
    VertexCorners c;
    c.start.assign(n + 1, 0);
    for (const Triangle& t : triangles)
        for (std::uint32_t v : t) ++c.start[v + 1];
    std::partial_sum(c.start.begin(), c.start.end(), c.start.begin());
    c.corner.resize(c.start[n]);
    std::vector<std::uint32_t> cursor(c.start.begin(), c.start.end() - 1);
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (std::uint32_t k = 0; k < 3; ++k) c.corner[cursor[triangles[t][k]]++] = 3 * t + k;
    return c;
}

} // namespace hrsr
