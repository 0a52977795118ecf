// Binary little-endian PLY writer (point clouds and triangle meshes).
#include "io/ply_writer.h"

#include "errors.h"
#include "io/atomic_file.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <utility>

#ifndef HRSR_VERSION
#define HRSR_VERSION "unknown"
#endif

namespace hrsr::io {
namespace {

bool host_is_big_endian() {
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 0;
}

/// Buffers little-endian values and writes them in large blocks.
class LittleEndianWriter {
public:
    LittleEndianWriter(std::ostream& out, const std::string& path) : out_(out), path_(path) {}

    template <class T>
    void put(T value) {
        static_assert(std::is_arithmetic_v<T>);
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        put_host_order(bytes, sizeof(T));
    }

    /// One value of `size` bytes (at most 8) in host byte order.
    void put_host_order(const unsigned char* value, std::size_t size) {
        if (used_ + size > sizeof buffer_) flush();
        std::memcpy(buffer_ + used_, value, size);
        if (big_endian_host_) std::reverse(buffer_ + used_, buffer_ + used_ + size);
        used_ += size;
    }

    void flush() {
        out_.write(reinterpret_cast<const char*>(buffer_), static_cast<std::streamsize>(used_));
        used_ = 0;
        if (!out_) throw IoError(path_ + ": write error (disk full?)");
    }

private:
    std::ostream& out_;
    const std::string& path_;
    const bool big_endian_host_ = host_is_big_endian();
    unsigned char buffer_[1 << 16];
    std::size_t used_ = 0;
};

void validate_attributes(const std::vector<Vec3>& positions,
                         const std::vector<PointAttribute>& attributes) {
    std::vector<std::string> names = {"x", "y", "z", "nx", "ny", "nz"};
    for (const PointAttribute& a : attributes) {
        if (a.size() != positions.size() || a.bytes.size() != a.size() * size_of(a.type))
            throw std::invalid_argument("write_ply: attribute '" + a.name + "' has " +
                                        std::to_string(a.size()) + " values for " +
                                        std::to_string(positions.size()) + " positions");
        const bool bad_name =
            a.name.empty() ||
            std::any_of(a.name.begin(), a.name.end(), [](char c) { return c <= ' ' || c == 0x7f; });
        if (bad_name || std::find(names.begin(), names.end(), a.name) != names.end())
            throw std::invalid_argument("write_ply: attribute name '" + a.name +
                                        "' is empty, has spaces or is used twice");
        names.push_back(a.name);
    }
}

} // namespace

void validate_ply_data(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                       const std::vector<Triangle>& triangles,
                       const std::vector<PointAttribute>& attributes) {
    validate_attributes(positions, attributes);
    if (!normals.empty() && normals.size() != positions.size()) {
        throw std::invalid_argument("write_ply: " + std::to_string(normals.size()) +
                                    " normals for " + std::to_string(positions.size()) +
                                    " positions (give one per position, or none)");
    }
    // Indices are written as PLY 'int' (signed 32-bit).
    const std::uint64_t limit = std::min<std::uint64_t>(
        positions.size(), std::uint64_t(std::numeric_limits<std::int32_t>::max()) + 1);
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        for (const std::uint32_t index : triangles[t]) {
            if (index >= limit) {
                throw std::invalid_argument(
                    "write_ply: triangle " + std::to_string(t) + " has vertex index " +
                    std::to_string(index) + ", but there are " + std::to_string(positions.size()) +
                    " positions" + (index < positions.size() ? " (beyond the PLY int range)" : ""));
            }
        }
    }
}

std::string ply_header(const std::string& format, std::size_t vertices, bool normals,
                       std::size_t triangles, CoordinatePrecision precision,
                       const std::vector<PointAttribute>& attributes) {
    const char* const type = precision == CoordinatePrecision::Float ? "float" : "double";
    std::ostringstream h;
    h << "ply\nformat " << format << " 1.0\ncomment written by hrsr " << HRSR_VERSION << "\n"
      << "element vertex " << vertices << "\n";
    for (const char* axis : {"x", "y", "z"}) h << "property " << type << " " << axis << "\n";
    if (normals) h << "property float nx\nproperty float ny\nproperty float nz\n";
    for (const PointAttribute& a : attributes)
        h << "property " << ply_type_name(a.type) << " " << a.name << "\n";
    if (triangles > 0) {
        h << "element face " << triangles << "\nproperty list uchar int vertex_indices\n";
    }
    h << "end_header\n";
    return h.str();
}

void write_ply(const std::string& path, const std::vector<Vec3>& positions,
               const std::vector<Vec3>& normals, const std::vector<Triangle>& triangles,
               CoordinatePrecision precision, const std::vector<PointAttribute>& attributes) {
    validate_ply_data(positions, normals, triangles, attributes);
    AtomicFile file(path);
    file.stream() << ply_header("binary_little_endian", positions.size(), !normals.empty(),
                                triangles.size(), precision, attributes);
    LittleEndianWriter out(file.stream(), path);
    const bool as_float = precision == CoordinatePrecision::Float;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            if (as_float) {
                out.put(static_cast<float>(positions[i][k]));
            } else {
                out.put(positions[i][k]);
            }
        }
        if (!normals.empty()) {
            for (int k = 0; k < 3; ++k) out.put(static_cast<float>(normals[i][k]));
        }
        for (const PointAttribute& a : attributes) out.put_host_order(a.data(i), size_of(a.type));
    }
    for (const Triangle& t : triangles) {
        out.put(std::uint8_t{3});
        for (const std::uint32_t index : t) out.put(static_cast<std::int32_t>(index));
    }
    out.flush();
    file.commit();
}

} // namespace hrsr::io
