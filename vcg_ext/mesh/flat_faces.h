// Faces whose three corners lie exactly on one line in the written coordinates (deviation
// D-36): a line scanner's points of one row share two coordinates bit for bit, and a triangle
// over three of them has no area. They are taken out of the output without losing a point.
#pragma once

#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"
#include "reconstruction_stats.h"

#include <vector>

namespace hrsr {

/// D-36. Every face of `triangles` whose corners are collinear at `positions` (exactly) goes:
/// its longest edge (the one its middle corner m lies on) is flipped when a face stands across
/// it, which splits that face at m into two proper triangles covering the same ground (no pair
/// can intersect that did not before); on the border the flat face is removed (the border then
/// runs through m), if every corner keeps a face and m one fan. Faces for which neither holds
/// (a run of four points on one line) are counted as left. `triangles` must be a consistently
/// oriented manifold (if not, nothing changes and every flat face is counted as left). Its
/// vertices are kept; faces are kept in their order, those across a flipped edge rewritten.
/// The search by blocks of faces in parallel, the clearing sequential: the same result for any
/// thread count.
FlatFaceStats clear_flat_faces(const std::vector<Vec3>& positions, std::vector<Triangle>& triangles,
                               const Execution& exec = Execution{1, nullptr});

} // namespace hrsr
