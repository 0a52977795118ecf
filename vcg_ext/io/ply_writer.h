// Writing clouds and meshes as binary little-endian PLY, atomically.
#pragma once

#include "point_set.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace hrsr::io {

using Triangle = std::array<std::uint32_t, 3>;

/// Writes positions (float or double x/y/z as `precision` says, so inputs round-trip
/// bit-exactly), optional normals (float nx/ny/nz; empty = none) and optional triangles
/// (list uchar int vertex_indices; empty = point cloud), and after the normals one vertex
/// property per attribute, with its name and type. `normals` and every attribute, when given,
/// must have the size of `positions`, attribute names must be unique, without spaces and not
/// x..nz; triangle indices must be < positions.size() (std::invalid_argument
/// otherwise). Written through a temporary file in the destination folder and renamed, so the
/// destination is either complete or untouched. Throws hrsr::IoError on failure.
void write_ply(const std::string& path, const std::vector<Vec3>& positions,
               const std::vector<Vec3>& normals, const std::vector<Triangle>& triangles,
               CoordinatePrecision precision, const std::vector<PointAttribute>& attributes = {});

/// The checks of write_ply() (std::invalid_argument), for writers of other layouts.
void validate_ply_data(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                       const std::vector<Triangle>& triangles,
                       const std::vector<PointAttribute>& attributes);

/// The PLY header write_ply() writes, with `format` "binary_little_endian" or "ascii".
std::string ply_header(const std::string& format, std::size_t vertices, bool normals,
                       std::size_t triangles, CoordinatePrecision precision,
                       const std::vector<PointAttribute>& attributes);

} // namespace hrsr::io
