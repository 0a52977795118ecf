// Reading point clouds from files: PLY (ascii, binary little/big endian), XYZ text, OBJ v/vn.
// Our own small readers: precise error messages, no asserts, no aborts (the bundled vcglib OBJ
// importer aborts on common files; see ../shared/docs/VCGLIB.md §6).
#pragma once

#include "point_set.h"

#include <istream>
#include <string>

namespace hrsr::io {

/// Reads a point set, choosing the format by the file extension (case-insensitive):
/// .ply, .xyz / .txt (text "x y z [nx ny nz]"), .obj (v / vn lines).
/// Faces and other elements are ignored. Throws hrsr::IoError whose message starts with the
/// file name and says what is wrong (unreadable, empty, truncated, header that lies, missing
/// x/y/z, unknown extension, ...).
PointSet read_point_set(const std::string& path);

/// Format-specific readers on a stream; `name` is used in error messages only.
PointSet read_ply(std::istream& in, const std::string& name);
PointSet read_xyz(std::istream& in, const std::string& name);
PointSet read_obj(std::istream& in, const std::string& name);

} // namespace hrsr::io
