// The MeshLab filter through meshlabserver 2020.09 (headless, private prefix): listed with every
// parameter, unit and default; the same mesh as the CLI on clouds with and without normals, on a
// layer with faces and on a layer with deleted vertices; dropped points selected; progress per
// phase; the comparison script; `cmake --install` to where MeshLab loads plugins.
#include "cli_runner.h"
#include "filter_checks.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"
#include "mesh/mesh_stats.h"
#include "meshlab_server.h"
#include "ply_faces.h"
#include "temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace hrsr {
namespace {

using testing::default_text;
using testing::expect_log_matches_report;
using testing::expect_manifold_mesh;
using testing::Outcome;
using testing::ply_body;
using testing::slurp;

class MeshLabFilter : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(server_.created()) << "make_prefix.sh failed"; }

    std::string path(const std::string& name) const { return folder_.path(name); }
    Outcome hrsr(const std::string& args) const {
        return testing::run(HRSR_EXE, args, folder_.root());
    }
    /// Runs `script` (written to script.mlx) with meshlabserver, log in log.txt.
    Outcome run_script(const std::string& script, const std::string& args) const {
        folder_.write("script.mlx", script);
        return server_.run("-l " + path("log.txt") + " " + args + " -s " + path("script.mlx"));
    }
    std::string log() const { return slurp(path("log.txt")); }
    /// The CLI's mesh and JSON report for `cloud` with default options.
    nlohmann::json cli(const std::string& cloud, const std::string& mesh) const {
        const Outcome r =
            hrsr("reconstruct " + cloud + " -o " + mesh + " -q --report " + path("cli.json"));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return nlohmann::json::parse(slurp(path("cli.json")));
    }

    testing::TempFolder folder_;
    testing::MeshLabServer server_{folder_.root().string(), HRSR_PLUGIN};
};

TEST_F(MeshLabFilter, DumpListsEveryParameterWithUnitAndDefault) {
    const Outcome r = server_.run("-d " + path("filters.txt"));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const std::string dump = slurp(path("filters.txt"));
    const std::size_t at = dump.find("Surface Reconstruction: HRsR");
    ASSERT_NE(at, std::string::npos);
    const std::string section = dump.substr(at, dump.find("\\section", at) - at);

    const ReconstructionOptions d;
    // label, unit, default: every parameter, defaults as the core's options header has them
    const std::vector<std::array<std::string, 3>> expected{
        {"k (neighbours)", "points", default_text(d.rsr.preprocess.k)},
        {"Collapse ratio p", "fraction of the points", default_text(d.collapse.collapse_ratio)},
        {"l_min (level of detail)", "length in model units", default_text(d.reexpand.l_min)},
        {"Handles", "count", default_text(d.rsr.handles)},
        {"Method", "choice", "HRsR"},
        {"Collapse neighbours", "points", default_text(d.collapse.collapse_k)},
        {"θ (normal angle)", "degrees", default_text(d.rsr.preprocess.theta_degrees)},
        {"r (outlier cut)", "multiple of the mean neighbour distance",
         default_text(d.rsr.preprocess.r)},
        {"n (shortest handle)", "point spacings", default_text(int(d.rsr.min_handle_loop))},
        {"Distance", "choice", "Tangent"},
        {"Normals", "choice", "Use the layer's normals"},
        {"Select dropped points", "on/off", "off"}};
    std::size_t rows = 0;
    for (std::size_t from = 0; (from = section.find("<TR>", from)) != std::string::npos; ++from)
        ++rows;
    EXPECT_EQ(rows, expected.size());
    for (const auto& [label, unit, value] : expected) {
        const std::size_t row = section.find("<TD> " + label + " </TD>");
        ASSERT_NE(row, std::string::npos) << label;
        const std::string line = section.substr(row, section.find("</TR>", row) - row);
        EXPECT_NE(line.find("Unit: " + unit), std::string::npos) << line;
        EXPECT_NE(line.find("Default: " + value), std::string::npos) << line;
    }
    // the HTML help: both papers, and every parameter by name in its table
    for (const char* s : {"Surface Reconstruction Using Rotation Systems", "arXiv:2402.01893",
                          "Hierarchical Rotation System Reconstruction", "arXiv:2606.07078"})
        EXPECT_NE(section.find(s), std::string::npos) << s;
    for (const char* name : {"k", "collapse_ratio", "l_min", "handles", "method", "collapse_k",
                             "theta", "r", "n", "distance", "normals", "select_dropped"})
        EXPECT_NE(section.find("<tt>" + std::string(name) + "</tt>"), std::string::npos) << name;
}

