#include "errors.h"
#include "hrsr/collapse.h"
#include "samplers.h"
#include "spatial_order.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hrsr {
namespace {

CollapsedCloud run(const PointSet& s, double ratio, int threads = 0) {
    CollapseOptions o;
    o.collapse_ratio = ratio;
    Execution exec;
    exec.threads = threads;
    return collapse(s.positions, s.normals, o, exec);
}

// ALGORITHM.md §13 item 7.
void expect_collapse_invariants(const PointSet& s, const CollapsedCloud& c) {
    const std::size_t n = s.size();
    EXPECT_EQ(c.survivors.size() + c.records.size(), n);
    // Every point is a survivor or the latent of exactly one record; latents never reappear.
    std::vector<int> role(n, 0);
    for (PointIndex v : c.survivors) ++role[v.value()];
    for (const CollapseRecord& r : c.records) {
        ++role[r.latent];
        EXPECT_LT(r.active, r.latent); // the smaller id survives
    }
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(role[i], 1) << i;
    // Replaying the records gives each survivor's tree: its position is the tree's mean and its
    // weight the tree's size; weights sum to N.
    std::vector<Vec3> sum(s.positions);
    std::vector<std::uint32_t> count(n, 1);
    for (const CollapseRecord& r : c.records) {
        sum[r.active] += sum[r.latent];
        count[r.active] += count[r.latent];
    }
    std::size_t total = 0;
    for (std::size_t k = 0; k < c.survivors.size(); ++k) {
        const std::uint32_t v = c.survivors[CoarseIndex(std::uint32_t(k))].value();
        EXPECT_EQ(c.weights[k], count[v]);
        total += c.weights[k];
        EXPECT_LT((c.positions[k] - sum[v] / double(count[v])).Norm(), 1e-12);
        EXPECT_NEAR(c.normals[k].Norm(), 1.0, 1e-12); // D-9
    }
    EXPECT_EQ(total, n);
}

TEST(Collapse, ReachesTheRatioAndKeepsItsInvariants) {
    const PointSet s = testing::sample_torus(20000, 1.0, 0.35, testing::Density::Graded);
    for (double p : {0.5, 0.25, 0.125}) {
        const CollapsedCloud c = run(s, p);
        EXPECT_FALSE(c.ran_out_of_edges);
        EXPECT_EQ(c.survivors.size(), std::size_t(std::llround(20000 * p)));
        expect_collapse_invariants(s, c);
    }
}

TEST(Collapse, RatioOneCollapsesNothing) {
    const PointSet s = testing::sample_sphere(1000);
    const CollapsedCloud c = run(s, 1.0);
    EXPECT_TRUE(c.records.empty());
    EXPECT_EQ(c.survivors.size(), 1000u);
    EXPECT_EQ(c.positions, s.positions);
}

TEST(Collapse, StopsCleanlyWhenNoValidEdgeIsLeft) {
    // Two opposite-facing points only: the > 90° rule forbids their edge (D-14).
    PointSet s;
    s.positions = {{0, 0, 0}, {1, 0, 0}};
    s.normals = {{0, 0, 1}, {0, 0, -1}};
    const CollapsedCloud c = run(s, 0.5);
    EXPECT_TRUE(c.ran_out_of_edges);
    EXPECT_TRUE(c.records.empty());
    EXPECT_EQ(c.survivors.size(), 2u);
}

TEST(Collapse, AnInheritedEdgeIsNotCheckedAgain) {
    // A–C is never linked (normals > 90° apart); A and B merge first (the shortest edge), and
    // the merged node inherits B–C although its normal is now > 90° from C's: as in GEL, the
    // rule holds for the graph as built only (D-15 withdrawn), so C merges too.
    PointSet s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {2.5, 0, 0}};
    s.normals = {{0, 0, 1}, {1, 0, 0}, Vec3(0.1, 0, -1).Normalize()};
    const CollapsedCloud c = run(s, 1.0 / 3.0);
    EXPECT_FALSE(c.ran_out_of_edges);
    ASSERT_EQ(c.records.size(), 2u);
    EXPECT_EQ(c.records[0].latent, 1u); // A–B first
    EXPECT_EQ(c.records[1].latent, 2u);
    expect_collapse_invariants(s, c);
}

TEST(Collapse, NeverMergesOppositeNormals) {
    // Two parallel sheets with opposite normals, closer than their own spacing.
    PointSet s = testing::sample_plane(30, 1.0, 5);
    PointSet other = testing::sample_plane(30, 1.0, 6);
    for (Vec3& p : other.positions) p[2] = 0.3;
    for (Vec3& n : other.normals) n = -n;
    testing::append(s, other);
    const CollapsedCloud c = run(s, 0.25);
    for (const CollapseRecord& r : c.records) EXPECT_EQ(r.active < 900, r.latent < 900);
    expect_collapse_invariants(s, c);
}

