// Pairs of triangles of a mesh that intersect each other (spatially accelerated).
#pragma once

#include "mesh/triangle_grid.h"
#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace hrsr {

/// The pairs (i, j), i < j, of triangles that intersect, sorted, on the coordinates as given
/// (exactly: triangle_intersection.h). The pair test is that of CGAL's
/// Polygon_mesh_processing::self_intersections: triangles sharing no vertex intersect if they
/// touch anywhere; sharing one vertex, if they meet anywhere else; sharing an edge, if they are
/// coplanar and overlap; sharing all three, always (two faces on one place; CGAL's Surface_mesh
/// holds such a pair only wound opposite ways). Vertices at the same position count as one vertex
/// here (CGAL goes by vertex, so two fans joined through copies of one point, as HRsR writes
/// non-manifold points, are a pair for CGAL and not here; intersecting_pairs_by_index() is CGAL's
/// view). Degenerate triangles (corners exactly on one line, a repeated vertex included; CGAL
/// reports them as a pair with themselves) are not tested: check_mesh() counts them, with a
/// tolerance, so its degenerate count includes every triangle left out here; it also counts
/// duplicate faces apart. Candidate pairs come from a uniform grid over the triangles' bounding
/// boxes (triangle_grid.h), each pair tested once, cells in parallel. `triangles` must index
/// `positions`, whose coordinates must be finite.
std::vector<TrianglePair> self_intersecting_pairs(const std::vector<Vec3>& positions,
                                                  const std::vector<Triangle>& triangles,
                                                  const Execution& exec);

/// The same with vertices shared by index only, as CGAL sees a mesh: two triangles touching at
/// distinct vertices that have the same position intersect.
std::vector<TrianglePair> intersecting_pairs_by_index(const std::vector<Vec3>& positions,
                                                      const std::vector<Triangle>& triangles,
                                                      const Execution& exec);

} // namespace hrsr