TEST_F(MeshLabFilter, CloudWithoutNormalsGivesTheCliMeshWithProgressPerPhase) {
    const Outcome r =
        run_script(testing::mlx(testing::hrsr_filter()),
                   "-i " + std::string(HRSR_SAMPLE) + " -o " + path("mesh.ply") + " -m vn");
    ASSERT_EQ(r.exit_code, 0) << r.out << log();
    const nlohmann::json report = cli(HRSR_SAMPLE, path("cli.ply"));
    EXPECT_EQ(ply_body(path("mesh.ply")), ply_body(path("cli.ply")));
    expect_manifold_mesh(path("mesh.ply"));
    expect_log_matches_report(log(), report);
    // meshlabserver prints each progress message: every phase, in pipeline order, RsR (one
    // large piece, or the pieces under 20,000 points together) between collapse and re-expansion
    std::size_t at = 0;
    for (const char* phase : {"normal estimation", "smoothing", "collapse graph", "re-expansion"}) {
        at = r.out.find(phase, at);
        EXPECT_NE(at, std::string::npos) << phase;
    }
    const std::size_t rsr = std::min(r.out.find("small components"), r.out.find("face split"));
    EXPECT_LT(r.out.find("collapse graph"), rsr);
    EXPECT_LT(rsr, r.out.find("re-expansion"));
}

TEST_F(MeshLabFilter, CloudWithNormalsGivesTheCliMesh) {
    ASSERT_EQ(
        hrsr("normals " + std::string(HRSR_SAMPLE) + " -o " + path("cloud.ply") + " -q").exit_code,
        0);
    const Outcome r = run_script(testing::mlx(testing::hrsr_filter({{"k", "40"}})),
                                 "-i " + path("cloud.ply") + " -o " + path("mesh.ply") + " -m vn");
    ASSERT_EQ(r.exit_code, 0) << r.out << log();
    EXPECT_EQ(log().find("normals are estimated"), std::string::npos) << "layer normals unused";
    const Outcome c = hrsr("reconstruct " + path("cloud.ply") + " -o " + path("cli.ply") +
                           " -q --k 40 --report " + path("cli.json"));
    ASSERT_EQ(c.exit_code, 0) << c.err;
    EXPECT_EQ(ply_body(path("mesh.ply")), ply_body(path("cli.ply")));
    expect_manifold_mesh(path("mesh.ply"));
    expect_log_matches_report(log(), nlohmann::json::parse(slurp(path("cli.json"))));
}

TEST_F(MeshLabFilter, LayerWithFacesUsesItsVerticesAndKeepsItsFaces) {
    cli(HRSR_SAMPLE, path("input_mesh.ply")); // a mesh with faces and normals as input
    const Outcome r = run_script(testing::mlx(testing::hrsr_filter()),
                                 "-i " + path("input_mesh.ply") + " -o " + path("mesh.ply") +
                                     " -l 1 -m vn -o " + path("input_after.ply") + " -l 0 -m vn");
    ASSERT_EQ(r.exit_code, 0) << r.out << log();
    const nlohmann::json report = cli(path("input_mesh.ply"), path("cli.ply"));
    EXPECT_EQ(ply_body(path("mesh.ply")), ply_body(path("cli.ply")));
    expect_log_matches_report(log(), report);
    EXPECT_EQ(ply_body(path("input_after.ply")), ply_body(path("input_mesh.ply")));
}

TEST_F(MeshLabFilter, DeletedVerticesAreIgnored) {
    const PointSet owl = io::read_point_set(HRSR_SAMPLE);
    double low = owl.positions[0][0], high = low;
    for (const Vec3& p : owl.positions) low = std::min(low, p[0]), high = std::max(high, p[0]);
    const double cut = low + 0.3 * (high - low);
    // delete the points with x < cut (meshlabserver does not compact between filters, so the
    // filter sees them as deleted vertices), reconstruct; save the cut cloud and the mesh
    const std::string script = testing::mlx(
        " <filter name=\"Conditional Vertex Selection\">\n"
        "  <Param type=\"RichString\" name=\"condSelect\" value=\"(x &lt; " +
        std::to_string(cut) + ")\"/>\n </filter>\n <filter name=\"Delete Selected Vertices\"/>\n" +
        testing::hrsr_filter());
    const Outcome r =
        run_script(script, "-i " + std::string(HRSR_SAMPLE) + " -o " + path("cut.ply") +
                               " -l 0 -o " + path("mesh.ply") + " -l 1 -m vn");
    ASSERT_EQ(r.exit_code, 0) << r.out << log();
    const PointSet kept = io::read_point_set(path("cut.ply"));
    ASSERT_GT(kept.size(), 1000u);
    ASSERT_LT(kept.size(), owl.size() - 1000);
    EXPECT_NE(log().find("HRsR: " + std::to_string(kept.size()) + " input points"),
              std::string::npos)
        << log();
    const nlohmann::json report = cli(path("cut.ply"), path("cli.ply"));
    EXPECT_EQ(ply_body(path("mesh.ply")), ply_body(path("cli.ply")));
    expect_log_matches_report(log(), report);
}