TEST(Collapse, TiesAndDuplicatesOfARegularGridAreDeterministic) {
    const PointSet grid = [] {
        PointSet g;
        for (int i = 0; i < 40; ++i)
            for (int j = 0; j < 40; ++j) {
                g.positions.emplace_back(i, j, 0);
                g.normals.emplace_back(0, 0, 1);
            }
        return g;
    }();
    const CollapsedCloud a = run(grid, 0.125, 1), b = run(grid, 0.125, 2);
    ASSERT_EQ(a.records.size(), b.records.size());
    for (std::size_t k = 0; k < a.records.size(); ++k) {
        EXPECT_EQ(a.records[k].active, b.records[k].active);
        EXPECT_EQ(a.records[k].latent, b.records[k].latent);
    }
    EXPECT_EQ(a.survivors, b.survivors);
    expect_collapse_invariants(grid, a);
}

// D-42: a cloud of several tiles, in spatial order as reconstruct() hands it over. The ratio is
// reached exactly, the records form §13 item 7's forest, nodes of different tiles are merged too
// (the borders do not stay apart), and the result is the same for 1, 2 and 8 threads.
TEST(Collapse, TilesReachTheRatioTheSameForAnyThreadCount) {
    const PointSet sampled = testing::sample_torus(200000, 1.0, 0.35, testing::Density::Graded);
    const PointSet s = reordered(sampled, spatial_order(sampled.positions, {}));
    const CollapsedCloud a = run(s, 0.25, 1);
    EXPECT_FALSE(a.ran_out_of_edges);
    EXPECT_EQ(a.survivors.size(), 50000u);
    EXPECT_GT(a.tile_collapses, a.records.size() / 2); // most of it in parallel
    expect_collapse_invariants(s, a);
    ASSERT_GT(a.tiles, 1u);
    const std::size_t tile_size = (s.size() + a.tiles - 1) / a.tiles;
    std::size_t across = 0;
    for (const CollapseRecord& r : a.records)
        across += r.active / tile_size != r.latent / tile_size;
    EXPECT_GT(across, 0u);
    for (int threads : {2, 8}) {
        const CollapsedCloud b = run(s, 0.25, threads);
        ASSERT_EQ(a.records.size(), b.records.size());
        for (std::size_t k = 0; k < a.records.size(); ++k) {
            ASSERT_EQ(a.records[k].active, b.records[k].active) << k;
            ASSERT_EQ(a.records[k].latent, b.records[k].latent) << k;
        }
        EXPECT_EQ(a.survivors, b.survivors);
        EXPECT_EQ(a.positions, b.positions);
    }
}

// D-42: on a regular grid every first cost is the same, so the tiles' first step at p = 3/4
// goes beyond the budget and the tiles start again below it: still the exact ratio, §13 item 7's
// forest, and the same records for any thread count.
TEST(Collapse, TilesStartAgainBelowAStepBeyondTheBudget) {
    PointSet grid;
    for (int i = 0; i < 300; ++i)
        for (int j = 0; j < 300; ++j) {
            grid.positions.emplace_back(i, j, 0);
            grid.normals.emplace_back(0, 0, 1);
        }
    const PointSet s = reordered(grid, spatial_order(grid.positions, {}));
    const CollapsedCloud a = run(s, 0.75, 1), b = run(s, 0.75, 8);
    EXPECT_GT(a.tiles, 1u);
    EXPECT_GT(a.tile_restarts, 0u);
    EXPECT_EQ(a.survivors.size(), 67500u);
    expect_collapse_invariants(s, a);
    EXPECT_EQ(a.survivors, b.survivors);
    ASSERT_EQ(a.records.size(), b.records.size());
    for (std::size_t k = 0; k < a.records.size(); ++k)
        ASSERT_EQ(a.records[k].latent, b.records[k].latent) << k;
}

TEST(Collapse, OptionsAreValidatedByName) {
    const PointSet s = testing::sample_sphere(100);
    CollapseOptions o;
    for (double bad : {0.0, -0.5, 1.5, std::nan("")}) {
        o.collapse_ratio = bad;
        try {
            collapse(s.positions, s.normals, o, {});
            FAIL() << bad;
        } catch (const InvalidOption& e) {
            EXPECT_EQ(e.option, OptionId::CollapseRatio);
            EXPECT_EQ(std::string(e.what()).rfind("collapse_ratio must be in (0, 1]", 0), 0u);
        }
    }
    o = {};
    o.collapse_k = 0;
    EXPECT_THROW(collapse(s.positions, s.normals, o, {}), InvalidOption);
}

} // namespace
} // namespace hrsr
