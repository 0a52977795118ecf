// Choosing a reader by file extension.
#include "io/point_set_reader.h"
#include "io/text_parsing.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace hrsr::io {
namespace {

using Reader = PointSet (*)(std::istream&, const std::string&, const ReadOptions&);

Reader reader_for(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".ply") return read_ply;
    if (ext == ".xyz" || ext == ".txt") return read_xyz;
    if (ext == ".obj") return read_obj;
    if (ext == ".pts") return read_pts;
    if (ext == ".pcd") return read_pcd;
    if (ext == ".las" || ext == ".laz") return read_las;
    detail::fail(path, (ext.empty() ? std::string("no file extension")
                                    : "unknown file extension " + detail::quote(ext)) +
                           " (supported: .ply, .xyz, .txt, .obj, .pts, .pcd, .las, .laz)");
}

} // namespace

PointSet read_point_set(const std::string& path, const ReadOptions& options) {
    return detail::guarded_read(path, [&] {
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec)) {
            detail::fail(path, "is a directory, not a point cloud file");
        }
        const Reader read = reader_for(path);
        errno = 0;
        std::ifstream in(path, std::ios::binary);
        if (!in) {
            detail::fail(path, std::string("cannot open: ") +
                                   (errno != 0 ? std::strerror(errno) : "unknown error"));
        }
        return read(in, path, options);
    });
}

} // namespace hrsr::io
