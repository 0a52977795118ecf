// The MeshLab filter in MeshLab 2022.02 (Debian trixie) or 2025.07 (sid): built inside that
// release's root against its own headers and run through meshlab_host, as PyMeshLab would run
// it (scripts/test_meshlab_roots.sh makes the roots and sets HRSR_MESHLAB_ROOT). Listed with
// every parameter and default; the CLI's mesh on clouds without and with normals; bad parameters
// and bad input fail with the reason; the dropped-point selection is exact; `cmake --install`
// puts the plugin where that MeshLab loads it.
#include "filter_checks.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"
#include "meshlab_root.h"
#include "options.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace hrsr::testing {
namespace {

class MeshLabRootFilter : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(root_.exists()) << "HRSR_MESHLAB_ROOT is not a root with the plugin built "
                                       "(scripts/test_meshlab_roots.sh makes it)";
    }
    std::string path(const std::string& name) const { return root_.path(name); }
    std::string inside(const std::string& name) const { return root_.inside(name); }
    /// The CLI (on the host) on `cloud` with `options`; its JSON report.
    nlohmann::json cli(const std::string& cloud, const std::string& mesh,
                       const std::string& options = "") const {
        const Outcome r = testing::run(HRSR_EXE,
                                       "reconstruct " + cloud + " -o " + mesh + " -q " + options +
                                           " --report " + path("cli.json"),
                                       path(""));
        EXPECT_EQ(r.exit_code, 0) << r.err;
        return nlohmann::json::parse(slurp(path("cli.json")));
    }
    /// The filter on `cloud` (a file of the work folder) into mesh.ply with `parameters`.
    Outcome apply(const std::string& cloud, const std::string& parameters = "") const {
        return root_.host(inside(cloud) + " " + inside("mesh.ply") + " " + parameters);
    }

    testing::MeshLabRoot root_;
};

TEST_F(MeshLabRootFilter, ListsEveryParameterWithItsDefault) {
    const Outcome r = root_.host("--list");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const ReconstructionOptions d;
    // name, type, default (an enum's as its text), label: the core's defaults, in dialog order
    const std::vector<std::array<std::string, 4>> expected{
        {"k", "RichInt", default_text(d.rsr.preprocess.k), "k (neighbours)"},
        {"collapse_ratio", "RichDynamicFloat", default_text(d.collapse.collapse_ratio),
         "Collapse ratio p"},
        {"l_min", "RichAbsPerc", default_text(d.reexpand.l_min), "l_min (level of detail)"},
        {"handles", "RichInt", default_text(d.rsr.handles), "Handles"},
        {"method", "RichEnum", "HRsR (collapse, RsR, re-expansion)", "Method"},
        {"collapse_k", "RichInt", default_text(d.collapse.collapse_k), "Collapse neighbours"},
        {"theta", "RichFloat", default_text(d.rsr.preprocess.theta_degrees), "θ (normal angle)"},
        {"r", "RichFloat", default_text(d.rsr.preprocess.r), "r (outlier cut)"},
        {"n", "RichInt", default_text(double(d.rsr.min_handle_loop)), "n (shortest handle)"},
        {"distance", "RichEnum", "Tangent (smooths along normals)", "Distance"},
        {"normals", "RichEnum", "Use the layer's normals (estimate if missing or unusable)",
         "Normals"},
        {"select_dropped", "RichBool", "false", "Select dropped points"}};
    std::string lines;
    for (const auto& [name, type, value, label] : expected)
        lines += name + "\t" + type + "\t" + value + "\t" + label + "\n";
    EXPECT_EQ(r.out, lines);
}

TEST_F(MeshLabRootFilter, PyMeshLabNameIsTheSameFilter) {
    const Outcome menu = root_.host("--list");
    const Outcome python =
        root_.host("--list", testing::MeshLabRoot::kPlugin, "generate_surface_reconstruction_hrsr");
    ASSERT_EQ(python.exit_code, 0) << python.err;
    EXPECT_EQ(python.out, menu.out);
    EXPECT_FALSE(python.out.empty());
}

