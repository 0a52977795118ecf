// Topology at the defaults (issue 15, D-27, D-28): analytic surfaces sampled at two densities,
// clean and noisy, with exact normals or none, reconstructed by RsR and by HRsR at p = 0.5, 0.25
// and 0.125 with every other option at its default. Each output must be one closed, manifold,
// coherently oriented piece of the surface's genus with r_v ≥ 99.9 %. bench/topology.sh runs the
// whole grid (and CGAL beside it); this is the part that runs in every test run.
#include "fold_fates.h"
#include "io/mesh_reader.h"
#include "io/point_set_reader.h"
#include "mesh/mesh_stats.h"
#include "options.h"
#include "reconstruction.h"
#include "rsr/handles.h"
#include "samplers.h"
#include "vertex_normals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <tuple>

namespace hrsr {
namespace {

using testing::Density;

enum class Shape { Sphere, Torus, DoubleTorus, TripleTorus };

struct Cloud {
    const char* name;
    Shape shape;
    std::size_t points;
    Density density;
    double noise_percent; ///< σ of isotropic Gaussian noise, % of the bounding-box diagonal
    bool normals;         ///< exact normals given, or none (estimated by the pre-processing)
};

long genus_of(Shape s) {
    switch (s) {
    case Shape::Sphere:
        return 0;
    case Shape::Torus:
        return 1;
    case Shape::DoubleTorus:
        return 2;
    case Shape::TripleTorus:
        return 3;
    }
    return -1;
}

PointSet sample(const Cloud& c) {
    PointSet s;
    switch (c.shape) {
    case Shape::Sphere:
        s = testing::sample_sphere(c.points, 1.0, Vec3(0, 0, 0), c.density);
        break;
    case Shape::Torus:
        s = testing::sample_torus(c.points, 1.0, 0.35, c.density);
        break;
    case Shape::DoubleTorus:
        s = testing::sample_multi_torus(c.points, 2, c.density);
        break;
    case Shape::TripleTorus:
        s = testing::sample_multi_torus(c.points, 3, c.density);
        break;
    }
    testing::add_noise(s, c.noise_percent / 100.0 * testing::bounding_box_diagonal(s));
    return c.normals ? s : testing::without_normals(s);
}

struct Method {
    const char* name;
    double p; ///< 1 = RsR on the full cloud
};

/// The defaults, but for the method under test.
ReconstructionOptions defaults_for(const Method& method) {
    ReconstructionOptions options;
    if (method.p < 1)
        options.collapse.collapse_ratio = method.p;
    else
        options.method = hrsr::Method::Rsr;
    return options;
}

using GridCase = std::tuple<Cloud, Method>;

std::string grid_name(const ::testing::TestParamInfo<GridCase>& info) {
    const auto& [cloud, method] = info.param;
    return std::string(cloud.name) + "_" + method.name;
}

/// Manifold and coherently oriented.
void expect_manifold(const MeshStats& m) {
    EXPECT_EQ(m.non_manifold_edges, 0u);
    EXPECT_EQ(m.non_manifold_vertices, 0u);
    EXPECT_EQ(m.inconsistently_oriented_edges, 0u);
}

/// One closed manifold piece of the given genus with r_v ≥ 99.9 %.
void expect_closed_surface(const MeshStats& m, const ReconstructionReport& report, long genus) {
    expect_manifold(m);
    EXPECT_EQ(m.boundary_edges, 0u);
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_TRUE(m.components[0].closed());
    EXPECT_EQ(m.components[0].genus(), genus);
    EXPECT_GE(report.vertex_reference_ratio, 0.999);
}

class TopologyAtDefaults : public ::testing::TestWithParam<GridCase> {};

TEST_P(TopologyAtDefaults, ClosedManifoldOfTheSurfaceGenus) {
    const auto& [c, method] = GetParam();
    const ReconstructionOptions options = defaults_for(method);
    ReconstructionReport report;
    const Reconstruction r = reconstruct(sample(c), options, {}, report);
    expect_closed_surface(measure_mesh(r.vertex_input_index.size(), r.triangles), report,
                          genus_of(c.shape));
    // D-27: every component reports the hop limit it used; on the full cloud that is n itself.
    ASSERT_FALSE(report.handle_hop_limits.empty());
    if (method.p == 1) {
        EXPECT_EQ(report.handle_hop_limits[0], std::size_t(options.rsr.min_handle_loop));
    }
}

// D-27: n spacings of the input are n hops on the full cloud and n·sqrt(p) hops on a coarse
// cloud that keeps a fraction p of the points, never fewer than 4.
TEST(HandleHopLimit, ScalesWithTheSquareRootOfTheCollapseRatio) {
    EXPECT_EQ(rsr::handle_hop_limit(20, 4000, 4000), 20u);
    EXPECT_EQ(rsr::handle_hop_limit(20, 1250, 10000), 7u);  // 20 · sqrt(1/8) = 7.07
    EXPECT_EQ(rsr::handle_hop_limit(20, 2500, 10000), 10u); // p = 1/4
    EXPECT_EQ(rsr::handle_hop_limit(50, 5000, 10000), 35u); // 35.36
    EXPECT_EQ(rsr::handle_hop_limit(20, 10, 100000), 4u);   // the floor
    EXPECT_EQ(rsr::handle_hop_limit(20, 2000, 2000), 20u);
    EXPECT_EQ(rsr::handle_hop_limit(20, 1000, 500), 16u); // p = 1; D-29: 0.5 · sqrt(1000) = 15.8
}

// D-29: on a small surface the loop asked for is at most 0.5 · sqrt(points it stands for).
TEST(HandleHopLimit, IsCappedOnSmallSurfaces) {
    EXPECT_EQ(rsr::handle_hop_limit(20, 1600, 1600), 20u); // 0.5 · 40: where the cap starts
    EXPECT_EQ(rsr::handle_hop_limit(20, 315, 315), 9u);    // the eight: 8.87 spacings
    EXPECT_EQ(rsr::handle_hop_limit(20, 200, 315), 7u);    // 8.87 · sqrt(200 / 315) = 7.07
    EXPECT_EQ(rsr::handle_hop_limit(20, 50, 50), 4u);      // the floor
}

const Method kMethods[] = {{"Rsr", 1.0}, {"Half", 0.5}, {"Quarter", 0.25}, {"Eighth", 0.125}};

INSTANTIATE_TEST_SUITE_P(
    Analytic, TopologyAtDefaults,
    ::testing::Combine(
        ::testing::Values(
            Cloud{"Sphere_5k", Shape::Sphere, 5000, Density::Uniform, 0, true},
            Cloud{"Sphere_20k_Graded_Noise03_NoNormals", Shape::Sphere, 20000, Density::Graded, 0.3,
                  false},
            Cloud{"Sphere_5k_Noise03", Shape::Sphere, 5000, Density::Uniform, 0.3, true},
            Cloud{"Torus_5k", Shape::Torus, 5000, Density::Uniform, 0, true},
            Cloud{"Torus_20k_Graded_NoNormals", Shape::Torus, 20000, Density::Graded, 0, false},
            Cloud{"Torus_5k_Noise01_NoNormals", Shape::Torus, 5000, Density::Uniform, 0.1, false},
            Cloud{"DoubleTorus_5k_Graded", Shape::DoubleTorus, 5000, Density::Graded, 0, true},
            Cloud{"DoubleTorus_20k_Noise03", Shape::DoubleTorus, 20000, Density::Uniform, 0.3,
                  true},
            Cloud{"TripleTorus_5k_NoNormals", Shape::TripleTorus, 5000, Density::Uniform, 0, false},
            // D-38: at p = 1/4 its sparse end kept a 5-edge slit whose fans crossed the faces
            // folding over it (bench/topology.sh, session 17).
            Cloud{"TripleTorus_5k_Graded", Shape::TripleTorus, 5000, Density::Graded, 0, true},
            // D-39: RsR on its coarse cloud at p = 1/4 left a 5-edge hole that the re-expansion
            // widened to an 8-edge slit (bench/topology.sh, session 18).
            Cloud{"TripleTorus_5k_Graded_Noise01_NoNormals", Shape::TripleTorus, 5000,
                  Density::Graded, 0.1, false},
            // D-39: at p = 1/8 its coarse mesh had the genus and one 6-edge hole, beyond five
            // edges but shorter than a handle loop (bench/topology.sh, session 24).
            Cloud{"TripleTorus_5k_Noise01", Shape::TripleTorus, 5000, Density::Uniform, 0.1, true},
            // D-53: at p = 1/8 its coarse mesh had the genus and a 10-edge hole over sampled
            // surface, longer than D-39's pinholes; the re-expansion widened it to 26 edges
            // (bench/topology.sh, session 44).
            Cloud{"TripleTorus_5k_Graded_Noise01", Shape::TripleTorus, 5000, Density::Graded, 0.1,
                  true},
            Cloud{"TripleTorus_20k_Graded_Noise01", Shape::TripleTorus, 20000, Density::Graded, 0.1,
                  true},
            // D-47: at p = 1/8 its coarse cloud of 343 points lost the handle whose edges D-31
            // refuses (genus 2; bench/topology.sh, sessions 6–30); at least 500 coarse points now.
            Cloud{"TripleTorus_5k_Graded_Noise03", Shape::TripleTorus, 5000, Density::Graded, 0.3,
                  true},
            // D-45: at p = 1/4 a 9-edge coarse slit that
            // every fan crossed came out of the re-expansion as a 10-edge loop (session 27).
            Cloud{"DoubleTorus_5k_Noise03_NoNormals", Shape::DoubleTorus, 5000, Density::Uniform,
                  0.3, false}),
        ::testing::ValuesIn(kMethods)),
    grid_name);

// D-33: noise of one to two point spacings (at 1M points the grid's 0.3 % of the diagonal is
// about three). HRsR measures it and collapses and re-expands on smoothed positions: one closed
// piece of the right genus, r_v ≥ 99.9 %, and so few folds that none costs a point beyond 0.1 %
// (measured before D-33: sphere 18 boundary edges and 114 points dropped in folds, torus 6 and 33).
using NoisyCase = std::tuple<Cloud, Method>;
class NoiseBeyondTheSpacing : public ::testing::TestWithParam<NoisyCase> {};
TEST_P(NoiseBeyondTheSpacing, HrsrStillClosesTheSurface) {
    const auto& [c, method] = GetParam();
    ReconstructionOptions options;
    options.collapse.collapse_ratio = method.p;
    ReconstructionReport report;
    const Reconstruction r = reconstruct(sample(c), options, {}, report);
    EXPECT_TRUE(report.preprocess.denoised);
    EXPECT_GT(report.preprocess.relative_noise, constants::kNoisyCloud);
    expect_closed_surface(measure_mesh(r.vertex_input_index.size(), r.triangles), report,
                          genus_of(c.shape));
    EXPECT_EQ(report.fold_removal.pairs_after, 0u);
}
const Method kHrsrMethods[] = {{"Half", 0.5}, {"Quarter", 0.25}, {"Eighth", 0.125}};
INSTANTIATE_TEST_SUITE_P(
    Analytic, NoiseBeyondTheSpacing,
    ::testing::Combine(::testing::Values(Cloud{"Sphere_20k_Noise15", Shape::Sphere, 20000,
                                               Density::Uniform, 1.5, true},
                                         Cloud{"Torus_20k_Noise10", Shape::Torus, 20000,
                                               Density::Uniform, 1.0, true}),
                       ::testing::ValuesIn(kHrsrMethods)),
    grid_name);

// D-33 with input normals: noise moves points along the surface too, so the exact normals are
// the surface's where each point was sampled, not where it lies. Smoothed along them as given,
// this cloud folded in 3,187 triangle pairs and D-32 cut 15 points out; with them averaged
// first (averaged_normals()), 45 pairs and none.
TEST(NoisyCloudWithNormals, ExactNormalsAreAveragedBeforeSmoothing) {
    const Cloud c{
        "TripleTorus_50k_Noise07", Shape::TripleTorus, 50000, Density::Uniform, 0.7, true};
    ReconstructionReport report;
    const Reconstruction r = reconstruct(sample(c), ReconstructionOptions{}, {}, report);
    EXPECT_TRUE(report.preprocess.denoised);
    expect_closed_surface(measure_mesh(r.vertex_input_index.size(), r.triangles), report, 3);
    EXPECT_LT(report.fold_repair.pairs_before, 300u);
    EXPECT_TRUE(report.dropped_fold.empty());
}

// D-33 for RsR: the cloud is embedded along its normals' neighbourhood mean, but the vertices
// keep the input's normals (before session 15 RsR wrote the mean; HRsR always wrote the input's).
TEST(NoisyCloudWithNormals, RsrWritesTheInputNormals) {
    const Cloud c{"Sphere_20k_Noise03", Shape::Sphere, 20000, Density::Uniform, 0.3, true};
    const PointSet cloud = sample(c);
    ReconstructionOptions options;
    options.method = hrsr::Method::Rsr;
    ReconstructionReport report;
    const Reconstruction r = reconstruct(cloud, options, {}, report);
    ASSERT_TRUE(report.preprocess.denoised);
    ASSERT_EQ(report.flipped_components, 0u); // D-6 would turn the normals of a flipped piece
    ASSERT_FALSE(r.vertex_input_index.empty());
    for (std::size_t v = 0; v < r.vertex_input_index.size(); ++v) {
        const Vec3& n = cloud.normals[r.vertex_input_index[v]];
        ASSERT_EQ(r.vertex_normals[v], n / n.Norm()) << "vertex " << v;
    }
}

// ---------------------------------------------------------------------------------------------
// The known-topology models of ../shared/data/topology as bare point clouds (normals dropped),
// with both methods at the defaults.

struct Model {
    const char* file; ///< in topology/
    long genus;       ///< of the closed model, or −1 for a model with boundary
};

using ModelCase = std::tuple<Model, Method>;

std::string model_case_name(const ::testing::TestParamInfo<ModelCase>& info) {
    const auto& [model, method] = info.param;
    const std::string file = model.file;
    return file.substr(0, file.rfind('.')) + "_" + method.name;
}

/// The model's points without normals and its reconstruction; false when the data is absent.
bool reconstruct_model(const ModelCase& c, MeshStats& m, ReconstructionReport& report) {
    const auto& [model, method] = c;
    const std::filesystem::path path =
        std::filesystem::path(HRSR_SHARED_DATA) / "topology" / model.file;
    if (!std::filesystem::exists(path)) return false;
    const PointSet cloud = testing::without_normals(io::read_point_set(path.string()));
    const ReconstructionOptions options = defaults_for(method);
    const Reconstruction r = reconstruct(cloud, options, {}, report);
    m = measure_mesh(r.vertex_input_index.size(), r.triangles);
    return true;
}

class ClosedModelAtDefaults : public ::testing::TestWithParam<ModelCase> {};

TEST_P(ClosedModelAtDefaults, ClosedManifoldOfKnownGenus) {
    MeshStats m;
    ReconstructionReport report;
    if (!reconstruct_model(GetParam(), m, report)) GTEST_SKIP() << "shared data not available";
    expect_closed_surface(m, report, std::get<0>(GetParam()).genus);
}

INSTANTIATE_TEST_SUITE_P(
    SharedData, ClosedModelAtDefaults,
    ::testing::Combine(::testing::Values(Model{"rocker_arm_genus1.ply", 1},
                                         Model{"torus_genus1.ply", 1},
                                         Model{"3holes_genus3.ply", 3},
                                         Model{"fertility_genus4.ply", 4},
                                         Model{"kitten_points_genus1_normals.ply", 1},
                                         Model{"eight_genus2.ply", 2}),
                       ::testing::ValuesIn(kMethods)),
    model_case_name);

class ModelWithBoundaryAtDefaults : public ::testing::TestWithParam<ModelCase> {};

// Open surfaces of genus 0 stay open and gain no handle.
TEST_P(ModelWithBoundaryAtDefaults, OpenManifoldOfGenusZero) {
    MeshStats m;
    ReconstructionReport report;
    if (!reconstruct_model(GetParam(), m, report)) GTEST_SKIP() << "shared data not available";
    expect_manifold(m);
    const ComponentTopology* largest = largest_component(m);
    ASSERT_NE(largest, nullptr);
    EXPECT_GE(largest->boundary_loops, 1u);
    EXPECT_EQ(largest->genus(), 0);
    testing::expect_r_v(report, 0.999);
}

INSTANTIATE_TEST_SUITE_P(
    SharedData, ModelWithBoundaryAtDefaults,
    ::testing::Combine(::testing::Values(Model{"halftunnel_boundary3.ply", -1},
                                         Model{"mech_holes_shark_boundary4.ply", -1}),
                       ::testing::ValuesIn(kMethods)),
    model_case_name);

// A known gap of the camel head (docs/STATUS.md): at p = 0.25 it comes out with genus 2 (session
// 29: the coarse RsR's face split leaves two faces of 65 and 104 darts that both run around the
// head through the mouth, and the handle phase joins them; every edge of the coarse mesh whose
// ends are more than 12 hops apart on the model crosses the lips, 0.004–0.006 apart against a
// spacing of 0.012). At p = 0.125 (the default) it was known to fail too (r_v 99.69 %, session 7)
// and passes since (found in session 24). The cause (session 53, docs/BENCHMARKS.md): one lip's
// estimated normals are flipped, so the collapse merges the two lips; with the model's signs on
// the same directions p = 0.25 is genus 0.
INSTANTIATE_TEST_SUITE_P(SharedDataCamelHead, ModelWithBoundaryAtDefaults,
                         ::testing::Combine(::testing::Values(Model{"camelhead_boundary1.ply", -1}),
                                            ::testing::Values(Method{"Rsr", 1.0},
                                                              Method{"Half", 0.5},
                                                              Method{"Eighth", 0.125})),
                         model_case_name);

/// The vertices on the border of a triangle list (edges in exactly one triangle).
std::set<std::uint32_t> border_vertices(const std::vector<Triangle>& triangles) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (const Triangle& t : triangles)
        for (int i = 0; i < 3; ++i) ++uses[std::minmax(t[i], t[(i + 1) % 3])];
    std::set<std::uint32_t> border;
    for (const auto& [edge, count] : uses)
        if (count == 1) border.insert({edge.first, edge.second});
    return border;
}

// D-47: the half tunnel (831 points, 3 boundary loops) on HRsR's 200 coarse points came out with
// a 17-edge hole where the model has four triangles and no hole (20 of its 101 border vertices
// off the model's border), and without the model's 16-edge hole, 2 spacings across, that RsR
// also closes. Every border of the output now lies on the model's border.
class HalfTunnelAtDefaults : public ::testing::TestWithParam<Method> {};
TEST_P(HalfTunnelAtDefaults, NoHoleWhereTheModelHasNone) {
    const std::filesystem::path path =
        std::filesystem::path(HRSR_SHARED_DATA) / "topology" / "halftunnel_boundary3.ply";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data not available";
    const io::MeshFile model = io::read_mesh(path.string());
    const ReconstructionOptions options = defaults_for(GetParam());
    ReconstructionReport report;
    const Reconstruction r =
        reconstruct(testing::without_normals(model.points), options, {}, report);
    const MeshStats m = measure_mesh(r.vertex_input_index.size(), r.triangles);
    expect_manifold(m);
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_EQ(m.components[0].genus(), 0);
    EXPECT_GE(m.components[0].boundary_loops, 2u); // the tunnel's two ends
    const std::set<std::uint32_t> model_border = border_vertices(model.triangles);
    std::size_t off_the_model_border = 0;
    const std::set<std::uint32_t> border = border_vertices(r.triangles);
    for (std::uint32_t v : border)
        off_the_model_border += !model_border.count(std::uint32_t(r.vertex_input_index[v]));
    EXPECT_LE(double(off_the_model_border), 0.05 * double(border.size()));
    testing::expect_r_v(report, 0.999);
}
INSTANTIATE_TEST_SUITE_P(SharedData, HalfTunnelAtDefaults, ::testing::ValuesIn(kMethods),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// D-30: the shark's four holes stay open with both methods at every p (before, HRsR's ears on
// the coarse cloud closed one at p = 0.25 and two at p = 0.125).
class SharkAtDefaults : public ::testing::TestWithParam<Method> {};
TEST_P(SharkAtDefaults, KeepsItsFourHoles) {
    MeshStats m;
    ReconstructionReport report;
    if (!reconstruct_model({Model{"mech_holes_shark_boundary4.ply", -1}, GetParam()}, m, report))
        GTEST_SKIP() << "shared data not available";
    expect_manifold(m);
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_EQ(m.components[0].boundary_loops, 4u);
    EXPECT_EQ(m.components[0].genus(), 0);
    EXPECT_GE(report.vertex_reference_ratio, 0.999);
}
INSTANTIATE_TEST_SUITE_P(SharedData, SharkAtDefaults, ::testing::ValuesIn(kMethods),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// D-31: HRsR keeps RsR's genus on the feline (genus 2) at every p: a coarse handle edge never
// spans a gap that the input points leave open (before: genus 4 at p = 0.25, 3 at p = 0.125).
// Its wings, thinner than the point spacing, still leave holes (test_rsr.cpp,
// DISABLED_FelineIsClosedGenus2), so the assertion is on the largest piece.
class FelineAtDefaults : public ::testing::TestWithParam<Method> {};
TEST_P(FelineAtDefaults, LargestPieceHasGenus2) {
    MeshStats m;
    ReconstructionReport report;
    if (!reconstruct_model({Model{"feline_genus2.ply", 2}, GetParam()}, m, report))
        GTEST_SKIP() << "shared data not available";
    expect_manifold(m);
    const ComponentTopology* largest = largest_component(m);
    ASSERT_NE(largest, nullptr);
    EXPECT_EQ(largest->genus(), 2);
    EXPECT_GE(double(largest->faces), 0.99 * double(m.faces));
    EXPECT_LE(double(m.boundary_edges), 0.01 * double(m.edges));
    testing::expect_r_v(report, 0.995);
}
INSTANTIATE_TEST_SUITE_P(SharedData, FelineAtDefaults, ::testing::ValuesIn(kMethods),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

// D-35: three interlocked rings (GEL's reference mesh), 0.023 apart where they pass through each
// other, against a coarse spacing of about 0.06 at p = 1/8. Their coarse kNN graph joined them
// into one surface (genus 2 with 48 boundary edges at p = 1/8; at p = 1/4 a ring torn open, 294
// edges); the coarse pieces are now the input's. With the mesh's own normals: as estimated,
// two rings come out oriented inwards and touch the third (docs/STATUS.md).
class InterlockedRingsWithNormals : public ::testing::TestWithParam<Method> {};
TEST_P(InterlockedRingsWithNormals, ThreeClosedRingsOfGenusOne) {
    const std::filesystem::path path =
        std::filesystem::path(HRSR_SHARED_DATA) / "topology" / "rings_3x_genus1.ply";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared data not available";
    const io::MeshFile mesh = io::read_mesh(path.string());
    PointSet cloud = mesh.points; // outwards, as the mesh is wound
    cloud.normals = testing::area_weighted_vertex_normals(cloud.positions, mesh.triangles);
    const ReconstructionOptions options = defaults_for(GetParam());
    ReconstructionReport report;
    const Reconstruction r = reconstruct(cloud, options, {}, report);
    const MeshStats m = measure_mesh(r.vertex_input_index.size(), r.triangles);
    expect_manifold(m);
    EXPECT_EQ(m.boundary_edges, 0u);
    ASSERT_EQ(m.components.size(), 3u);
    for (const ComponentTopology& c : m.components) {
        EXPECT_TRUE(c.closed());
        EXPECT_EQ(c.genus(), 1);
    }
    testing::expect_r_v(report, 0.999);
}
INSTANTIATE_TEST_SUITE_P(SharedData, InterlockedRingsWithNormals, ::testing::ValuesIn(kMethods),
                         [](const auto& param_info) { return std::string(param_info.param.name); });

class ModelWithBoundaryAtDefaultsKnownFailure : public ModelWithBoundaryAtDefaults {};
TEST_P(ModelWithBoundaryAtDefaultsKnownFailure, DISABLED_OpenManifoldOfGenusZero) {
    MeshStats m;
    ReconstructionReport report;
    if (!reconstruct_model(GetParam(), m, report)) GTEST_SKIP() << "shared data not available";
    const ComponentTopology* largest = largest_component(m);
    ASSERT_NE(largest, nullptr);
    EXPECT_EQ(largest->genus(), 0);
    testing::expect_r_v(report, 0.999);
}
INSTANTIATE_TEST_SUITE_P(SharedDataCamelHead, ModelWithBoundaryAtDefaultsKnownFailure,
                         ::testing::Combine(::testing::Values(Model{"camelhead_boundary1.ply", -1}),
                                            ::testing::Values(Method{"Quarter", 0.25})),
                         model_case_name);

} // namespace
} // namespace hrsr
