// Vertices at exactly the same position: meshes often store one point several times (vertex
// copies at non-manifold points, seams, duplicated scan points). Geometric checks treat such
// copies as one vertex.
#pragma once

#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"

#include <vector>

namespace hrsr {

/// For every vertex, the smallest index of a vertex at exactly the same position.
std::vector<std::uint32_t> same_position_representatives(const std::vector<Vec3>& positions);
/// The same, sorted in parallel (the same result for any thread count).
std::vector<std::uint32_t> same_position_representatives(const std::vector<Vec3>& positions,
                                                         const Execution& exec);

/// `triangles` with every corner replaced by its representative.
std::vector<Triangle> welded_triangles(const std::vector<Triangle>& triangles,
                                       const std::vector<std::uint32_t>& representative);
/// The same, by blocks in parallel.
std::vector<Triangle> welded_triangles(const std::vector<Triangle>& triangles,
                                       const std::vector<std::uint32_t>& representative,
                                       const Execution& exec);

} // namespace hrsr
