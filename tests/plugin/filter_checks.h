// Checks shared by the plugin tests of every MeshLab version: the mesh bit for bit, its
// manifoldness, and the filter's log against the CLI's JSON report.
#pragma once

#include "cli_runner.h"
#include "mesh/mesh_stats.h"
#include "ply_faces.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace hrsr::testing {

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
