// Whether two triangles of a mesh intersect, given their corners and vertex ids.
#pragma once

#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <array>

namespace hrsr {

using Corners = std::array<Vec3, 3>;

/// Whether two non-degenerate triangles of a mesh meet other than where the mesh joins them,
/// as CGAL's Polygon_mesh_processing::self_intersections decides (the rule self_intersections.h
/// describes): sharing no vertex, if they touch at all; sharing one vertex, if they meet
/// anywhere else; sharing an edge, if they are coplanar and overlap (their opposite corners on
/// the same side of the edge); sharing all three vertices (a duplicate), always: two faces
/// on one place cover each other (CGAL's Surface_mesh holds such a pair only wound opposite ways,
/// and reports it). Which corners are shared is decided by the ids `ia`, `ib`. Exact on the
/// coordinates as given (finite doubles): every decision is the sign of an orientation determinant
/// (exact_predicates.h).
bool mesh_triangles_intersect(const Corners& a, const Triangle& ia, const Corners& b,
                              const Triangle& ib);

/// Whether triangle abc is degenerate for the intersection test: its corners are exactly on one
/// line (a repeated or coinciding corner included). Such triangles are not tested.
bool collinear_corners(const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace hrsr
