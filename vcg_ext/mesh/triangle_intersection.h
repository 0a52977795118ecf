// Whether two triangles of a mesh intersect, given their corners and vertex ids.
#pragma once

#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <array>

namespace hrsr {

using Corners = std::array<Vec3, 3>;

/// vcglib's Clean::TestFaceFaceIntersection on bare triangles (the rule self_intersections.h
/// describes), for code that changes a mesh and re-tests a few triangles at a time: triangles
/// sharing no vertex intersect if they touch anywhere; sharing one vertex, if either one's
/// opposite edge, pulled half-way towards the shared vertex, crosses the other; sharing two or
/// three, never (a fold along a shared edge, or a duplicate, is not an intersection here).
/// Which corners are shared is decided by the ids `ia`, `ib`.
bool mesh_triangles_intersect(const Corners& a, const Triangle& ia, const Corners& b,
                              const Triangle& ib);

} // namespace hrsr
