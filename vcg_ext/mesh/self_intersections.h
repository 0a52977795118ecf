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

/// The pairs (i, j), i < j, of triangles that intersect, sorted. Vertices at the same position
/// count as one vertex. The pair test is vcglib's Clean::TestFaceFaceIntersection (on bare
/// triangles: triangle_intersection.h): triangles
/// sharing no vertex intersect if they touch anywhere; triangles sharing one vertex if either
/// one's opposite edge, pulled half-way towards the shared vertex, crosses the other one;
/// triangles sharing an edge never count (a fold along a shared edge is not found). Degenerate
/// triangles (a repeated vertex, or zero area) and pairs on the same three vertices (duplicate
/// faces) are not tested: they are reported as such by check_mesh(). Candidate pairs come from
/// a uniform grid over the triangles' bounding boxes (triangle_grid.h), each pair tested once,
/// cells in parallel. `triangles` must index `positions`.
std::vector<TrianglePair> self_intersecting_pairs(const std::vector<Vec3>& positions,
                                                  const std::vector<Triangle>& triangles,
                                                  const Execution& exec);

} // namespace hrsr