TEST_F(MeshLabRootFilter, SampleGivesTheCliMeshWithProgressPerPhase) {
    std::filesystem::copy_file(HRSR_SAMPLE, path("owl.ply"));
    const Outcome r = apply("owl.ply");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const nlohmann::json report = cli(HRSR_SAMPLE, path("cli.ply"));
    EXPECT_EQ(ply_body(path("mesh.ply")), ply_body(path("cli.ply")));
    expect_manifold_mesh(path("mesh.ply"));
    expect_log_matches_report(r.out, report);
    // the progress callback sees every phase in pipeline order, RsR between collapse and
    // re-expansion
    std::size_t at = 0;
    for (const char* phase :
         {"normal estimation", "smoothing", "collapse graph", "re-expansion", "fold repair"}) {
        at = r.out.find("% " + std::string(phase), at);
        EXPECT_NE(at, std::string::npos) << phase << " not in order in\n" << r.out;
    }
    const std::size_t rsr = std::min(r.out.find("small components"), r.out.find("face split"));
    EXPECT_LT(r.out.find("collapse graph"), rsr);
    EXPECT_LT(rsr, r.out.find("re-expansion"));
}

TEST_F(MeshLabRootFilter, CloudWithNormalsGivesTheCliMesh) {
    const Outcome n = testing::run(
        HRSR_EXE, "normals " + std::string(HRSR_SAMPLE) + " -o " + path("cloud.ply") + " -q",
        path(""));
    ASSERT_EQ(n.exit_code, 0) << n.err;
    const Outcome r = apply("cloud.ply", "k=40 collapse_ratio=0.25");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.out.find("normals are estimated"), std::string::npos) << "layer normals unused";
    const nlohmann::json report =
        cli(path("cloud.ply"), path("cli.ply"), "--k 40 --collapse-ratio 0.25");
    EXPECT_EQ(ply_body(path("mesh.ply")), ply_body(path("cli.ply")));
    expect_manifold_mesh(path("mesh.ply"));
    expect_log_matches_report(r.out, report);
}

TEST_F(MeshLabRootFilter, BadParametersFailWithTheReason) {
    std::filesystem::copy_file(HRSR_SAMPLE, path("owl.ply"));
    // name=value, the reason expected
    const std::vector<std::array<std::string, 2>> cases{
        {"k=2", "k (neighbours) must be between"},
        {"handles=-5", "Handles must be"},
        {"collapse_ratio=0", "Collapse ratio p must be in (0, 1]"},
        {"k=many", "parameter k: cannot use the value many"},
        {"no_such=1", "no parameter no_such=1"}};
    for (const auto& [assignment, reason] : cases) {
        const Outcome r = apply("owl.ply", assignment);
        EXPECT_EQ(r.exit_code, 1) << assignment << "\n" << r.out << r.err;
        EXPECT_NE(r.err.find(reason), std::string::npos) << assignment << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(path("mesh.ply"))) << assignment;
    }
}

TEST_F(MeshLabRootFilter, BadInputFailsWithTheReason) {
    std::ofstream(path("two.ply")) << "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                                      "property float y\nproperty float z\nend_header\n0 0 0\n1 0 "
                                      "0\n";
    const Outcome r = apply("two.ply");
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.err.find("at least 3 are needed"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(path("mesh.ply")));
}

TEST_F(MeshLabRootFilter, SelectDroppedSelectsExactlyThePointsNotInTheMesh) {
    const std::size_t outliers = 30;
    const PointSet cloud = testing::write_sample_with_far_outliers(path("cloud.ply"), outliers);
    const Outcome r =
        apply("cloud.ply", "select_dropped=true --selected " + inside("selected.txt"));
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const nlohmann::json report = cli(path("cloud.ply"), path("cli.ply"));
    const std::size_t dropped =
        cloud.size() - report.at("points").at("referenced").get<std::size_t>();
    EXPECT_GE(dropped, outliers);
    EXPECT_NE(
        r.out.find("HRsR: " + std::to_string(dropped) + " points not in the mesh are selected"),
        std::string::npos)
        << r.out;
    // selected: exactly the input points whose position is not a vertex of the mesh
    std::set<std::array<double, 3>> vertices;
    for (const Vec3& p : io::read_point_set(path("mesh.ply")).positions)
        vertices.insert({p[0], p[1], p[2]});
    std::set<std::size_t> expected, selected;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const Vec3& p = cloud.positions[i];
        if (!vertices.count({p[0], p[1], p[2]})) expected.insert(i);
    }
    std::ifstream in(path("selected.txt"));
    for (std::size_t i; in >> i;) selected.insert(i);
    EXPECT_EQ(selected.size(), dropped);
    EXPECT_EQ(selected, expected);
}

