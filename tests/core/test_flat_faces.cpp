// D-36: faces whose corners lie exactly on one line leave the output without a point lost.
#include "mesh/exact_predicates.h"
#include "mesh/flat_faces.h"
#include "mesh/mesh_stats.h"
#include "mesh/self_intersections.h"

#include "mesh_fixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace hrsr {
namespace {

using testing::used_vertices;

std::size_t flat_faces(const std::vector<Vec3>& p, const std::vector<Triangle>& triangles) {
    std::size_t n = 0;
    for (const Triangle& t : triangles) n += exact::collinear(p[t[0]], p[t[1]], p[t[2]]);
    return n;
}

// Manifold, coherently oriented, every vertex kept, no flat face, no intersecting pair.
void expect_clean(const std::vector<Vec3>& p, const std::vector<Triangle>& before,
                  const std::vector<Triangle>& after) {
    const MeshStats s = measure_mesh(p.size(), after);
    EXPECT_EQ(s.non_manifold_edges, 0u);
    EXPECT_EQ(s.non_manifold_vertices, 0u);
    EXPECT_EQ(s.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(used_vertices(after), used_vertices(before));
    EXPECT_EQ(flat_faces(p, after), 0u);
    EXPECT_TRUE(self_intersecting_pairs(p, after, {}).empty());
}

// m = (0, 0) lies on the border edge a–b, inside a closed fan: the flat face (m, b, a) closes
// the notch above m with no area; it goes and the border runs a → m → b.
TEST(FlatFaces, AFlatFaceOnTheBorderIsTakenOff) {
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {-1, 0, 0}, {-0.5, -1, 0}, {0.5, -1, 0}};
    const std::vector<Triangle> before = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}};
    std::vector<Triangle> t = before;
    const FlatFaceStats st = clear_flat_faces(p, t);
    EXPECT_EQ(st.found, 1u);
    EXPECT_EQ(st.removed, 1u);
    EXPECT_EQ(st.left, 0u);
    EXPECT_EQ(t.size(), 3u);
    expect_clean(p, before, t);
    EXPECT_EQ(measure_mesh(p.size(), t).boundary_edges, 5u); // one more: a–m, m–b for a–b
}

// A tip: m's only face is flat, across its longest edge a–b stands (b, a, o). The flip splits
// that face at m into (m, a, o) and (m, o, b): the same ground, two proper triangles.
TEST(FlatFaces, AFlatFaceInsideIsFlippedAway) {
    const std::vector<Vec3> p = {{0.25, 0, 0}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}};
    const std::vector<Triangle> before = {{0, 2, 1}, {2, 3, 1}}; // (m, b, a), (b, o, a)
    std::vector<Triangle> t = before;
    const FlatFaceStats st = clear_flat_faces(p, t);
    EXPECT_EQ(st.found, 1u);
    EXPECT_EQ(st.flipped, 1u);
    EXPECT_EQ(t.size(), 2u);
    expect_clean(p, before, t);
}

// Four points on one line: every face over them is flat and no flip gives proper triangles,
// so the faces are counted as left (never a lost point or a broken mesh).
TEST(FlatFaces, ARunOfFourCollinearPointsIsLeftAndCounted) {
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
    const std::vector<Triangle> before = {{0, 1, 3}, {1, 2, 3}};
    std::vector<Triangle> t = before;
    const FlatFaceStats st = clear_flat_faces(p, t);
    EXPECT_EQ(st.found, 2u);
    EXPECT_EQ(st.left + st.flipped + st.removed, 2u);
    EXPECT_EQ(used_vertices(t), used_vertices(before));
    EXPECT_EQ(measure_mesh(p.size(), t).non_manifold_edges, 0u);
}

// A mesh that is not a manifold (three faces on one edge) is left as it is, its flat face
// counted as left: the pass never fails a reconstruction.
TEST(FlatFaces, ANonManifoldMeshIsLeftAsItIs) {
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0.5}};
    const std::vector<Triangle> before = {{0, 2, 1}, {0, 1, 3}, {1, 0, 4}, {0, 1, 4}};
    std::vector<Triangle> t = before;
    const FlatFaceStats st = clear_flat_faces(p, t);
    EXPECT_EQ(st.found, 1u);
    EXPECT_EQ(st.left, 1u);
    EXPECT_EQ(t, before);
}

// A mesh without flat faces is returned as it was.
TEST(FlatFaces, AProperMeshIsUnchanged) {
    const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}};
    const std::vector<Triangle> before = {{0, 1, 2}, {2, 1, 3}};
    std::vector<Triangle> t = before;
    EXPECT_EQ(clear_flat_faces(p, t).found, 0u);
    EXPECT_EQ(t, before);
}

// The search runs by blocks of faces in parallel: a grid of 60,000 faces with flat faces along
// its bottom row (as in the second test), shuffled into every block, gives the same faces and
// counts for any thread count.
TEST(FlatFaces, AnyThreadCountClearsTheSameFaces) {
    const int columns = 150, rows = 200;
    std::vector<Vec3> p;
    for (int r = 0; r <= rows; ++r)
        for (int c = 0; c <= columns; ++c)
            p.emplace_back(c, r, r == 0 ? 0 : 0.01 * ((r * 7 + c * 3) % 5));
    const auto at = [&](int r, int c) { return std::uint32_t(r * (columns + 1) + c); };
    std::vector<Triangle> before;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            before.push_back({at(r, c), at(r, c + 1), at(r + 1, c + 1)});
            before.push_back({at(r, c), at(r + 1, c + 1), at(r + 1, c)});
        }
    // Flat notches along the bottom row: a point halfway between two of its points, with a
    // face (m, b, a) on the line and (m, a, below) and (m, below, b) under it.
    for (int c = 0; c < columns; c += 2) {
        const std::uint32_t a = at(0, c), b = at(0, c + 1), m = std::uint32_t(p.size()),
                            below = std::uint32_t(p.size() + 1);
        p.push_back((p[a] + p[b]) * 0.5);
        p.emplace_back(c + 0.5, -1, 0);
        before.push_back({m, b, a});
        before.push_back({m, a, below});
        before.push_back({m, below, b});
    }
    std::shuffle(before.begin(), before.end(), std::mt19937(7)); // flat faces in every block
    std::vector<Triangle> one = before;
    const FlatFaceStats single = clear_flat_faces(p, one, {1, nullptr});
    EXPECT_GE(single.found, std::size_t(columns / 2));
    EXPECT_EQ(single.left, 0u);
    for (int threads : {2, 8}) {
        std::vector<Triangle> many = before;
        const FlatFaceStats st = clear_flat_faces(p, many, {threads, nullptr});
        EXPECT_EQ(many, one) << threads << " threads";
        EXPECT_EQ(st.found, single.found);
        EXPECT_EQ(st.flipped, single.flipped);
        EXPECT_EQ(st.removed, single.removed);
    }
}

} // namespace
} // namespace hrsr
