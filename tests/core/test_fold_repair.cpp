// D-26: the flips that undo folds.
#include "io/point_set_reader.h"
#include "mesh/fold_repair.h"
#include "mesh/mesh_stats.h"
#include "mesh/self_intersections.h"
#include "mesh/welding.h"
#include "reconstruction.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <tuple>

namespace hrsr {
namespace {

struct Output {
    std::vector<Vec3> positions; ///< the output vertices at their input coordinates
    std::vector<Triangle> triangles;
    FoldRepairStats repair;
};

Output reconstruct_owl(int fold_repair_rounds, int threads = 0) {
    const PointSet cloud = io::read_point_set(HRSR_SAMPLE);
    ReconstructionOptions options;
    options.rsr.fold_repair_rounds = fold_repair_rounds;
    ReconstructionReport report;
    const Reconstruction r = reconstruct(cloud, options, {threads, nullptr}, report);
    Output out;
    for (std::uint32_t i : r.vertex_input_index) out.positions.push_back(cloud.positions[i]);
    out.triangles = r.triangles;
    out.repair = report.fold_repair;
    return out;
}

// Flips keep V, E, F, the boundary and every component's genus, and a manifold stays one.
void expect_same_topology(const MeshStats& a, const MeshStats& b) {
    const auto counts = [](const MeshStats& m) {
        return std::make_tuple(m.vertices, m.edges, m.faces, m.boundary_edges, m.boundary_loops);
    };
    EXPECT_EQ(counts(a), counts(b));
    ASSERT_EQ(a.components.size(), b.components.size());
    for (std::size_t c = 0; c < a.components.size(); ++c)
        EXPECT_EQ(a.components[c].genus(), b.components[c].genus());
    EXPECT_EQ(b.non_manifold_edges, 0u);
    EXPECT_EQ(b.non_manifold_vertices, 0u);
    EXPECT_EQ(b.inconsistently_oriented_edges, 0u);
}

// One search serves D-26 and D-32: after the flips its pairs are exactly those a new search of
// the repaired mesh finds, so D-32 needs none of its own.
TEST(FoldRepair, TheSharedSearchEndsWithExactlyThePairsLeft) {
    const Output plain = reconstruct_owl(0);
    std::vector<Triangle> repaired = plain.triangles;
    FoldSearch search(plain.positions, repaired, {});
    ASSERT_GT(search.pairs.size(), 0u) << "the sample no longer has a fold to repair";
    const FoldRepairStats stats = repair_folds(search, repaired, 2);
    EXPECT_GT(stats.flips, 0u);
    EXPECT_EQ(search.pairs, self_intersecting_pairs(plain.positions, repaired, {}));
    EXPECT_EQ(stats.pairs_after, search.pairs.size());
}

// The shipped owl's HRsR mesh has folds (15 intersecting pairs when this test was written).
TEST(FoldRepair, FewerIntersectionsSameVerticesAndTopology) {
    const Output plain = reconstruct_owl(0);
    const std::vector<TrianglePair> before =
        self_intersecting_pairs(plain.positions, plain.triangles, {});
    ASSERT_GT(before.size(), 0u) << "the sample no longer has a fold to repair";
    EXPECT_EQ(plain.repair.pairs_before, 0u); // not searched at all with 0 rounds

    std::vector<Triangle> repaired = plain.triangles;
    const FoldRepairStats stats = repair_folds(plain.positions, repaired, 2, {});
    EXPECT_EQ(stats.pairs_before, before.size());
    const std::vector<TrianglePair> after = self_intersecting_pairs(plain.positions, repaired, {});
    EXPECT_EQ(stats.pairs_after, after.size()); // the repair's own count is exact
    EXPECT_LT(after.size(), before.size());
    EXPECT_GT(stats.flips, 0u);
    expect_same_topology(measure_mesh(plain.positions.size(), plain.triangles),
                         measure_mesh(plain.positions.size(), repaired));
    // Each flip rewrites two triangles in place; the others keep their slot and corners.
    ASSERT_EQ(repaired.size(), plain.triangles.size());
    std::size_t changed = 0;
    for (std::size_t t = 0; t < repaired.size(); ++t) changed += repaired[t] != plain.triangles[t];
    EXPECT_GT(changed, 0u);
    EXPECT_LE(changed, 2 * stats.flips);

    // Through reconstruct(), which flips in its normalised coordinates (D-2) and then cuts out
    // what is left (D-32, test_fold_removal.cpp): flips reported, no pair left in the written
    // coordinates, the genus and the boundary kept.
    const Output through = reconstruct_owl(8);
    // (A pair that only touches can count on one side of the rounding and not the other.)
    EXPECT_NEAR(double(through.repair.pairs_before), double(before.size()),
                1.0 + 0.1 * double(before.size()));
    EXPECT_LT(through.repair.pairs_after, through.repair.pairs_before);
    EXPECT_GT(through.repair.flips, 0u);
    EXPECT_TRUE(self_intersecting_pairs(through.positions, through.triangles, {}).empty());
    const MeshStats a = measure_mesh(plain.positions.size(), plain.triangles);
    const MeshStats b = measure_mesh(through.positions.size(), through.triangles);
    ASSERT_EQ(a.components.size(), b.components.size());
    for (std::size_t c = 0; c < a.components.size(); ++c)
        EXPECT_EQ(a.components[c].genus(), b.components[c].genus());
    EXPECT_EQ(a.boundary_edges, b.boundary_edges);
    EXPECT_EQ(b.non_manifold_edges + b.non_manifold_vertices, 0u);
}

TEST(FoldRepair, SameResultOnOneAndTwoThreads) {
    const Output plain = reconstruct_owl(0, 1);
    std::vector<Triangle> one = plain.triangles, two = plain.triangles;
    const FoldRepairStats a = repair_folds(plain.positions, one, 2, {1, nullptr});
    const FoldRepairStats b = repair_folds(plain.positions, two, 2, {2, nullptr});
    EXPECT_EQ(one, two);
    EXPECT_EQ(a.flips, b.flips);
    EXPECT_EQ(a.pairs_after, b.pairs_after);
}

// The fold search welds vertices at one position (a parallel sort by their hash): every thread
// count gives the smallest index at each position, −0 and +0 being one.
TEST(FoldRepair, WeldingInParallelGivesTheSequentialRepresentatives) {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> coordinate(0, 40); // a coarse lattice: many repeats
    std::vector<Vec3> positions;
    for (int i = 0; i < 60000; ++i)
        positions.emplace_back(coordinate(random), coordinate(random) * 0.5,
                               coordinate(random) % 3);
    for (std::size_t v = 0; v < positions.size(); v += 7) // −0 and +0 are one position
        for (int k = 0; k < 3; ++k)
            if (positions[v][k] == 0) positions[v][k] = -0.0;
    std::vector<Triangle> triangles;
    for (std::uint32_t i = 0; i + 2 < positions.size(); i += 3)
        triangles.push_back({i, i + 2, i + 1});
    std::map<std::tuple<double, double, double>, std::uint32_t> first; // the reference
    std::vector<std::uint32_t> expected;
    for (std::uint32_t v = 0; v < positions.size(); ++v)
        expected.push_back(
            first.emplace(std::make_tuple(positions[v][0], positions[v][1], positions[v][2]), v)
                .first->second);
    ASSERT_LT(first.size(), positions.size() / 2); // most vertices repeat a position
    const std::vector<std::uint32_t> sequential = same_position_representatives(positions);
    EXPECT_EQ(sequential, expected);
    for (int threads : {1, 2, 8}) {
        EXPECT_EQ(same_position_representatives(positions, {threads, nullptr}), sequential)
            << threads;
        EXPECT_EQ(welded_triangles(triangles, sequential, {threads, nullptr}),
                  welded_triangles(triangles, sequential))
            << threads;
    }
}

TEST(FoldRepair, NothingToDoOnACleanMeshOrWithZeroRounds) {
    // A flat 3 × 3 grid of quads: no intersection, so no flip.
    std::vector<Vec3> positions;
    std::vector<Triangle> triangles;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) positions.emplace_back(x, y, 0);
    for (std::uint32_t y = 0; y < 3; ++y)
        for (std::uint32_t x = 0; x < 3; ++x) {
            const std::uint32_t v = 4 * y + x;
            triangles.push_back({v, v + 1, v + 5});
            triangles.push_back({v, v + 5, v + 4});
        }
    const std::vector<Triangle> original = triangles;
    const FoldRepairStats stats = repair_folds(positions, triangles, 2, {});
    EXPECT_EQ(stats.pairs_before, 0u);
    EXPECT_EQ(stats.flips, 0u);
    EXPECT_EQ(triangles, original);
    EXPECT_EQ(repair_folds(positions, triangles, 0, {}).pairs_before, 0u);
}

} // namespace
} // namespace hrsr
