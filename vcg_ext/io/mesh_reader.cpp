// Opening a mesh file (the format readers live with the point readers: ply_reader.cpp).
#include "io/mesh_reader.h"
#include "io/text_parsing.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace hrsr::io {

MeshFile read_mesh(const std::string& path) {
    return detail::guarded_read(path, [&] {
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
            detail::fail(path, "is a directory, not a mesh file");
        std::string ext = std::filesystem::path(path).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (ext != ".ply")
            detail::fail(path, (ext.empty() ? std::string("no file extension")
                                            : "unknown mesh file extension " + detail::quote(ext)) +
                                   " (supported: .ply)");
        errno = 0;
        std::ifstream in(path, std::ios::binary);
        if (!in)
            detail::fail(path, std::string("cannot open: ") +
                                   (errno != 0 ? std::strerror(errno) : "unknown error"));
        return read_ply_mesh(in, path);
    });
}

} // namespace hrsr::io