TEST_F(MeshLabFilter, SelectDroppedSelectsExactlyThePointsNotInTheMesh) {
    const std::size_t outliers = 30;
    const PointSet cloud = testing::write_sample_with_far_outliers(path("cloud.ply"), outliers);
    // reconstruct with select_dropped, then delete the selection in the input layer (layer 0)
    const std::string script =
        testing::mlx(testing::hrsr_filter({{"select_dropped", "true"}}) +
                     " <filter name=\"Change the current layer\">\n"
                     "  <Param type=\"RichMesh\" name=\"layer\" value=\"0\"/>\n </filter>\n"
                     " <filter name=\"Delete Selected Vertices\"/>\n");
    const Outcome r = run_script(script, "-i " + path("cloud.ply") + " -o " + path("left.ply") +
                                             " -l 0 -o " + path("mesh.ply") + " -l 1");
    ASSERT_EQ(r.exit_code, 0) << r.out << log();
    const nlohmann::json report = cli(path("cloud.ply"), path("cli.ply"));
    const std::size_t dropped =
        cloud.size() - report.at("points").at("referenced").get<std::size_t>();
    EXPECT_GE(dropped, outliers);
    EXPECT_NE(
        log().find("HRsR: " + std::to_string(dropped) + " points not in the mesh are selected"),
        std::string::npos)
        << log();
    // what is left of the input is exactly the set of mesh vertex positions
    const PointSet left = io::read_point_set(path("left.ply"));
    const PointSet mesh = io::read_point_set(path("mesh.ply"));
    EXPECT_EQ(left.size(), cloud.size() - dropped);
    auto as_set = [](const PointSet& s) {
        std::set<std::array<double, 3>> points;
        for (const Vec3& p : s.positions) points.insert({p[0], p[1], p[2]});
        return points;
    };
    EXPECT_EQ(as_set(left), as_set(mesh));
}

TEST_F(MeshLabFilter, MeshVerticesCarryTheLayersColourQualityRadiusAndTexCoord) {
    testing::write_sample_with_attributes(path("cloud.ply"));
    const Outcome r =
        run_script(testing::mlx(testing::hrsr_filter()),
                   "-i " + path("cloud.ply") + " -o " + path("mesh.ply") + " -m vc vq vr vt vn");
    ASSERT_EQ(r.exit_code, 0) << r.out << log();
    cli(path("cloud.ply"), path("cli.ply"));
    const PointSet mesh = io::read_point_set(path("mesh.ply"));
    const PointSet cli = io::read_point_set(path("cli.ply"));
    ASSERT_GE(mesh.size(), 10000u) << log();
    testing::expect_vertex_values_as_cli(mesh, cli, testing::kLayerProperties);
    // the texture the coordinates refer to
    EXPECT_NE(slurp(path("mesh.ply")).find("comment TextureFile owl_texture.png\n"),
              std::string::npos);
}

TEST_F(MeshLabFilter, MeshVerticesCarryTheLayersCustomAttributes) {
    // MeshLab 2020.09 reads no custom PLY property and saves custom attributes only when its
    // dialog asks, so the attribute is made by a MeshLab filter (label = 3 * vertex index + 1,
    // a float) and read back through the quality of the mesh layer.
    testing::write_sample_with_attributes(path("cloud.ply"));
    const std::string script = testing::mlx(
        " <filter name=\"Define New Per Vertex Attribute\">\n"
        "  <Param type=\"RichString\" name=\"name\" value=\"label\"/>\n"
        "  <Param type=\"RichString\" name=\"expr\" value=\"3 * vi + 1\"/>\n </filter>\n" +
        testing::hrsr_filter() +
        " <filter name=\"Per Vertex Quality Function\">\n"
        "  <Param type=\"RichString\" name=\"q\" value=\"label\"/>\n"
        "  <Param type=\"RichBool\" name=\"normalize\" value=\"false\"/>\n"
        "  <Param type=\"RichBool\" name=\"map\" value=\"false\"/>\n"
        "  <Param type=\"RichBool\" name=\"onselected\" value=\"false\"/>\n </filter>\n");
    const Outcome r =
        run_script(script, "-i " + path("cloud.ply") + " -o " + path("mesh.ply") + " -m vq");
    ASSERT_EQ(r.exit_code, 0) << r.out << log();
    EXPECT_EQ(log().find("is not carried"), std::string::npos) << log();
    cli(path("cloud.ply"), path("cli.ply"));
    const PointSet mesh = io::read_point_set(path("mesh.ply"));
    const PointSet cli = io::read_point_set(path("cli.ply"));
    ASSERT_EQ(mesh.size(), cli.size());
    const PointAttribute* quality = testing::attribute(mesh, "quality");
    const PointAttribute* index = testing::attribute(cli, "index"); // the input point of vertex k
    ASSERT_TRUE(quality && index);
    std::size_t differ = 0;
    for (std::size_t k = 0; k < mesh.size(); ++k)
        differ += quality->value(k) != 3 * index->value(k) + 1;
    EXPECT_EQ(differ, 0u) << "of " << mesh.size() << " vertices";
}

