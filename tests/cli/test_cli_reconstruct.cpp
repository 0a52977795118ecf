// End-to-end tests of `hrsr reconstruct --method rsr`: exit codes, the written mesh (vertices at
// the input coordinates, bit-exact; faces), the JSON report and determinism across threads.
#include "cli_runner.h"
#include "io/point_set_reader.h"
#include "ply_faces.h"
#include "reconstruction.h"
#include "samplers.h"
#include "temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace fs = std::filesystem;

namespace hrsr {
namespace {

using testing::lines;
using testing::Outcome;
using testing::read_ply_faces;
using testing::slurp;

class CliReconstruct : public ::testing::Test {
protected:
    // Runs hrsr with `args`, no stdin.
    Outcome hrsr(const std::string& args) { return testing::run(HRSR_EXE, args, folder_.root()); }
    std::string path(const std::string& name) const { return folder_.path(name); }

    testing::TempFolder folder_;
};

bool same_bits(const Vec3& a, const Vec3& b) {
    return std::memcmp(&a[0], &b[0], sizeof(double)) == 0 &&
           std::memcmp(&a[1], &b[1], sizeof(double)) == 0 &&
           std::memcmp(&a[2], &b[2], sizeof(double)) == 0;
}

TEST_F(CliReconstruct, WritesAMeshOverTheInputPointsAndAReport) {
    const Outcome r = hrsr("reconstruct " + std::string(HRSR_SAMPLE) + " --method rsr -o " +
                           path("out.ply") + " --report " + path("r.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;

    const nlohmann::json report = nlohmann::json::parse(slurp(path("r.json")));
    const nlohmann::json& mesh = report.at("mesh");
    const double ratio = report.at("points").at("vertex_reference_ratio").get<double>();
    EXPECT_GT(ratio, 0.99);
    EXPECT_LE(ratio, 1.0);
    for (const char* key : {"boundary_edges", "boundary_loops", "non_manifold_edges",
                            "non_manifold_vertices", "components", "vertices", "faces"})
        ASSERT_TRUE(mesh.contains(key) && mesh.at(key).is_number_unsigned()) << key;
    EXPECT_EQ(mesh.at("non_manifold_edges").get<long>(), 0);
    EXPECT_EQ(mesh.at("non_manifold_vertices").get<long>(), 0);
    EXPECT_GE(mesh.at("components").get<long>(), 1);
    EXPECT_EQ(mesh.at("boundary_edges").get<long>() == 0,
              mesh.at("boundary_loops").get<long>() == 0);
    ASSERT_TRUE(mesh.at("genus_of_closed_components").is_array());
    EXPECT_LE(mesh.at("genus_of_closed_components").size(),
              mesh.at("components").get<std::size_t>());
    for (const nlohmann::json& genus : mesh.at("genus_of_closed_components"))
        EXPECT_GE(genus.get<long>(), 0);
    const nlohmann::json& largest = mesh.at("largest_component");
    EXPECT_LE(largest.at("faces").get<long>(), mesh.at("faces").get<long>());
    EXPECT_GE(largest.at("genus").get<long>(), 0);
    EXPECT_LE(largest.at("boundary_loops").get<long>(), mesh.at("boundary_loops").get<long>());
    ASSERT_TRUE(report.at("rsr").at("handles").is_number_unsigned());
    ASSERT_TRUE(report.at("timings").is_array());
    EXPECT_FALSE(report.at("timings").empty());
    for (const nlohmann::json& t : report.at("timings")) {
        EXPECT_TRUE(t.at("phase").is_string());
        EXPECT_GE(t.at("seconds").get<double>(), 0.0);
    }
    EXPECT_GT(report.at("peak_memory_bytes").get<double>(), 0.0);

    // The mesh: as many vertices as reported, each at the coordinates of an input point.
    const PointSet input = io::read_point_set(HRSR_SAMPLE);
    const PointSet out = io::read_point_set(path("out.ply"));
    ASSERT_EQ(out.size(), mesh.at("vertices").get<std::size_t>());
    std::map<std::array<double, 3>, std::uint32_t> input_point;
    for (std::uint32_t i = 0; i < input.size(); ++i)
        input_point.emplace(std::array<double, 3>{input.positions[i][0], input.positions[i][1],
                                                  input.positions[i][2]},
                            i);
    std::size_t not_input = 0;
    for (const Vec3& p : out.positions)
        if (!input_point.count({p[0], p[1], p[2]})) ++not_input;
    EXPECT_EQ(not_input, 0u);

    // Faces: as many as reported; the library's own result on the same input and defaults
    // says which input point each vertex stands for, and the written positions are those points
    // bit for bit.
    std::size_t vertices = 0;
    std::vector<Triangle> faces;
    ASSERT_TRUE(read_ply_faces(slurp(path("out.ply")), vertices, faces));
    EXPECT_EQ(faces.size(), mesh.at("faces").get<std::size_t>());
    EXPECT_GT(faces.size(), out.size());
    ReconstructionReport library_report;
    const Reconstruction expected = reconstruct_rsr(input, RsrOptions{}, {}, library_report);
    ASSERT_EQ(expected.vertex_input_index.size(), out.size());
    EXPECT_EQ(faces, expected.triangles);
    std::size_t moved = 0;
    for (std::size_t v = 0; v < out.size(); ++v)
        if (!same_bits(out.positions[v], input.positions[expected.vertex_input_index[v]])) ++moved;
    EXPECT_EQ(moved, 0u);
    EXPECT_EQ(ratio, library_report.vertex_reference_ratio);
}

// D-33: a cloud noisier than a point spacing is reconstructed on smoothed positions, which the
// summary says and the report records; the mesh's vertices are still the input points.
TEST_F(CliReconstruct, SaysWhenTheCloudIsNoisyEnoughForSmoothedPositions) {
    PointSet s = testing::sample_sphere(20000);
    testing::add_noise(s, 0.015 * testing::bounding_box_diagonal(s));
    std::ostringstream xyz;
    xyz.precision(17);
    for (std::size_t i = 0; i < s.size(); ++i)
        xyz << s.positions[i][0] << ' ' << s.positions[i][1] << ' ' << s.positions[i][2] << ' '
            << s.normals[i][0] << ' ' << s.normals[i][1] << ' ' << s.normals[i][2] << '\n';
    std::ofstream(path("noisy.xyz")) << xyz.str();
    const Outcome r = hrsr("reconstruct " + path("noisy.xyz") + " -o " + path("out.ply") +
                           " --report " + path("r.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("so HRsR worked on smoothed positions"), std::string::npos) << r.out;
    const nlohmann::json report = nlohmann::json::parse(slurp(path("r.json")));
    const nlohmann::json& smoothing = report.at("preprocess").at("smoothing");
    EXPECT_TRUE(smoothing.at("hrsr_on_smoothed_positions").get<bool>());
    EXPECT_GT(smoothing.at("relative_noise").get<double>(), 0.2);
    EXPECT_EQ(report.at("mesh").at("boundary_edges").get<long>(), 0);
    const PointSet in = io::read_point_set(path("noisy.xyz"));
    const PointSet out = io::read_point_set(path("out.ply"));
    std::map<std::array<double, 3>, int> input_point;
    for (const Vec3& p : in.positions) input_point[{p[0], p[1], p[2]}] = 1;
    for (const Vec3& p : out.positions) EXPECT_TRUE(input_point.count({p[0], p[1], p[2]}));

    // The shipped sample is not noisy: no such line, the flag false.
    const Outcome clean = hrsr("reconstruct " + std::string(HRSR_SAMPLE) + " -o " +
                               path("owl.ply") + " --report " + path("owl.json"));
    ASSERT_EQ(clean.exit_code, 0) << clean.err;
    EXPECT_EQ(clean.out.find("smoothed positions"), std::string::npos);
    EXPECT_FALSE(nlohmann::json::parse(slurp(path("owl.json")))
                     .at("preprocess")
                     .at("smoothing")
                     .at("hrsr_on_smoothed_positions")
                     .get<bool>());
}

TEST_F(CliReconstruct, InvalidHandlesIsAUsageError) {
    const Outcome r = hrsr("reconstruct " + std::string(HRSR_SAMPLE) + " --method rsr -o " +
                           path("out.ply") + " --report " + path("r.json") + " --handles -2");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("handles"), std::string::npos) << r.err;
    EXPECT_EQ(folder_.entries(), std::vector<std::string>{});
}

TEST_F(CliReconstruct, UnknownMethodIsAUsageError) {
    const Outcome r = hrsr("reconstruct " + std::string(HRSR_SAMPLE) + " -o " + path("out.ply") +
                           " --method foo");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("method"), std::string::npos) << r.err;
    EXPECT_EQ(folder_.entries(), std::vector<std::string>{});
}

TEST_F(CliReconstruct, SameBytesForOneAndTwoThreads) {
    for (const char* threads : {"1", "2"}) {
        const Outcome r = hrsr("reconstruct " + std::string(HRSR_SAMPLE) + " -q --method rsr -o " +
                               path(std::string("t") + threads + ".ply") + " --threads " + threads);
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const std::string one = slurp(path("t1.ply")), two = slurp(path("t2.ply"));
    EXPECT_GT(one.size(), 10000u * 24);
    EXPECT_TRUE(one == two);
}

} // namespace
} // namespace hrsr
