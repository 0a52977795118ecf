// Rotation System Reconstruction (ALGORITHM.md §5) through its entry point, against the
// invariants and testable properties of §13: topology of analytic surfaces sampled with exact
// normals, the invariants seen by an observer at every insertion, self-intersections (vcglib),
// known-topology models of the shared data, determinism across thread counts and the accounting
// of every input point.
#include "fold_fates.h"
#include "io/point_set_reader.h"
#include "mesh/mesh_stats.h"
#include "preprocess/preprocess.h"
#include "reconstruction_observed.h"
#include "rsr/reconstruct_component.h"
#include "rsr_invariants.h"
#include "samplers.h"
#include "vcg_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace hrsr {
namespace {

using testing::Density;

struct Result {
    Reconstruction mesh;
    ReconstructionReport report;
    MeshStats stats; ///< measured here on the returned mesh, not taken from the report
};

/// The defaults, with a genus limit when asked (§5.9).
RsrOptions rsr_options(int handles = -1) {
    RsrOptions o;
    o.handles = handles;
    return o;
}

Result reconstruct(const PointSet& cloud, const RsrOptions& options, int threads = 0,
                   rsr::Observer* observer = nullptr) {
    Result r;
    Execution exec;
    exec.threads = threads;
    r.mesh = reconstruct_rsr(cloud, options, exec, r.report, observer);
    r.stats = measure_mesh(r.mesh.vertex_input_index.size(), r.mesh.triangles);
    return r;
}

/// What every RsR output must be (§13 items 5, 6): edge- and vertex-manifold, consistently
/// oriented, no degenerate or unreferenced element, unit normals; and the report's figures are
/// those of the mesh returned.
void expect_manifold(const Result& r) {
    const MeshStats& m = r.stats;
    EXPECT_GT(m.faces, 0u);
    EXPECT_EQ(m.non_manifold_edges, 0u);
    EXPECT_EQ(m.non_manifold_vertices, 0u);
    EXPECT_EQ(m.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(m.degenerate_faces, 0u);
    EXPECT_EQ(m.unreferenced_vertices, 0u);
    ASSERT_EQ(r.mesh.vertex_normals.size(), r.mesh.vertex_input_index.size());
    std::size_t not_unit = 0;
    for (const Vec3& n : r.mesh.vertex_normals)
        if (!(std::abs(n.Norm() - 1.0) < 1e-9)) ++not_unit;
    EXPECT_EQ(not_unit, 0u);
    const MeshStats& reported = r.report.mesh;
    EXPECT_EQ(reported.vertices, m.vertices);
    EXPECT_EQ(reported.faces, m.faces);
    EXPECT_EQ(reported.boundary_edges, m.boundary_edges);
    EXPECT_EQ(reported.boundary_loops, m.boundary_loops);
    EXPECT_EQ(reported.non_manifold_edges, m.non_manifold_edges);
    EXPECT_EQ(reported.non_manifold_vertices, m.non_manifold_vertices);
    EXPECT_EQ(reported.components.size(), m.components.size());
}

/// A closed, connected output of the given genus with (nearly) every input point a vertex.
void expect_closed_surface(const Result& r, long genus) {
    expect_manifold(r);
    const MeshStats& m = r.stats;
    EXPECT_EQ(m.boundary_edges, 0u);
    EXPECT_EQ(m.boundary_loops, 0u);
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_TRUE(m.components[0].closed());
    EXPECT_EQ(m.components[0].genus(), genus);
    EXPECT_EQ(r.report.handles, std::size_t(genus)); // D-11: one handle per unit of genus
    EXPECT_GE(r.report.vertex_reference_ratio, 0.999);
}

/// Triangles not wound counter-clockwise seen from their vertices' normals (§5.3).
std::size_t triangles_against_normals(const PointSet& input, const Result& r) {
    std::size_t count = 0;
    for (const Triangle& t : r.mesh.triangles) {
        const Vec3& a = input.positions[r.mesh.vertex_input_index[t[0]]];
        const Vec3& b = input.positions[r.mesh.vertex_input_index[t[1]]];
        const Vec3& c = input.positions[r.mesh.vertex_input_index[t[2]]];
        const Vec3 normals =
            r.mesh.vertex_normals[t[0]] + r.mesh.vertex_normals[t[1]] + r.mesh.vertex_normals[t[2]];
        if (!(((b - a) ^ (c - a)).dot(normals) > 0)) ++count;
    }
    return count;
}

// ---------------------------------------------------------------------------------------------
// Analytic surfaces with exact normals, reconstructed at the defaults. D-27: n counts point
// spacings of the input, and every loop around a tube here is longer than the default 20: at 5k
// points the torus tube (2π · 0.35) is about 40 spacings around, and about 13 where a graded
// sample is sparsest (a tenth of the density), which is why the graded cases are 20k and more.
// The sphere has no handle to find: spurious handles would show as genus.

enum class Shape { Sphere, Torus, DoubleTorus, TripleTorus };

struct SurfaceCase {
    const char* name;
    Shape shape;
    std::size_t points; ///< asked of the sampler
    Density density;
    long genus;
};

PointSet sample(const SurfaceCase& c) {
    switch (c.shape) {
    case Shape::Sphere:
        return testing::sample_sphere(c.points, 1.0, Vec3(0, 0, 0), c.density);
    case Shape::Torus:
        return testing::sample_torus(c.points, 1.0, 0.35, c.density);
    case Shape::DoubleTorus:
        return testing::sample_double_torus(c.points, c.density);
    case Shape::TripleTorus:
        return testing::sample_multi_torus(c.points, 3, c.density);
    }
    return {};
}

void PrintTo(const SurfaceCase& c, std::ostream* os) {
    *os << c.name;
}

std::string case_name(const ::testing::TestParamInfo<SurfaceCase>& info) {
    return info.param.name;
}

class RsrSurface : public ::testing::TestWithParam<SurfaceCase> {};

// §13 items 6, 14, 15: closed, manifold, consistently oriented, exact genus, r_v ≥ 99.9 %.
TEST_P(RsrSurface, ClosedManifoldOfExactGenus) {
    const SurfaceCase& c = GetParam();
    const PointSet cloud = sample(c);
    const Result r = reconstruct(cloud, rsr_options());
    expect_closed_surface(r, c.genus);
    EXPECT_EQ(r.stats.vertices, cloud.size()); // exact normals: every point is a vertex
    EXPECT_EQ(r.report.vertex_copies, 0u);
    // Outward (D-6): the output normals are the exact outward normals, and the triangles wind
    // counter-clockwise around them.
    std::size_t turned = 0;
    for (std::size_t v = 0; v < r.mesh.vertex_normals.size(); ++v)
        if (!(r.mesh.vertex_normals[v].dot(cloud.normals[r.mesh.vertex_input_index[v]]) > 0.999))
            ++turned;
    EXPECT_EQ(turned, 0u);
    EXPECT_EQ(triangles_against_normals(cloud, r), 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Analytic, RsrSurface,
    ::testing::Values(
        SurfaceCase{"Sphere_Uniform_10k", Shape::Sphere, 10000, Density::Uniform, 0},
        SurfaceCase{"Sphere_Graded_20k", Shape::Sphere, 20000, Density::Graded, 0},
        SurfaceCase{"Torus_Uniform_5k", Shape::Torus, 5000, Density::Uniform, 1},
        SurfaceCase{"Torus_Uniform_10k", Shape::Torus, 10000, Density::Uniform, 1},
        SurfaceCase{"Torus_Graded_20k", Shape::Torus, 20000, Density::Graded, 1},
        SurfaceCase{"Torus_Graded_50k", Shape::Torus, 50000, Density::Graded, 1},
        SurfaceCase{"Torus_Uniform_100k", Shape::Torus, 100000, Density::Uniform, 1},
        SurfaceCase{"DoubleTorus_Uniform_20k", Shape::DoubleTorus, 20000, Density::Uniform, 2},
        SurfaceCase{"DoubleTorus_Graded_40k", Shape::DoubleTorus, 40000, Density::Graded, 2},
        // At 5k one triangle D-23 closed at a junction wound against its vertices' normals until
        // some session before 44 (docs/ALGORITHM.md, D-23).
        SurfaceCase{"TripleTorus_Uniform_5k", Shape::TripleTorus, 5000, Density::Uniform, 3},
        SurfaceCase{"TripleTorus_Uniform_10k", Shape::TripleTorus, 10000, Density::Uniform, 3},
        // D-52: a concave quad closed by D-23 across its outside, one of its triangles winding
        // against its vertices' normals.
        SurfaceCase{"TripleTorus_Graded_30k", Shape::TripleTorus, 30000, Density::Graded, 3}),
    case_name);

class RsrSurfaceWithoutHandles : public ::testing::TestWithParam<SurfaceCase> {};

// §5.9 / §13 item 14: handles = 0 forces genus 0; a surface of higher genus is then cut open.
TEST_P(RsrSurfaceWithoutHandles, GenusZeroWithBoundary) {
    const SurfaceCase& c = GetParam();
    const PointSet cloud = sample(c);
    const Result r = reconstruct(cloud, rsr_options(0));
    expect_manifold(r);
    const MeshStats& m = r.stats;
    EXPECT_EQ(r.report.handles, 0u);
    EXPECT_EQ(r.report.handle_edges, 0u);
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_EQ(m.components[0].genus(), 0);
    EXPECT_FALSE(m.components[0].closed());
    EXPECT_GT(m.boundary_edges, 0u);
    EXPECT_GE(r.report.vertex_reference_ratio, 0.999);
}

INSTANTIATE_TEST_SUITE_P(
    Analytic, RsrSurfaceWithoutHandles,
    ::testing::Values(
        SurfaceCase{"Torus_Uniform_10k", Shape::Torus, 10000, Density::Uniform, 1},
        SurfaceCase{"Torus_Graded_20k", Shape::Torus, 20000, Density::Graded, 1},
        SurfaceCase{"DoubleTorus_Uniform_20k", Shape::DoubleTorus, 20000, Density::Uniform, 2},
        SurfaceCase{"DoubleTorus_Graded_40k", Shape::DoubleTorus, 40000, Density::Graded, 2}),
    case_name);

// ---------------------------------------------------------------------------------------------
// Invariants at every insertion (§13 items 2–4), on inputs of at most 20k points.

struct InvariantCase {
    SurfaceCase surface;
    int handles; ///< −1 or 0
};

void PrintTo(const InvariantCase& c, std::ostream* os) {
    PrintTo(c.surface, os);
    *os << ", handles = " << c.handles;
}

std::string invariant_case_name(const ::testing::TestParamInfo<InvariantCase>& info) {
    return std::string(info.param.surface.name) +
           (info.param.handles == 0 ? "_NoHandles" : "_AutoHandles");
}

/// The invariant checker, also counting insertions per phase and the face-split insertions
/// after which χ is not 2.
class PhaseChecker : public testing::InvariantChecker {
public:
    using InvariantChecker::InvariantChecker;
    void edge_inserted(rsr::Phase phase, std::uint32_t u, std::uint32_t v,
                       const rsr::RotationSystem& rs, const rsr::Faces& faces,
                       const std::vector<rsr::LocalTriangle>& triangles,
                       std::size_t new_triangles) override {
        InvariantChecker::edge_inserted(phase, u, v, rs, faces, triangles, new_triangles);
        ++insertions[std::size_t(phase)];
        if (phase == rsr::Phase::FaceSplit && euler() != 2) ++face_split_euler_not_two;
    }
    std::array<std::size_t, 3> insertions{}; ///< by rsr::Phase
    std::size_t face_split_euler_not_two = 0;
};

class RsrInvariants : public ::testing::TestWithParam<InvariantCase> {};

// χ = 2 after every face-split (and ear) insertion, face labels traced from scratch every 1000
// insertions, every recorded triangle a face; each handle merge lowers χ by 2, and the handles
// counted by the checker, reported by RsR and seen as genus in the closed output agree.
TEST_P(RsrInvariants, EulerCharacteristicAndHandleAccounting) {
    const InvariantCase& c = GetParam();
    PhaseChecker checker(1000);
    const Result r = reconstruct(sample(c.surface), rsr_options(c.handles), 0, &checker);
    expect_manifold(r);
    const MeshStats& m = r.stats;
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_GT(checker.insertions[std::size_t(rsr::Phase::FaceSplit)], m.vertices);
    EXPECT_EQ(checker.face_split_euler_not_two, 0u);
    EXPECT_EQ(checker.merges(), r.report.handles);
    EXPECT_EQ(checker.insertions[std::size_t(rsr::Phase::Handles)], r.report.handle_edges);
    if (c.handles == 0) {
        EXPECT_EQ(checker.merges(), 0u);
        EXPECT_EQ(checker.euler(), 2);
        EXPECT_EQ(m.components[0].genus(), 0);
    } else {
        ASSERT_TRUE(m.components[0].closed());
        EXPECT_EQ(m.components[0].genus(), c.surface.genus);
        EXPECT_EQ(long(r.report.handles), m.components[0].genus());
        EXPECT_EQ(checker.euler(), 2 - 2 * c.surface.genus);
    }
}

// §13 item 6, geometrically: vcglib finds no pair of intersecting triangles (pairs sharing an
// edge are not tested by vcglib). The same outputs, cross-checked with vcglib's topology tools.
TEST_P(RsrInvariants, NoSelfIntersections) {
    const InvariantCase& c = GetParam();
    const PointSet cloud = sample(c.surface);
    const Result r = reconstruct(cloud, rsr_options(c.handles));
    testing::VcgMesh m;
    testing::build_vcg_mesh(cloud, r.mesh, m);
    EXPECT_EQ(testing::self_intersecting_faces(m).size(), 0u);
    // Not CountNonManifoldEdgeFF: it never frees the three face user bits it takes (vcglib
    // 2020.09), and once they run out SelfIntersections' bookkeeping reports pairs twice.
    using Clean = vcg::tri::Clean<testing::VcgMesh>;
    int edges = 0, boundary_edges = 0, non_manifold_edges = 0;
    Clean::CountEdgeNum(m, edges, boundary_edges, non_manifold_edges);
    EXPECT_EQ(non_manifold_edges, 0);
    EXPECT_EQ(std::size_t(boundary_edges), r.stats.boundary_edges);
    EXPECT_EQ(Clean::CountNonManifoldVertexFF(m, false), 0);
    EXPECT_TRUE(Clean::IsCoherentlyOrientedMesh(m));
    EXPECT_EQ(Clean::CountConnectedComponents(m), 1);
    EXPECT_EQ(Clean::MeshGenus(m), c.handles == 0 ? 0 : c.surface.genus);
}

INSTANTIATE_TEST_SUITE_P(
    Analytic, RsrInvariants,
    ::testing::Values(
        InvariantCase{{"Sphere_Uniform_10k", Shape::Sphere, 10000, Density::Uniform, 0}, -1},
        InvariantCase{{"Torus_Graded_10k", Shape::Torus, 10000, Density::Graded, 1}, -1},
        InvariantCase{{"Torus_Uniform_10k", Shape::Torus, 10000, Density::Uniform, 1}, 0},
        InvariantCase{{"DoubleTorus_Uniform_15k", Shape::DoubleTorus, 15000, Density::Uniform, 2},
                      -1},
        InvariantCase{{"DoubleTorus_Graded_20k", Shape::DoubleTorus, 20000, Density::Graded, 2},
                      -1},
        InvariantCase{{"DoubleTorus_Uniform_10k", Shape::DoubleTorus, 10000, Density::Uniform, 2},
                      0}),
    invariant_case_name);

// The component stage alone on a small sphere, every insertion checked in full every 50.
TEST(RsrComponent, SphereIsAClosedGenusZeroManifold) {
    RsrOptions o;
    testing::InvariantChecker checker(50);
    PreprocessReport report;
    const PreparedCloud c = preprocess(testing::sample_sphere(3000), o.preprocess, {}, report);
    ASSERT_EQ(report.components_kept, 1u);
    rsr::ComponentStats stats;
    const auto local = rsr::reconstruct_component(
        {c.positions, c.smoothed, c.normals, c.size(), {}, {}}, o, {}, stats, &checker);
    const std::vector<Triangle> triangles(local.begin(), local.end());
    const MeshStats m = measure_mesh(c.size(), triangles);
    EXPECT_EQ(m.non_manifold_edges, 0u);
    EXPECT_EQ(m.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(m.degenerate_faces, 0u);
    EXPECT_EQ(m.boundary_edges, 0u);
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_EQ(m.components[0].genus(), 0);
    EXPECT_EQ(m.vertices, c.size());
    EXPECT_EQ(checker.euler(), 2);
}

// ---------------------------------------------------------------------------------------------
// Known-topology models of ../shared/data/topology, used as point clouds: vertices only, no
// normals (the reader ignores faces), at the defaults.

std::string shared(const std::string& relative) {
    const std::filesystem::path p = std::filesystem::path(HRSR_SHARED_DATA) / relative;
    return std::filesystem::exists(p) ? p.string() : std::string();
}

struct ModelCase {
    const char* file; ///< in topology/
    long genus;       ///< of the closed model, or −1 for a model with boundary
};

void PrintTo(const ModelCase& c, std::ostream* os) {
    *os << c.file;
}

std::string model_name(const ::testing::TestParamInfo<ModelCase>& info) {
    const std::string file = info.param.file;
    return file.substr(0, file.rfind('.'));
}

/// Reads a model as a point cloud and reconstructs it at the defaults; false if it is absent.
bool reconstruct_model(const std::string& file, PointSet& cloud, Result& r) {
    const std::string path = shared("topology/" + file);
    if (path.empty()) return false;
    cloud = io::read_point_set(path);
    EXPECT_FALSE(cloud.has_normals()) << file;
    r = reconstruct(cloud, rsr_options());
    return true;
}

void expect_closed_model(const std::string& file, long genus) {
    PointSet cloud;
    Result r;
    if (!reconstruct_model(file, cloud, r)) {
        GTEST_SKIP() << "shared data not available";
    }
    expect_closed_surface(r, genus);
    testing::VcgMesh m;
    testing::build_vcg_mesh(cloud, r.mesh, m);
    EXPECT_EQ(testing::self_intersecting_faces(m).size(), 0u);
}

class RsrClosedModel : public ::testing::TestWithParam<ModelCase> {};

TEST_P(RsrClosedModel, ClosedManifoldOfKnownGenus) {
    expect_closed_model(GetParam().file, GetParam().genus);
}

INSTANTIATE_TEST_SUITE_P(SharedData, RsrClosedModel,
                         ::testing::Values(ModelCase{"rocker_arm_genus1.ply", 1},
                                           ModelCase{"torus_genus1.ply", 1},
                                           ModelCase{"fertility_genus4.ply", 4},
                                           ModelCase{"3holes_genus3.ply", 3}),
                         model_name);

// The feline's wings and tail are 2–3 units thick against a median vertex spacing of 1.6 (and
// its vertices include near-coincident pairs): there the estimated normals flip in patches and
// the rotation folds, so RsR leaves holes (docs/STATUS.md, known gap 1). Its topology is still
// right: the surface has genus 2 once the holes are counted as boundary loops (χ = 2 − 2g − b).
// Measured at n = 20: 40,654 of 40,751 triangles in one piece, 653 of 61,453 edges on holes.
TEST(RsrModelOfKnownGenusWithHoles, FelineIsOnePieceOfGenus2) {
    PointSet cloud;
    Result r;
    if (!reconstruct_model("feline_genus2.ply", cloud, r)) {
        GTEST_SKIP() << "shared data not available";
    }
    expect_manifold(r);
    const ComponentTopology* largest = largest_component(r.stats);
    ASSERT_NE(largest, nullptr);
    EXPECT_EQ(largest->genus(), 2);
    EXPECT_GE(double(largest->faces), 0.99 * double(r.stats.faces));
    EXPECT_LE(double(r.stats.boundary_edges), 0.02 * double(r.stats.edges));
    EXPECT_GE(r.report.vertex_reference_ratio, 0.995);
}

// The target the test above stops short of; enable when the thin parts close.
TEST(RsrClosedModelKnownFailure, DISABLED_FelineIsClosedGenus2) {
    expect_closed_model("feline_genus2.ply", 2);
}

class RsrModelWithBoundary : public ::testing::TestWithParam<ModelCase> {};

TEST_P(RsrModelWithBoundary, ManifoldWithBoundary) {
    PointSet cloud;
    Result r;
    if (!reconstruct_model(GetParam().file, cloud, r)) {
        GTEST_SKIP() << "shared data not available";
    }
    expect_manifold(r);
    EXPECT_GE(r.stats.boundary_loops, 1u);
    testing::expect_r_v(r.report, 0.999);
}

INSTANTIATE_TEST_SUITE_P(SharedData, RsrModelWithBoundary,
                         ::testing::Values(ModelCase{"camelhead_boundary1.ply", -1},
                                           ModelCase{"halftunnel_boundary3.ply", -1},
                                           ModelCase{"mech_holes_shark_boundary4.ply", -1}),
                         model_name);

// ---------------------------------------------------------------------------------------------
// Determinism (§13 item 11).

PointSet translated(PointSet s, const Vec3& by) {
    for (Vec3& p : s.positions) p += by;
    return s;
}

// Several components under 20000 points, which run side by side with more than one thread: a
// sphere, a torus far from it, a small (150-point) sphere, and a 20-point cluster (dropped).
TEST(RsrDeterminism, SameMeshForOneAndTwoThreads) {
    PointSet cloud = testing::sample_sphere(8000, 1.0, Vec3(0, 0, 0), Density::Graded);
    testing::append(cloud, translated(testing::sample_torus(10000, 1.0, 0.35, Density::Uniform, 7),
                                      Vec3(10, 0, 0)));
    testing::append(cloud, testing::sample_sphere(150, 0.05, Vec3(0, 10, 0), Density::Uniform, 8));
    testing::append(cloud, testing::sample_sphere(20, 0.01, Vec3(0, 0, 10), Density::Uniform, 9));
    const RsrOptions options = rsr_options();
    const Result one = reconstruct(cloud, options, 1);
    const Result two = reconstruct(cloud, options, 2);
    ASSERT_EQ(one.report.preprocess.components_kept, 3u);
    ASSERT_EQ(one.stats.components.size(), 3u);
    EXPECT_EQ(one.report.preprocess.count(PointFate::SmallComponent), 20u);

    EXPECT_EQ(one.mesh.vertex_input_index, two.mesh.vertex_input_index);
    EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
    ASSERT_EQ(one.mesh.vertex_normals.size(), two.mesh.vertex_normals.size());
    std::size_t different_normals = 0;
    for (std::size_t v = 0; v < one.mesh.vertex_normals.size(); ++v)
        for (int k = 0; k < 3; ++k)
            if (std::memcmp(&one.mesh.vertex_normals[v][k], &two.mesh.vertex_normals[v][k],
                            sizeof(double)) != 0)
                ++different_normals;
    EXPECT_EQ(different_normals, 0u); // bit-identical
    EXPECT_EQ(one.report.handles, two.report.handles);
    EXPECT_EQ(one.report.not_in_triangle, two.report.not_in_triangle);
    EXPECT_EQ(one.report.referenced_input_points, two.report.referenced_input_points);
}

// ---------------------------------------------------------------------------------------------
// Accounting (§13 item 10): every input point is referenced by an output vertex (directly, or
// as a duplicate merged into one, D-3) or dropped for exactly one reason.

void expect_accounted(const PointSet& input, const Result& r) {
    const ReconstructionReport& report = r.report;
    const PreprocessReport& pre = report.preprocess;
    const std::size_t n = input.size();
    ASSERT_EQ(pre.input_points, n);
    ASSERT_EQ(pre.fate.size(), n);
    ASSERT_EQ(pre.duplicate_of.size(), n);

    // Our own count of the referenced points, from the mesh.
    std::vector<bool> is_vertex(n, false), not_in_triangle(n, false);
    for (std::uint32_t i : r.mesh.vertex_input_index) {
        ASSERT_LT(i, n);
        is_vertex[i] = true;
    }
    for (std::uint32_t i : report.not_in_triangle) {
        ASSERT_LT(i, n);
        not_in_triangle[i] = true;
    }
    for (std::uint32_t i : report.dropped_fold) { // D-32: never a vertex, never listed twice
        ASSERT_LT(i, n);
        EXPECT_FALSE(is_vertex[i] || not_in_triangle[i]) << i;
    }
    std::size_t referenced = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const bool merged = pre.fate[i] == PointFate::Duplicate && is_vertex[pre.duplicate_of[i]];
        if (is_vertex[i] || merged) ++referenced;
        // A point is never both a vertex and dropped.
        if (is_vertex[i]) {
            EXPECT_EQ(pre.fate[i], PointFate::Kept) << i;
            EXPECT_FALSE(not_in_triangle[i]) << i;
        }
        // Listed: a kept point, or a duplicate of a listed point (it shares that point's fate).
        if (not_in_triangle[i]) {
            EXPECT_TRUE(pre.fate[i] == PointFate::Kept || (pre.fate[i] == PointFate::Duplicate &&
                                                           not_in_triangle[pre.duplicate_of[i]]))
                << i;
        }
    }
    EXPECT_EQ(report.referenced_input_points, referenced);
    const std::size_t dropped =
        pre.count(PointFate::NonFinite) + pre.count(PointFate::SmallComponent) +
        pre.count(PointFate::NoNormal) + report.not_in_triangle.size() + report.dropped_fold.size();
    EXPECT_EQ(report.referenced_input_points + dropped, n)
        << "referenced " << report.referenced_input_points << ", non-finite "
        << pre.count(PointFate::NonFinite) << ", small component "
        << pre.count(PointFate::SmallComponent) << ", no normal " << pre.count(PointFate::NoNormal)
        << ", not in any triangle " << report.not_in_triangle.size() << ", in folds "
        << report.dropped_fold.size() << ", merged duplicates " << pre.count(PointFate::Duplicate);
    EXPECT_EQ(report.vertex_reference_ratio, double(referenced) / double(n));
}

/// Appends an exact copy (position and normal) of point i.
void append_copy(PointSet& s, std::size_t i) {
    s.positions.push_back(s.positions[i]);
    if (s.has_normals()) s.normals.push_back(s.normals[i]);
}

TEST(RsrAccounting, EveryInputPointIsReferencedOrDroppedForOneReason) {
    PointSet cloud = testing::sample_sphere(5000);
    // A far cluster of 12 points: dropped as a small component (§4.6).
    testing::append(cloud, testing::sample_sphere(12, 0.01, Vec3(20, 0, 0), Density::Uniform, 5));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i < 3; ++i) {
        cloud.positions.emplace_back(nan, double(i), 0.0);
        cloud.normals.emplace_back(0, 0, 1);
    }
    cloud.positions.emplace_back(std::numeric_limits<double>::infinity(), 0.0, 0.0);
    cloud.normals.emplace_back(0, 0, 1);
    for (std::size_t i : {0, 17, 17, 4999}) append_copy(cloud, i); // merged into sphere points
    for (std::size_t i : {5000, 5011}) append_copy(cloud, i);      // merged into dropped points
    const Result r = reconstruct(cloud, rsr_options());
    const PreprocessReport& pre = r.report.preprocess;
    EXPECT_EQ(pre.count(PointFate::NonFinite), 4u);
    EXPECT_EQ(pre.count(PointFate::SmallComponent), 14u);
    EXPECT_EQ(pre.count(PointFate::Duplicate), 4u);
    EXPECT_EQ(r.report.referenced_input_points, 5004u);
    expect_accounted(cloud, r);
}

// Duplicates of points that RsR left out of every triangle are not referenced either: they
// must be counted as dropped. RsR leaves 9 of the feline's points out (session 24; the camel
// head, used before, has none left out since): with none the test has no case and fails.
TEST(RsrAccounting, DuplicatesOfPointsInNoTriangleAreDropped) {
    PointSet cloud;
    Result first;
    if (!reconstruct_model("feline_genus2.ply", cloud, first)) {
        GTEST_SKIP() << "shared data not available";
    }
    ASSERT_FALSE(first.report.not_in_triangle.empty())
        << "every feline point is in a triangle: find another cloud that leaves points out";
    expect_accounted(cloud, first);
    const std::size_t n = cloud.size();
    for (std::uint32_t i : first.report.not_in_triangle) append_copy(cloud, i);
    append_copy(cloud, first.mesh.vertex_input_index.front());
    const Result r = reconstruct(cloud, rsr_options());
    // Duplicates are merged before anything else: the same mesh over the same points, and each
    // copy of a point in no triangle is listed under the same reason as that point.
    ASSERT_EQ(r.mesh.vertex_input_index, first.mesh.vertex_input_index);
    std::vector<std::uint32_t> expected = first.report.not_in_triangle;
    for (std::size_t k = 0; k < first.report.not_in_triangle.size(); ++k)
        expected.push_back(std::uint32_t(n + k));
    ASSERT_EQ(r.report.not_in_triangle, expected);
    EXPECT_EQ(r.report.preprocess.count(PointFate::Duplicate), cloud.size() - n);
    expect_accounted(cloud, r);
}

} // namespace
} // namespace hrsr
