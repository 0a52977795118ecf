// D-28: closing the tiniest holes of an output mesh, whatever phase left them.
#pragma once

#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <cstddef>
#include <vector>

namespace hrsr {

/// Boundary loops of at most this many edges are closed (D-28): a loop through five input
/// points is a gap of about one point spacing, not a hole in the data.
inline constexpr std::size_t kMaxFilledLoop = 5;

/// Closes every boundary loop of 3 … `max_edges` distinct vertices, each of which has no other
/// boundary edge, by the fan (one of the loop's triangulations) with the largest smallest angle
/// whose diagonals are not edges yet; loops whose best fan has an angle below 1° are left open.
/// New triangles follow the loop's winding, so the mesh stays edge- and vertex-manifold and
/// coherently oriented. `positions` are per vertex. Returns the number of loops closed.
/// Deterministic: loops are visited in order of their smallest vertex.
std::size_t fill_small_holes(std::vector<Triangle>& triangles, const std::vector<Vec3>& positions,
                             std::size_t max_edges = kMaxFilledLoop);

} // namespace hrsr
