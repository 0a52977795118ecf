// D-34: notches of the border that HRsR's border splits leave, closed by ears.
#pragma once

#include "index_types.h"
#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <array>
#include <cstddef>
#include <vector>

namespace hrsr {

/// A border edge a → b as the triangle holding it runs (no triangle has b → a).
using BorderEdge = std::array<std::uint32_t, 2>;

/// A border vertex whose faces leave less than `max_gap` radians of its surroundings open (its
/// two border neighbours close together, seen from it) lies in a notch of the border: the ear
/// over the gap (v, u, w) closes it, if {u, w} is no edge yet and the ear faces the way of the
/// two faces it joins. Smallest gaps first; an ear can make a new notch at u or w, which is
/// closed in turn; no ear takes a border loop below constants::kMinNotchedLoop vertices.
/// `border` lists every border edge of `triangles`. Vertex v lies at points[vertex_point[v]].
/// Returns the number of ears added (appended to `triangles`). Deterministic.
std::size_t close_border_notches(std::vector<Triangle>& triangles,
                                 const std::vector<BorderEdge>& border,
                                 const std::vector<Vec3>& points,
                                 const IndexVector<VertexIndex, PointIndex>& vertex_point,
                                 double max_gap);

} // namespace hrsr
