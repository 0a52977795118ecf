#include "mesh/self_intersections.h"

#include "mesh/welding.h"

namespace hrsr {

std::vector<TrianglePair> self_intersecting_pairs(const std::vector<Vec3>& positions,
                                                  const std::vector<Triangle>& triangles,
                                                  const Execution& exec) {
    return intersecting_pairs_by_index(
        positions, welded_triangles(triangles, same_position_representatives(positions)), exec);
}

std::vector<TrianglePair> intersecting_pairs_by_index(const std::vector<Vec3>& positions,
                                                      const std::vector<Triangle>& triangles,
                                                      const Execution& exec) {
    if (triangles.size() < 2) return {};
    const TriangleGeometry g(positions, triangles);
    return TriangleGrid(g, exec).all_pairs(g, exec);
}

} // namespace hrsr
