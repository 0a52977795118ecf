// The triangles of a PLY mesh file, for tests (positions and normals: io::read_point_set).
#pragma once

#include "mesh/triangle_mesh.h"

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace hrsr::testing {

/// The triangles of a binary little-endian PLY whose vertex properties are all float or double
/// and whose faces are `list uchar int` (what hrsr and MeshLab write). False on any other layout.
inline bool read_ply_faces(const std::string& bytes, std::size_t& vertices,
                           std::vector<Triangle>& triangles) {
    const std::size_t end = bytes.find("end_header\n");
    if (end == std::string::npos) return false;
    std::istringstream header(bytes.substr(0, end));
    std::string line, element;
    std::size_t stride = 0, faces = 0;
    bool face_list = false;
    while (std::getline(header, line)) {
        std::istringstream words(line);
        std::string word, type;
        words >> word;
        if (word == "format" && line != "format binary_little_endian 1.0") return false;
        if (word == "element") {
            std::size_t count = 0;
            words >> element >> count;
            if (element == "vertex")
                vertices = count;
            else if (element == "face")
                faces = count;
            else
                return false;
        } else if (word == "property" && element == "vertex") {
            words >> type;
            if (type == "float")
                stride += 4;
            else if (type == "double")
                stride += 8;
            else
                return false;
        } else if (word == "property" && element == "face") {
            face_list = line == "property list uchar int vertex_indices";
        }
    }
    if (!face_list) return false;
    std::size_t at = end + std::strlen("end_header\n") + vertices * stride;
    if (bytes.size() != at + faces * 13) return false;
    triangles.resize(faces);
    for (Triangle& t : triangles) {
        if (bytes[at] != 3) return false;
        for (int k = 0; k < 3; ++k) {
            std::int32_t index;
            std::memcpy(&index, bytes.data() + at + 1 + 4 * k, 4);
            t[k] = std::uint32_t(index);
        }
        at += 13;
    }
    return true;
}

} // namespace hrsr::testing
