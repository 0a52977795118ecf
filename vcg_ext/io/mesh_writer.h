// Writing a reconstructed mesh in the format its file name asks for: PLY (binary, or ascii),
// OBJ, OFF; atomically (a complete file or none).
#pragma once

#include "io/ply_writer.h"

#include <string>
#include <vector>

namespace hrsr::io {

enum class MeshFormat { Ply, Obj, Off };

/// The format of `path` by its extension (case-insensitive): .ply, .obj or .off. Throws
/// hrsr::InvalidOption naming the supported ones otherwise (before any work is done).
MeshFormat mesh_format_of(const std::string& path);

struct MeshWriteOptions {
    bool ascii_ply = false; ///< PLY only: `format ascii 1.0` instead of binary little-endian
};

/// Writes the mesh as mesh_format_of(path) says. PLY holds everything (write_ply()); OBJ holds
/// positions, normals and colour (`v x y z r g b` in [0, 1]), OFF positions and colour (COFF,
/// 0-255) - colour from uchar or ushort red/green/blue[/alpha] attributes. Returns a warning
/// for the attributes the format cannot hold (empty if none). Throws hrsr::IoError.
std::vector<std::string> write_mesh(const std::string& path, const std::vector<Vec3>& positions,
                                    const std::vector<Vec3>& normals,
                                    const std::vector<Triangle>& triangles,
                                    CoordinatePrecision precision,
                                    const std::vector<PointAttribute>& attributes,
                                    const MeshWriteOptions& options = {});

} // namespace hrsr::io
