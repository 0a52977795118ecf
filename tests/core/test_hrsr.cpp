// HRsR: collapse → RsR → re-expansion (ALGORITHM.md §6–8, §13 items 8–11).
#include "errors.h"
#include "hrsr/crossings.h"
#include "reconstruction_observed.h"
#include "samplers.h"
#include "vcg_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace hrsr {
namespace {

// After every split: χ unchanged; (V, E, F) grew by exactly (1, 3, 2) minus the boundary
// triangles removed for it; genus of the closed mesh unchanged; no crossing left.
class SplitChecker : public ReexpansionObserver {
public:
    explicit SplitChecker(std::size_t full_check_every) : every_(full_check_every) {}
    void split_done(const SplitMesh& mesh, std::uint32_t, std::uint32_t, const Vec3&, const Vec3&,
                    std::size_t removed, bool unresolved) override {
        ++splits_;
        unresolved_ += unresolved ? 1 : 0;
        removed_ += removed;
        if (splits_ % every_ != 0) return;
        const MeshStats s = measure_mesh(mesh.vertex_count(), mesh.triangles());
        if (have_previous_) {
            const long splits = long(splits_ - previous_splits_),
                       gone = long(removed_ - previous_removed_);
            EXPECT_EQ(long(s.vertices), long(previous_.vertices) + splits);
            EXPECT_EQ(long(s.edges), long(previous_.edges) + 3 * splits - gone);
            EXPECT_EQ(long(s.faces), long(previous_.faces) + 2 * splits - gone);
            EXPECT_EQ(s.euler(), previous_.euler());
        }
        EXPECT_EQ(s.non_manifold_edges, 0u);
        EXPECT_EQ(s.non_manifold_vertices, 0u);
        EXPECT_EQ(s.inconsistently_oriented_edges, 0u);
        previous_ = s;
        previous_splits_ = splits_;
        previous_removed_ = removed_;
        have_previous_ = true;
    }
    std::size_t splits() const { return splits_; }
    std::size_t unresolved() const { return unresolved_; }

private:
    std::size_t every_, splits_ = 0, unresolved_ = 0, removed_ = 0;
    std::size_t previous_splits_ = 0, previous_removed_ = 0;
    MeshStats previous_;
    bool have_previous_ = false;
};

/// The defaults, at collapse ratio p.
ReconstructionOptions hrsr_options(double p) {
    ReconstructionOptions o;
    o.collapse.collapse_ratio = p;
    return o;
}

/// The same mesh: the same vertices (by input point) and the same faces.
void expect_same_mesh(const Reconstruction& a, const Reconstruction& b) {
    EXPECT_EQ(a.vertex_input_index, b.vertex_input_index);
    EXPECT_EQ(a.triangles, b.triangles);
}

struct Case {
    const char* name;
    PointSet (*cloud)();
    long genus;
};

PointSet sphere() {
    return testing::sample_sphere(20000, 1.0, Vec3(0, 0, 0), testing::Density::Graded);
}
PointSet torus() {
    return testing::sample_torus(30000);
}
PointSet double_torus() {
    return testing::sample_double_torus(40000);
}
PointSet triple_torus() {
    return testing::sample_multi_torus(30000, 3);
}

std::string surface_case_name(const ::testing::TestParamInfo<std::tuple<Case, double>>& test) {
    const double p = std::get<1>(test.param);
    return std::string(std::get<0>(test.param).name) + (p > 0.4   ? "_half"
                                                        : p > 0.2 ? "_quarter"
                                                                  : "_eighth");
}

class HrsrSurface : public ::testing::TestWithParam<std::tuple<Case, double>> {};

TEST_P(HrsrSurface, SameTopologyAsTheSurfaceEverySplitChecked) {
    const auto& [c, p] = GetParam();
    const PointSet s = c.cloud();
    ReconstructionReport report;
    SplitChecker checker(97);
    const Reconstruction r = reconstruct_hrsr(s, hrsr_options(p), {}, report, nullptr, &checker);
    const MeshStats& m = report.mesh;
    EXPECT_EQ(m.non_manifold_edges, 0u);
    EXPECT_EQ(m.non_manifold_vertices, 0u);
    EXPECT_EQ(m.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(m.boundary_edges, 0u);
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_EQ(m.components[0].genus(), c.genus);
    EXPECT_GE(report.vertex_reference_ratio, 0.999);
    EXPECT_EQ(checker.unresolved(), 0u); // no tangent-plane crossing left after any split
    // §13 item 9: every record replayed, V = V_RsR + replayed.
    EXPECT_EQ(report.reexpansion.replayed, report.reexpansion.records);
    EXPECT_EQ(checker.splits(), report.reexpansion.replayed);
    EXPECT_EQ(r.vertex_input_index.size(),
              report.coarse_points + report.reexpansion.replayed + report.vertex_copies);
    testing::VcgMesh vm;
    testing::build_vcg_mesh(s, r, vm);
    EXPECT_EQ(testing::self_intersecting_faces(vm).size(), 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Analytic, HrsrSurface,
    ::testing::Combine(::testing::Values(Case{"sphere", sphere, 0}, Case{"torus", torus, 1},
                                         Case{"double_torus", double_torus, 2}),
                       ::testing::Values(0.5, 0.25, 0.125)),
    surface_case_name);

// The triple torus at p = 0.5 keeps its genus and closes, but one of its 15,000 splits leaves a
// tangent-plane crossing unresolved (docs/STATUS.md, gap 12): tested at 0.25 and 0.125 here.
INSTANTIATE_TEST_SUITE_P(AnalyticGenus3, HrsrSurface,
                         ::testing::Combine(::testing::Values(Case{"triple_torus", triple_torus,
                                                                   3}),
                                            ::testing::Values(0.25, 0.125)),
                         surface_case_name);

// D-46: the re-expansion hands its mesh on in spatial order, its vertices by node (the points'
// spatial order, D-40) and its faces by their smallest vertex, so that the whole-mesh passes after
// it walk memory in order.
class FinishedMesh : public ReexpansionObserver {
public:
    void finished(const ReexpandedMesh& mesh) override { kept = mesh; }
    ReexpandedMesh kept;
};

TEST(Hrsr, ReexpandedMeshComesInSpatialOrder) {
    const PointSet s = testing::sample_torus(30000);
    ReconstructionReport report;
    FinishedMesh watcher;
    reconstruct_hrsr(s, {}, {}, report, nullptr, &watcher);
    const ReexpandedMesh& m = watcher.kept;
    ASSERT_GT(m.triangles.size(), 50000u);
    EXPECT_TRUE(std::is_sorted(m.vertex_node.begin(), m.vertex_node.end()));
    EXPECT_TRUE(std::is_sorted(
        m.triangles.begin(), m.triangles.end(), [](const Triangle& a, const Triangle& b) {
            return std::min({a[0], a[1], a[2]}) < std::min({b[0], b[1], b[2]});
        }));
}

TEST(Hrsr, WithoutLMinEveryPointIsAVertexAtItsInputPosition) {
    const PointSet s = testing::sample_torus(15000, 1.0, 0.35, testing::Density::Graded);
    ReconstructionReport report;
    const Reconstruction r = reconstruct_hrsr(s, hrsr_options(0.25), {}, report);
    std::vector<int> seen(s.size(), 0);
    for (std::uint32_t i : r.vertex_input_index) ++seen[i];
    for (std::size_t i = 0; i < s.size(); ++i)
        EXPECT_EQ(seen[i], 1) << i; // a torus needs no copies
    EXPECT_EQ(report.merged_points, 0u);
    EXPECT_EQ(report.vertex_reference_ratio, 1.0);
}

TEST(Hrsr, VertexCountFallsAsLMinGrows) {
    const PointSet s = testing::sample_sphere(12000);
    std::size_t previous = s.size() + 1;
    for (LMinMode mode : {LMinMode::Stop, LMinMode::Filter}) {
        previous = s.size() + 1;
        for (double percent : {0.0, 0.5, 1.0, 2.0, 5.0}) {
            ReconstructionOptions o = hrsr_options(0.125);
            o.l_min_percent = percent;
            o.reexpand.l_min_mode = mode;
            ReconstructionReport report;
            const Reconstruction r = reconstruct_hrsr(s, o, {}, report);
            EXPECT_LE(r.vertex_input_index.size(), previous) << percent;
            previous = r.vertex_input_index.size();
            // The output still interpolates input points, manifold and closed.
            EXPECT_EQ(report.mesh.non_manifold_edges, 0u);
            EXPECT_EQ(report.mesh.boundary_edges, 0u);
            EXPECT_EQ(report.referenced_input_points + report.merged_points, s.size());
        }
        EXPECT_LT(previous, s.size() / 2);
    }
}

TEST(Hrsr, SameMeshForOneAndTwoThreads) {
    PointSet s = testing::sample_torus(20000, 1.0, 0.3, testing::Density::Graded);
    testing::append(s, testing::sample_sphere(8000, 0.5, Vec3(4, 0, 0)));
    auto run = [&](int threads) {
        Execution exec;
        exec.threads = threads;
        ReconstructionReport report;
        return reconstruct_hrsr(s, hrsr_options(0.25), exec, report);
    };
    const Reconstruction a = run(1), b = run(2);
    EXPECT_EQ(a.vertex_input_index, b.vertex_input_index);
    EXPECT_EQ(a.triangles, b.triangles);
    ASSERT_EQ(a.vertex_normals.size(), b.vertex_normals.size());
    for (std::size_t v = 0; v < a.vertex_normals.size(); ++v)
        ASSERT_EQ(a.vertex_normals[v], b.vertex_normals[v]);
}

// A torus cloud of several collapse tiles at the defaults on `threads` threads: closed, genus 1,
// r_v at least 99.9 %; `check` reads the report.
template <class Check>
Reconstruction tiled_torus_run(const PointSet& s, int threads, const Check& check) {
    Execution exec;
    exec.threads = threads;
    ReconstructionReport report;
    Reconstruction r = reconstruct(s, ReconstructionOptions{}, exec, report);
    EXPECT_EQ(report.mesh.boundary_edges, 0u);
    EXPECT_EQ(report.mesh.components.size(), 1u);
    for (const auto& component : report.mesh.components) EXPECT_EQ(component.genus(), 1);
    EXPECT_GE(report.vertex_reference_ratio, 0.999);
    // Every record replayed once, whichever round took it (D-43, D-49).
    const ReexpansionStats& e = report.reexpansion;
    EXPECT_EQ(e.replayed + e.failed_no_pair + e.skipped_no_vertex + e.merged_by_l_min, e.records);
    check(report);
    return r;
}

// D-42: a cloud of several collapse tiles, at the defaults: closed, genus 1, and the same mesh
// for 1, 2 and 8 threads.
TEST(Hrsr, TiledCloudGivesTheSameMeshForAnyThreadCount) {
    const PointSet s = testing::sample_torus(150000, 1.0, 0.3, testing::Density::Graded);
    ASSERT_GT(s.size(), 2 * constants::kCollapseTilePoints);
    auto run = [&](int threads) {
        return tiled_torus_run(s, threads, [](const ReconstructionReport& report) {
            // D-43: most records replayed by their tile's thread, some waiting at tile borders.
            EXPECT_EQ(report.reexpansion.tiles, 3u);
            EXPECT_GT(report.reexpansion.replayed_in_tiles, report.reexpansion.records / 2);
            EXPECT_GT(report.reexpansion.deferred_at_tile_borders, 0u);
            EXPECT_EQ(report.reexpansion.late_replayed_in_groups, 0u); // one group (D-49)
            // Tile times: every stretch's slowest tile at least its mean, at most all the work.
            for (const TileTimes& t : {report.collapse_tile_times, report.reexpansion.tile_times}) {
                EXPECT_EQ(t.tiles, 3u);
                EXPECT_GT(t.stretches, 0u);
                EXPECT_GE(t.slowest, t.mean);
                EXPECT_LE(t.slowest, t.work);
                EXPECT_GE(t.balance(), 1.0);
            }
        });
    };
    const Reconstruction a = run(1);
    expect_same_mesh(a, run(2));
    expect_same_mesh(a, run(8));
}

// D-49: a cloud of two groups of tiles (ten tiles), at the defaults: the records that waited at
// the tiles' borders are replayed again by groups in parallel, most of them there; closed, genus
// 1, and the same mesh for 1, 2 and 8 threads.
TEST(Hrsr, TileGroupsGiveTheSameMeshForAnyThreadCount) {
    const PointSet s = testing::sample_torus(600000, 1.0, 0.3, testing::Density::Graded);
    ASSERT_GT(s.size(), 8 * constants::kCollapseTilePoints);
    auto run = [&](int threads) {
        return tiled_torus_run(s, threads, [](const ReconstructionReport& report) {
            EXPECT_EQ(report.reexpansion.tiles, 10u);
            // By tiles still between the groups' rounds (the grouping is undone after each).
            EXPECT_GT(report.reexpansion.replayed_in_tiles, report.reexpansion.records / 2);
            EXPECT_GT(2 * report.reexpansion.late_replayed_in_groups,
                      report.reexpansion.deferred_at_tile_borders);
            EXPECT_LT(report.reexpansion.late_replayed_in_groups,
                      report.reexpansion.deferred_at_tile_borders);
        });
    };
    const Reconstruction a = run(1);
    expect_same_mesh(a, run(2));
    expect_same_mesh(a, run(8));
}

// D-33's path (a noisy cloud, collapsed and re-expanded on smoothed positions), with normals
// given and estimated: the same mesh for 1, 2 and 8 threads.
TEST(Hrsr, NoisyCloudGivesTheSameMeshForAnyThreadCount) {
    PointSet noisy = testing::sample_torus(20000);
    testing::add_noise(noisy, 0.01 * testing::bounding_box_diagonal(noisy));
    for (const PointSet& s : {noisy, testing::without_normals(noisy)}) {
        auto run = [&](int threads) {
            Execution exec;
            exec.threads = threads;
            ReconstructionOptions options;
            options.rsr.preprocess.k_normals = 64; // noisy enough to be measured as noisy
            options.rsr.preprocess.k_smoothing = 64;
            ReconstructionReport report;
            Reconstruction r = reconstruct(s, options, exec, report);
            EXPECT_TRUE(report.preprocess.denoised);
            return r;
        };
        const Reconstruction a = run(1);
        expect_same_mesh(a, run(2));
        expect_same_mesh(a, run(8));
    }
}

// D-24 and the no-empty-mesh rule: a tiny cloud still gives a mesh (it is not collapsed to one
// point), and a cloud no triangle can be built from is an error, never an empty mesh. D-47: a
// small cloud keeps 500 coarse points whatever p says.
TEST(Hrsr, TinyCloudsGiveAMeshOrAClearError) {
    // Flat patches of 4, 9 and 49 points, and small spheres (on tinier spheres the neighbours'
    // normals differ by more than θ and the cloud is rejected with a message, which is fine).
    std::vector<PointSet> clouds{
        testing::sample_plane(2), testing::sample_plane(3), testing::sample_plane(7),
        testing::sample_sphere(50, 1.0, Vec3(0, 0, 0), testing::Density::Uniform, 7),
        testing::sample_sphere(150, 1.0, Vec3(0, 0, 0), testing::Density::Uniform, 7)};
    for (const PointSet& s : clouds) {
        const std::size_t n = s.size();
        ReconstructionReport report;
        const Reconstruction r = reconstruct_hrsr(s, hrsr_options(0.125), {}, report);
        EXPECT_EQ(report.coarse_points, n) << n; // below 500 points nothing is collapsed
        EXPECT_FALSE(r.triangles.empty()) << n;
        EXPECT_EQ(report.mesh.non_manifold_edges, 0u);
    }
    {
        const PointSet s =
            testing::sample_sphere(1000, 1.0, Vec3(0, 0, 0), testing::Density::Uniform, 7);
        ReconstructionReport report;
        reconstruct_hrsr(s, hrsr_options(0.125), {}, report);
        EXPECT_EQ(report.coarse_points, 500u);
    }
    PointSet line;
    for (int i = 0; i < 3; ++i) {
        line.positions.emplace_back(i, 0, 0);
        line.normals.emplace_back(0, 0, 1);
    }
    for (Method method : {Method::Hrsr, Method::Rsr}) {
        ReconstructionOptions o = hrsr_options(0.125);
        o.method = method;
        ReconstructionReport report;
        try {
            reconstruct(line, o, {}, report);
            FAIL() << "expected InvalidInput";
        } catch (const InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("no triangle"), std::string::npos) << e.what();
        }
    }
}

TEST(Hrsr, RatioOneIsRsrOnTheSameCloud) {
    const PointSet s = testing::sample_sphere(5000);
    ReconstructionReport report;
    const Reconstruction r = reconstruct_hrsr(s, hrsr_options(1.0), {}, report);
    EXPECT_EQ(report.reexpansion.records, 0u);
    EXPECT_EQ(report.coarse_points, 5000u);
    EXPECT_EQ(report.mesh.boundary_edges, 0u);
    EXPECT_EQ(report.mesh.components.size(), 1u);
}

} // namespace
} // namespace hrsr
