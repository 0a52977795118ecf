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

#include <cstdio>
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
