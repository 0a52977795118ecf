#include "io/mesh_writer.h"

#include "errors.h"
#include "io/atomic_file.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

namespace hrsr::io {
namespace {

/// Shortest text that reads back to the same value: 9 significant digits for a float, 17 for
/// a double.
std::string number(double v, bool as_float) {
    char text[32];
    if (as_float) {
        std::snprintf(text, sizeof text, "%.9g", double(float(v)));
    } else {
        std::snprintf(text, sizeof text, "%.17g", v);
    }
    return text;
}

std::string value_text(const PointAttribute& a, std::size_t i) {
    if (a.type == ScalarType::Float32) return number(a.value(i), true);
    if (a.type == ScalarType::Float64) return number(a.value(i), false);
    char text[24];
    std::snprintf(text, sizeof text, "%.0f", a.value(i));
    return text;
}

/// Colour channels found among the attributes (uchar or ushort), as fractions of full scale.
struct Colour {
    std::vector<const PointAttribute*> channels; // red, green, blue[, alpha]
    bool present() const { return channels.size() >= 3; }
    double fraction(std::size_t channel, std::size_t i) const {
        const PointAttribute& a = *channels[channel];
        return a.value(i) / (a.type == ScalarType::UInt8 ? 255.0 : 65535.0);
    }
};

Colour colour_of(const std::vector<PointAttribute>& attributes) {
    Colour c;
    for (const char* name : {"red", "green", "blue", "alpha"}) {
        const auto it = std::find_if(attributes.begin(), attributes.end(), [&](const auto& a) {
            return a.name == name && (a.type == ScalarType::UInt8 || a.type == ScalarType::UInt16);
        });
        if (it == attributes.end()) break;
        c.channels.push_back(&*it);
    }
    if (c.channels.size() < 3) c.channels.clear();
    return c;
}

/// The attributes a format without them leaves out, as a warning.
std::vector<std::string> left_out(const std::vector<PointAttribute>& attributes, const Colour& kept,
                                  std::size_t kept_channels, const std::string& format) {
    std::string names;
    for (const PointAttribute& a : attributes) {
        const auto end =
            kept.channels.begin() + long(std::min(kept_channels, kept.channels.size()));
        if (std::find(kept.channels.begin(), end, &a) != end) continue;
        names += (names.empty() ? "'" : ", '") + a.name + "'";
    }
    if (names.empty()) return {};
    return {format + " has no room for the per-vertex " + names +
            ": left out (write .ply to keep them)"};
}

void write_ascii_ply(AtomicFile& file, const std::vector<Vec3>& positions,
                     const std::vector<Vec3>& normals, const std::vector<Triangle>& triangles,
                     CoordinatePrecision precision, const std::vector<PointAttribute>& attributes) {
    std::ofstream& out = file.stream();
    const bool as_float = precision == CoordinatePrecision::Float;
    out << ply_header("ascii", positions.size(), !normals.empty(), triangles.size(), precision,
                      attributes);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        out << number(positions[i][0], as_float) << ' ' << number(positions[i][1], as_float) << ' '
            << number(positions[i][2], as_float);
        if (!normals.empty())
            for (int k = 0; k < 3; ++k) out << ' ' << number(normals[i][k], true);
        for (const PointAttribute& a : attributes) out << ' ' << value_text(a, i);
        out << '\n';
    }
    for (const Triangle& t : triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

void write_obj(AtomicFile& file, const std::vector<Vec3>& positions,
               const std::vector<Vec3>& normals, const std::vector<Triangle>& triangles,
               CoordinatePrecision precision, const Colour& colour) {
    std::ofstream& out = file.stream();
    const bool as_float = precision == CoordinatePrecision::Float;
    out << "# written by hrsr " << HRSR_VERSION << "\n";
    for (std::size_t i = 0; i < positions.size(); ++i) {
        out << "v " << number(positions[i][0], as_float) << ' ' << number(positions[i][1], as_float)
            << ' ' << number(positions[i][2], as_float);
        if (colour.present())
            for (std::size_t c = 0; c < 3; ++c) out << ' ' << number(colour.fraction(c, i), true);
        out << '\n';
    }
    for (const Vec3& n : normals)
        out << "vn " << number(n[0], true) << ' ' << number(n[1], true) << ' ' << number(n[2], true)
            << '\n';
    for (const Triangle& t : triangles) {
        out << 'f';
        for (const std::uint32_t v : t) {
            out << ' ' << v + 1;
            if (!normals.empty()) out << "//" << v + 1;
        }
        out << '\n';
    }
}

void write_off(AtomicFile& file, const std::vector<Vec3>& positions,
               const std::vector<Triangle>& triangles, CoordinatePrecision precision,
               const Colour& colour) {
    std::ofstream& out = file.stream();
    const bool as_float = precision == CoordinatePrecision::Float;
    out << (colour.present() ? "COFF\n" : "OFF\n") << positions.size() << ' ' << triangles.size()
        << " 0\n";
    for (std::size_t i = 0; i < positions.size(); ++i) {
        out << number(positions[i][0], as_float) << ' ' << number(positions[i][1], as_float) << ' '
            << number(positions[i][2], as_float);
        if (colour.present()) {
            for (std::size_t c = 0; c < 4; ++c) {
                const double f = c < colour.channels.size() ? colour.fraction(c, i) : 1.0;
                out << ' ' << long(f * 255.0 + 0.5);
            }
        }
        out << '\n';
    }
    for (const Triangle& t : triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

} // namespace

MeshFormat mesh_format_of(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".off") return MeshFormat::Off;
    throw InvalidOption(OptionId::Output, path + ": " +
                                              (ext.empty() ? std::string("no file extension")
                                                           : "unknown extension " + ext) +
                                              " (the format is chosen by it: .ply, .obj or .off)");
}

std::vector<std::string> write_mesh(const std::string& path, const std::vector<Vec3>& positions,
                                    const std::vector<Vec3>& normals,
                                    const std::vector<Triangle>& triangles,
                                    CoordinatePrecision precision,
                                    const std::vector<PointAttribute>& attributes,
                                    const MeshWriteOptions& options) {
    const MeshFormat format = mesh_format_of(path);
    if (format == MeshFormat::Ply && !options.ascii_ply) {
        write_ply(path, positions, normals, triangles, precision, attributes);
        return {};
    }
    validate_ply_data(positions, normals, triangles, attributes);
    AtomicFile file(path);
    std::vector<std::string> warnings;
    const Colour colour = colour_of(attributes);
    if (format == MeshFormat::Ply) {
        write_ascii_ply(file, positions, normals, triangles, precision, attributes);
    } else if (format == MeshFormat::Obj) {
        write_obj(file, positions, normals, triangles, precision, colour);
        warnings = left_out(attributes, colour, 3, "OBJ");
    } else {
        write_off(file, positions, triangles, precision, colour);
        warnings = left_out(attributes, colour, 4, "OFF");
    }
    file.commit();
    return warnings;
}

} // namespace hrsr::io
