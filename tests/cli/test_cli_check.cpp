// End-to-end tests of `hrsr check`: summary, JSON, --input, --reference, exit codes.
#include "cli_runner.h"
#include "io/ply_writer.h"
#include "mesh_fixtures.h"
#include "temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace hrsr {
namespace {

using testing::Outcome;

class CliCheck : public ::testing::Test {
protected:
    Outcome hrsr(const std::string& args) { return testing::run(HRSR_EXE, args, folder_.root()); }
    std::string path(const std::string& name) const { return folder_.path(name); }
    std::string write(const std::string& name, const testing::TestMesh& m) {
        io::write_ply(path(name), m.positions, {}, m.triangles, CoordinatePrecision::Double);
        return path(name);
    }

    testing::TempFolder folder_;
};

TEST_F(CliCheck, TorusJson) {
    const std::string mesh = write("torus.ply", testing::torus());
    const Outcome r = hrsr("check " + mesh + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["faces"], 1024);
    EXPECT_EQ(j["vertices"], 512);
    EXPECT_EQ(j["boundary_edges"], 0);
    EXPECT_EQ(j["components"], 1);
    EXPECT_EQ(j["genus_of_closed_components"], nlohmann::json::array({1}));
    EXPECT_EQ(
        j["largest_component"],
        nlohmann::json({{"vertices", 512}, {"faces", 1024}, {"genus", 1}, {"boundary_loops", 0}}));
    EXPECT_EQ(j["coherently_oriented"], true);
    EXPECT_EQ(j["self_intersecting_pairs"], 0);
    EXPECT_EQ(j["duplicate_faces"], 0);
    EXPECT_TRUE(j["faces_against_vertex_normals"].is_null()); // written without normals
    EXPECT_EQ(j["mesh"], mesh);
}

TEST_F(CliCheck, SummaryNamesTheProblems) {
    testing::TestMesh flipped = testing::square_patch(4);
    std::swap(flipped.triangles[10][1], flipped.triangles[10][2]); // an interior triangle
    Outcome r = hrsr("check " + write("flipped.ply", flipped));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("boundary: 16 edges in 1 loops"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("orientation: 3 inconsistent edges"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("0 duplicate"), std::string::npos) << r.out;

    testing::TestMesh doubled = testing::square_patch(4);
    doubled.triangles.push_back(doubled.triangles[10]);
    r = hrsr("check " + write("doubled.ply", doubled));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("1 duplicate"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("non-manifold: 3 edges"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("orientation: coherent"), std::string::npos) << r.out;
}

TEST_F(CliCheck, InputAndReferenceWithReportFile) {
    const testing::TestMesh m = testing::square_patch(8);
    const std::string mesh = write("patch.ply", m);
    const std::string reference = write("shifted.ply", testing::shifted(m, Vec3(0, 0, 0.01)));
    io::write_ply(path("cloud.ply"), m.positions, {}, {}, CoordinatePrecision::Double);
    const Outcome r = hrsr("check " + mesh + " --input " + path("cloud.ply") + " --reference " +
                           reference + " --samples 2000 --report " + path("check.json"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("r_v 100.0000 %"), std::string::npos) << r.out;
    const nlohmann::json j = nlohmann::json::parse(testing::slurp(path("check.json")));
    EXPECT_EQ(j["input"]["vertex_reference_ratio"], 1.0);
    EXPECT_EQ(j["input"]["points"], 81);
    const double diagonal = j["reference"]["diagonal"];
    EXPECT_NEAR(diagonal, std::sqrt(2.0), 1e-9);
    EXPECT_NEAR(double(j["reference"]["chamfer_of_diagonal"]), 0.01 / diagonal, 1e-9);
    EXPECT_NEAR(double(j["reference"]["hausdorff_of_diagonal"]), 0.01 / diagonal, 1e-9);
    EXPECT_EQ(j["reference"]["mesh_to_reference"]["area_samples"], 2000);
}

TEST_F(CliCheck, ExitCodes) {
    const std::string mesh = write("torus.ply", testing::torus());
    Outcome r = hrsr("check " + path("missing.ply"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("missing.ply"), std::string::npos);
    r = hrsr("check " + folder_.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\n"));
    EXPECT_EQ(r.exit_code, 1);
    r = hrsr("check " + mesh + " --reference " +
             folder_.write("cloud.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float "
                                        "x\nproperty float y\nproperty float z\nend_header\n0 0 "
                                        "0\n"));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.err.find("no triangles"), std::string::npos) << r.err;
    r = hrsr("check " + mesh + " --report " + mesh); // never overwrite the input
    EXPECT_EQ(r.exit_code, 2);
    r = hrsr("check " + mesh + " --samples -3");
    EXPECT_EQ(r.exit_code, 2);
    r = hrsr("check");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(testing::lines(r.err), 1);
}

TEST_F(CliCheck, ChecksWhatReconstructWrites) {
    const Outcome made = hrsr(std::string("reconstruct ") + HRSR_SAMPLE + " -o " + path("owl.ply") +
                              " -q --report " + path("report.json"));
    ASSERT_EQ(made.exit_code, 0) << made.err;
    const Outcome r = hrsr("check " + path("owl.ply") + " --input " + HRSR_SAMPLE + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json c = nlohmann::json::parse(r.out);
    const nlohmann::json report = nlohmann::json::parse(testing::slurp(path("report.json")));
    // The checker and the reconstruction's own report agree.
    for (const char* key : {"vertices", "faces", "boundary_edges", "boundary_loops",
                            "non_manifold_edges", "non_manifold_vertices", "components"})
        EXPECT_EQ(c[key], report["mesh"][key]) << key;
    EXPECT_EQ(c["genus_of_closed_components"], report["mesh"]["genus_of_closed_components"]);
    EXPECT_EQ(c["largest_component"], report["mesh"]["largest_component"]);
    EXPECT_EQ(c["input"]["present_as_vertices"], report["points"]["referenced"]);
    EXPECT_EQ(c["degenerate_faces"], 0);
    EXPECT_EQ(c["duplicate_faces"], 0);
    // The output has normals: faces against them are counted (D-64 leaves few; the report's
    // own count uses the algorithm's normals, which D-54 may have turned).
    ASSERT_TRUE(c["faces_against_vertex_normals"].is_number()) << c.dump();
    EXPECT_LT(c["faces_against_vertex_normals"].get<double>(), 0.01 * c["faces"].get<double>());
}

} // namespace
} // namespace hrsr