TEST_F(MeshLabFilter, SixteenBitColourDoesNotReachMeshLab) {
    // MeshLab's PLY importer (vcglib's) reads red/green/blue as uchar only: with a ushort colour
    // (as hrsr writes for 16-bit LAS colour) 2020.09 has only its default white. The README
    // says so; this fails when MeshLab starts reading it.
    testing::write_sample_with_ushort_colour(path("cloud.ply"));
    const Outcome r = run_script(testing::mlx(testing::hrsr_filter()),
                                 "-i " + path("cloud.ply") + " -o " + path("mesh.ply") + " -m vc");
    ASSERT_EQ(r.exit_code, 0) << r.out << log();
    const PointSet mesh = io::read_point_set(path("mesh.ply"));
    ASSERT_GE(mesh.size(), 9000u);
    for (const char* name : {"red", "green", "blue"}) {
        const PointAttribute* a = testing::attribute(mesh, name);
        ASSERT_TRUE(a);
        for (std::size_t k = 0; k < mesh.size(); ++k) ASSERT_EQ(a->value(k), 255) << name << k;
    }
}

TEST_F(MeshLabFilter, ComparisonScriptSavesHrsrBallPivotingAndPoisson) {
    ASSERT_EQ(
        hrsr("normals " + std::string(HRSR_SAMPLE) + " -o " + path("cloud.ply") + " -q").exit_code,
        0);
    const Outcome r =
        testing::run("bash " + std::string(HRSR_SOURCE_DIR) + "/scripts/meshlab_compare.sh",
                     path("cloud.ply") + " " + path("out") + " " + HRSR_PLUGIN, folder_.root());
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    for (const char* name : {"hrsr.ply", "ball_pivoting.ply", "poisson.ply"}) {
        std::size_t vertices = 0;
        std::vector<Triangle> triangles;
        ASSERT_TRUE(testing::read_ply_faces(slurp(path("out/") + name), vertices, triangles))
            << name;
        EXPECT_GT(triangles.size(), 1000u) << name;
    }
    expect_manifold_mesh(path("out/hrsr.ply"));
    const nlohmann::json report = cli(path("cloud.ply"), path("cli.ply"));
    EXPECT_EQ(ply_body(path("out/hrsr.ply")), ply_body(path("cli.ply")));
}

TEST_F(MeshLabFilter, InstallPutsThePluginWhereMeshLabLoadsIt) {
    // where Debian's MeshLab keeps its own plugins (one of them: the Ball Pivoting one)
    const Outcome files = testing::run("dpkg", "-L meshlab", folder_.root());
    ASSERT_EQ(files.exit_code, 0);
    const std::string clean = "/libfilter_clean.so\n";
    const std::size_t end = files.out.find(clean);
    ASSERT_NE(end, std::string::npos) << files.out;
    const std::string plugins =
        files.out.substr(files.out.rfind('\n', end) + 1, end - files.out.rfind('\n', end) - 1);
    // a private copy of the system layout under root/usr, then the install into it
    const std::string root = path("root");
    const Outcome make = testing::run("sh " + std::string(HRSR_PLUGIN_TESTS) + "/make_prefix.sh",
                                      "- " + root + "/usr", folder_.root());
    ASSERT_EQ(make.exit_code, 0) << make.err;
    const Outcome install = testing::run(
        "DESTDIR=" + root + " cmake --install " + std::string(HRSR_BUILD_DIR), "", folder_.root());
    ASSERT_EQ(install.exit_code, 0) << install.out << install.err;
    const std::filesystem::path file = root + plugins + "/libfilter_hrsr.so";
    ASSERT_TRUE(std::filesystem::is_regular_file(file)) << file << "\n" << install.out;
    const Outcome list =
        testing::run("cd " + root + " && xvfb-run -a " + root + "/usr/bin/meshlabserver",
                     "-d " + path("filters.txt"), folder_.root());
    ASSERT_EQ(list.exit_code, 0) << list.out;
    EXPECT_NE(slurp(path("filters.txt")).find("Surface Reconstruction: HRsR"), std::string::npos);
}

} // namespace
} // namespace hrsr
