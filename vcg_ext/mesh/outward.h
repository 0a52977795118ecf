// D-6: closed pieces of the output turned outwards (docs/ALGORITHM.md §14).
#pragma once

#include "mesh/mesh_stats.h"
#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <cstdint>
#include <vector>

namespace hrsr {

/// Turns inside out every closed component of `stats` (`component`: each triangle's, from
/// measure_mesh) whose triangles enclose a negative volume over `positions`: its triangles' winding
/// and its vertices' `normals`. A vertex's normal turns once per turned component it is a corner
/// of. One pass over the triangles for all components. Returns how many components turned.
std::size_t turn_closed_components_outwards(const std::vector<Vec3>& positions,
                                            const MeshStats& stats,
                                            const std::vector<std::uint32_t>& component,
                                            std::vector<Triangle>& triangles,
                                            std::vector<Vec3>& normals);

} // namespace hrsr