TEST_F(MeshLabRootFilter, MeshVerticesCarryTheLayersColourQualityRadiusAndTexCoord) {
    testing::write_sample_with_attributes(path("cloud.ply"));
    const Outcome r = apply("cloud.ply", "--attributes");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    cli(path("cloud.ply"), path("cli.ply"));
    const PointSet mesh = io::read_point_set(path("mesh.ply"));
    const PointSet cli = io::read_point_set(path("cli.ply"));
    ASSERT_GE(mesh.size(), 10000u) << r.out;
    testing::expect_vertex_values_as_cli(mesh, cli, testing::kLayerProperties);
    // the texture the coordinates refer to
    EXPECT_NE(slurp(path("mesh.ply")).find("comment TextureFile owl_texture.png\n"),
              std::string::npos);
}

TEST_F(MeshLabRootFilter, MeshVerticesCarryTheLayersCustomAttributes) {
    // a scalar and a point attribute made by MeshLab's own filters on the input layer: label =
    // 3 vi + 1 (saved as a PLY property) and offset = (vi, 2 vi + 1, -vi), read back on the mesh
    // into the quality as 4 x + 2 y + z = 7 vi + 2 (MeshLab saves points as PLY lists)
    testing::write_sample_with_attributes(path("cloud.ply"));
    const Outcome r =
        apply("cloud.ply", "--attributes --before compute_new_custom_scalar_attribute_per_vertex "
                           "'name=label;expr=3 * vi + 1' --before "
                           "compute_new_custom_point_attribute_per_vertex "
                           "'name=offset;x_expr=vi;y_expr=2 * vi + 1;z_expr=-vi' --after "
                           "compute_scalar_by_function_per_vertex "
                           "'q=4 * offset_x + 2 * offset_y + offset_z'");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.out.find("is not carried"), std::string::npos) << r.out;
    cli(path("cloud.ply"), path("cli.ply"));
    const PointSet mesh = io::read_point_set(path("mesh.ply"));
    const PointSet cli = io::read_point_set(path("cli.ply"));
    ASSERT_EQ(mesh.size(), cli.size());
    const PointAttribute* label = testing::attribute(mesh, "label");
    const PointAttribute* quality = testing::attribute(mesh, "quality");
    const PointAttribute* index = testing::attribute(cli, "index"); // the input point of vertex k
    ASSERT_TRUE(label && quality && index);
    std::size_t differ = 0;
    for (std::size_t k = 0; k < mesh.size(); ++k)
        differ += label->value(k) != 3 * index->value(k) + 1 ||
                  quality->value(k) != 7 * index->value(k) + 2;
    EXPECT_EQ(differ, 0u) << "of " << mesh.size() << " vertices";
}

TEST_F(MeshLabRootFilter, SixteenBitColourDoesNotReachMeshLab) {
    // MeshLab's PLY importer (vcglib's) reads red/green/blue as uchar only: a ushort colour (as
    // hrsr writes for 16-bit LAS colour) leaves the layer without colour. The README says so;
    // this fails when a MeshLab version starts reading it.
    testing::write_sample_with_ushort_colour(path("cloud.ply"));
    const Outcome r = apply("cloud.ply", "--attributes");
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    const PointSet mesh = io::read_point_set(path("mesh.ply"));
    ASSERT_GE(mesh.size(), 9000u);
    EXPECT_TRUE(mesh.attributes.empty()) << mesh.attributes.front().name;
}

TEST_F(MeshLabRootFilter, InstallPutsThePluginWhereThisMeshLabLoadsIt) {
    // a real install into the root (it is ours), removed again by the manifest
    const Outcome install = root_.run("cmake", "--install /hrsr/build");
    ASSERT_EQ(install.exit_code, 0) << install.out << install.err;
    const Outcome r = root_.host("--list", "-"); // the installed plugins only
    const Outcome uninstall =
        root_.run("sh", "-c 'xargs rm -v < /hrsr/build/install_manifest.txt'");
    EXPECT_EQ(uninstall.exit_code, 0) << uninstall.err;
    EXPECT_NE(uninstall.out.find("meshlab/plugins/libfilter_hrsr.so"), std::string::npos)
        << uninstall.out;
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_EQ(r.out.find("k\tRichInt\t"), 0u) << r.out;
}

} // namespace
} // namespace hrsr::testing
