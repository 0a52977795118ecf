// Reading point clouds from files: PLY (ascii, binary little/big endian), XYZ text, OBJ v/vn,
// Leica PTS, PCL PCD, LAS/LAZ.
// Our own small readers: precise error messages, no asserts, no aborts (the bundled vcglib OBJ
// importer aborts on common files; see docs/VCGLIB.md §6).
#pragma once

#include "point_set.h"

#include <istream>
#include <string>
#include <vector>

namespace hrsr::io {

struct ReadOptions {
    /// Read per-point attributes (colour, intensity, ...) into PointSet::attributes; false
    /// skips them (less memory, and values that do not fit their declared type are ignored).
    bool attributes = true;
};

/// Reads a point set, choosing the format by the file extension (case-insensitive):
/// .ply, .xyz / .txt (text "x y z [nx ny nz]"), .obj (v / vn lines), .pts (Leica),
/// .pcd (PCL), .las / .laz.
/// Faces and other elements are ignored. Throws hrsr::IoError whose message starts with the
/// file name and says what is wrong (unreadable, empty, truncated, header that lies, missing
/// x/y/z, unknown extension, ...).
PointSet read_point_set(const std::string& path, const ReadOptions& options = {});

/// Reads several files as one cloud, in the order given (point indices run on from file to
/// file). Every file must have the same fields: normals in all or none, and the same attributes
/// (names and types, in the same order); otherwise IoError names the file that differs. Each
/// warning starts with the name of the file it is about.
PointSet read_point_sets(const std::vector<std::string>& paths, const ReadOptions& options = {});

/// Format-specific readers on a stream; `name` is used in error messages only.
PointSet read_ply(std::istream& in, const std::string& name, const ReadOptions& options = {});
PointSet read_xyz(std::istream& in, const std::string& name, const ReadOptions& options = {});
PointSet read_obj(std::istream& in, const std::string& name, const ReadOptions& options = {});
PointSet read_pts(std::istream& in, const std::string& name, const ReadOptions& options = {});
PointSet read_pcd(std::istream& in, const std::string& name, const ReadOptions& options = {});
/// LAS and LAZ (through LASzip; IoError if hrsr was built without it).
PointSet read_las(std::istream& in, const std::string& name, const ReadOptions& options = {});

} // namespace hrsr::io
