// What a mesh vertex carries over from the input point it was made from, besides the position:
// MeshLab's per-vertex colour, quality, radius and texture coordinate, and the layer's custom
// (named) per-vertex attributes. HRsR keeps the points as vertices, so these are exact copies.
#pragma once

#include "ml_compat.h"

#include <string>
#include <vector>

namespace hrsr::plugin {

/// Copies onto vertex k of `out` (already filled, one vertex per entry of `sources`) the
/// per-vertex data of `sources[k]`, a vertex of `in`: each of colour, quality, radius and texture
/// coordinate that `in` has (its data mask), enabled on `out` only then, with the texture
/// names that the coordinates refer to; and every named per-vertex attribute of a type in the
/// list of vertex_data.cpp, under the same name and type. Returns the names of the attributes
/// that were left out because their type is not in that list.
std::vector<std::string> copy_vertex_data(MeshModel& in, const std::vector<CVertexO*>& sources,
                                          MeshModel& out);

} // namespace hrsr::plugin
