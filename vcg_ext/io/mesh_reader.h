// Reading triangle meshes (PLY) for checking and comparing them: vertices and faces.
#pragma once

#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace hrsr::io {

struct MeshFile {
    PointSet points; ///< the vertices (and their normals, if the file has them)
    std::vector<Triangle> triangles;
    std::size_t polygons_triangulated = 0; ///< faces with more than 3 corners, split as fans
};

/// Reads a PLY mesh (ascii or binary): the vertex element as read_ply() does, and the face
/// element's `vertex_indices` (or `vertex_index`) list; polygons are split into triangle fans. A
/// file without a face element is a mesh without triangles. Throws hrsr::IoError naming the file
/// and the problem (truncated data, a face with fewer than 3 corners, an index that is negative
/// or not below the vertex count, ...).
MeshFile read_ply_mesh(std::istream& in, const std::string& name);

/// Opens `path` (which must end in .ply, any case) and reads it with read_ply_mesh().
MeshFile read_mesh(const std::string& path);

} // namespace hrsr::io
