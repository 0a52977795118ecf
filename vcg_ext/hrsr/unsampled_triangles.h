// D-30: triangles of HRsR's output that span a hole in the data (laid by RsR's ears on the
// coarse cloud, whose edges are √(1/p) times longer than the input's spacing).
#pragma once

#include "index_types.h"
#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"

#include <cstddef>
#include <vector>

namespace hrsr {

/// Reopens the holes in the data that the mesh covers completely. A triangle is overlong when
/// one of its edges is more than twice as long as the distance from either end to its `rank`-th
/// nearest neighbour among `points` (§5.1 bounds RsR's candidate edges by that distance, so RsR
/// on the full cloud never makes such an edge). An edge-connected patch of overlong triangles
/// is removed when it is a disk whose every vertex lies on its outline (no point inside), none
/// on the mesh's boundary, with more than kMaxFilledLoop vertices (D-28 closes smaller loops):
/// one new boundary loop, every vertex kept and manifold. Vertex v
/// lies at points[vertex_point[v]]. Returns the number of triangles removed; the others keep
/// their order. Deterministic, the same for any thread count.
std::size_t remove_unsampled_triangles(std::vector<Triangle>& triangles,
                                       const std::vector<Vec3>& points,
                                       const IndexVector<VertexIndex, PointIndex>& vertex_point,
                                       int rank, const Execution& exec);

} // namespace hrsr
