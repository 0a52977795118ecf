// Checks shared by the plugin tests of every MeshLab version: the mesh bit for bit, its
// manifoldness, the filter's log against the CLI's JSON report, and the test clouds.
#pragma once

#include "cli_runner.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"
#include "mesh/mesh_stats.h"
#include "ply_faces.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hrsr::testing {

/// A default as the filter shows it (QString::number's shortest form, as iostream writes it).
inline std::string default_text(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

/// Writes the sample with `outliers` points in a far cluster (smaller than a component may be,
/// so they are dropped) to `file`, and returns that cloud.
inline PointSet write_sample_with_far_outliers(const std::string& file, std::size_t outliers) {
    PointSet cloud = io::read_point_set(HRSR_SAMPLE);
    for (std::size_t i = 0; i < outliers; ++i)
        cloud.positions.emplace_back(1e4 + double(i % 5), 1e4 + double(i / 5), 1e4);
    io::write_ply(file, cloud.positions, {}, {}, cloud.precision);
    return cloud;
}

/// The per-vertex data a MeshLab layer can carry, as the PLY properties MeshLab reads and writes.
inline const std::vector<std::string> kLayerProperties{
    "red", "green", "blue", "alpha", "quality", "radius", "texture_u", "texture_v"};

/// Writes the sample to `file` with the kLayerProperties, every one varying from point to point
/// (none constant, so that a value taken from the wrong point shows), an `int index` (the
/// point's index: the CLI carries it, so its output names the input point of every vertex)
/// and the texture file the coordinates refer to; returns that cloud. The last three points
/// repeat the first three with other values: a merged duplicate gives its first occurrence's.
inline PointSet write_sample_with_attributes(const std::string& file) {
    PointSet cloud = io::read_point_set(HRSR_SAMPLE);
    for (std::size_t i = 0; i < 3; ++i) cloud.positions.push_back(cloud.positions[i]);
    auto add = [&](const std::string& name, ScalarType type, auto value_of) {
        PointAttribute a(name, type);
        for (std::size_t i = 0; i < cloud.size(); ++i) a.append(value_of(double(i)));
        cloud.attributes.push_back(a);
    };
    add("red", ScalarType::UInt8, [](double i) { return std::fmod(i, 256); });
    add("green", ScalarType::UInt8, [](double i) { return std::fmod(7 * i, 256); });
    add("blue", ScalarType::UInt8, [](double i) { return std::fmod(13 * i, 253); });
    add("alpha", ScalarType::UInt8, [](double i) { return 255 - std::fmod(i, 200); });
    add("quality", ScalarType::Float32, [](double i) { return 0.5 * i - 17.25; });
    add("radius", ScalarType::Float32, [](double i) { return 0.125 * std::fmod(i, 97); });
    add("texture_u", ScalarType::Float32, [](double i) { return std::fmod(i, 1024) / 1024; });
    add("texture_v", ScalarType::Float32, [](double i) { return std::fmod(i, 512) / 512; });
    add("index", ScalarType::Int32, [](double i) { return i; });
    const std::string plain = file + ".plain.ply";
    io::write_ply(plain, cloud.positions, {}, {}, cloud.precision, cloud.attributes);
    std::string bytes = slurp(plain);
    const std::string format = "format binary_little_endian 1.0\n";
    bytes.insert(bytes.find(format) + format.size(), "comment TextureFile owl_texture.png\n");
    std::ofstream(file, std::ios::binary) << bytes;
    std::remove(plain.c_str());
    // a 1 x 1 PNG: MeshLab 2022.02 and later replace a texture they cannot load by "dummy.png"
    static const char png[] =
        "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x01\x00\x00"
        "\x00\x01\x08\x02\x00\x00\x00\x90\x77\x53\xde\x00\x00\x00\x0c\x49\x44\x41\x54\x78\x9c\x63"
        "\xf8\xdf\xc0\x00\x00\x04\x01\x01\x80\xc5\x2a\x18\x5d\x00\x00\x00\x00\x49\x45\x4e\x44\xae"
        "\x42\x60\x82";
    const std::filesystem::path texture =
        std::filesystem::path(file).parent_path() / "owl_texture.png";
    std::ofstream(texture, std::ios::binary).write(png, sizeof png - 1);
    return cloud;
}

/// Writes the sample to `file` with a 16-bit colour (ushort red, green, blue), as hrsr writes
/// the colour of LAS files.
inline void write_sample_with_ushort_colour(const std::string& file) {
    PointSet cloud = io::read_point_set(HRSR_SAMPLE);
    for (const char* name : {"red", "green", "blue"}) {
        PointAttribute a(name, ScalarType::UInt16);
        for (std::size_t i = 0; i < cloud.size(); ++i) a.append(double(256 * (i % 256)));
        cloud.attributes.push_back(a);
    }
    io::write_ply(file, cloud.positions, {}, {}, cloud.precision, cloud.attributes);
}

/// The attribute called `name` of `cloud` (a failed expectation and null if there is none).
inline const PointAttribute* attribute(const PointSet& cloud, const std::string& name) {
    for (const PointAttribute& a : cloud.attributes)
        if (a.name == name) return &a;
    ADD_FAILURE() << "no attribute " << name;
    return nullptr;
}

/// Vertex k of the filter's `mesh` has the position and the `properties` of vertex k of the
/// CLI's mesh (which carries the input point's values onto the vertex made from it).
inline void expect_vertex_values_as_cli(const PointSet& mesh, const PointSet& cli,
                                        const std::vector<std::string>& properties) {
    ASSERT_EQ(mesh.size(), cli.size());
    EXPECT_EQ(mesh.positions, cli.positions);
    for (const std::string& name : properties) {
        const PointAttribute *ours = attribute(mesh, name), *theirs = attribute(cli, name);
        if (!ours || !theirs) continue;
        std::size_t differ = 0;
        for (std::size_t k = 0; k < mesh.size(); ++k) differ += ours->value(k) != theirs->value(k);
        EXPECT_EQ(differ, 0u) << name << " differs on " << differ << " of " << mesh.size()
                              << " vertices";
    }
}

/// What follows "end_header\n": vertices and faces, bit for bit.
inline std::string ply_body(const std::string& file) {
    const std::string bytes = slurp(file);
    const std::size_t end = bytes.find("end_header\n");
    return end == std::string::npos ? "" : bytes.substr(end + 11);
}

/// The saved mesh is edge- and vertex-manifold, without degenerate faces, and has faces.
inline void expect_manifold_mesh(const std::string& file) {
    std::size_t vertices = 0;
    std::vector<Triangle> triangles;
    ASSERT_TRUE(read_ply_faces(slurp(file), vertices, triangles)) << file;
    const MeshStats m = measure_mesh(vertices, triangles);
    EXPECT_GT(m.faces, 0u);
    EXPECT_EQ(m.non_manifold_edges, 0u);
    EXPECT_EQ(m.non_manifold_vertices, 0u);
    EXPECT_EQ(m.degenerate_faces, 0u);
}

/// "r_v = 99.1234 %" and "genus of closed ones: 1, 0" of the filter's log, as the CLI's report
/// gives them.
inline void expect_log_matches_report(const std::string& log, const nlohmann::json& report) {
    char r_v[32];
    std::snprintf(r_v, sizeof r_v, "r_v = %.4f %%",
                  100.0 * report.at("points").at("vertex_reference_ratio").get<double>());
    EXPECT_NE(log.find(r_v), std::string::npos) << r_v << " not in\n" << log;
    std::string genus;
    for (const auto& g : report.at("mesh").at("genus_of_closed_components"))
        genus += (genus.empty() ? "" : ", ") + std::to_string(g.get<long>());
    const std::string expected = "genus of closed ones: " + (genus.empty() ? "none" : genus) + ")";
    EXPECT_NE(log.find(expected), std::string::npos) << expected << " not in\n" << log;
}

} // namespace hrsr::testing
