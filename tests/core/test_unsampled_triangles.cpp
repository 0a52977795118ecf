// D-30: triangles over a hole in the data are removed from HRsR's output; triangles of a
// regularly sampled surface, however they are cut, are not.
#include "hrsr/unsampled_triangles.h"
#include "mesh/mesh_stats.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace hrsr {
namespace {

constexpr int kRank = 46; // ⌊2k/3⌋ at the default k = 70

/// Points of a unit-spaced n × n grid in the plane z = 0, without those strictly inside the
/// square hole [lo, hi]² (a hole in the data, as a scanner leaves it).
std::vector<Vec3> grid_points(int n, int lo, int hi) {
    std::vector<Vec3> p;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            if (!(x > lo && x < hi && y > lo && y < hi)) p.push_back(Vec3(x, y, 0));
    return p;
}

std::uint32_t at(const std::vector<Vec3>& p, int x, int y) {
    for (std::uint32_t i = 0; i < p.size(); ++i)
        if (p[i][0] == x && p[i][1] == y) return i;
    ADD_FAILURE() << "no point at " << x << ", " << y;
    return 0;
}

/// The grid's two triangles per cell wherever all four corners are points.
std::vector<Triangle> grid_triangles(const std::vector<Vec3>& p, int n, int lo, int hi) {
    auto present = [&](int x, int y) { return !(x > lo && x < hi && y > lo && y < hi); };
    std::vector<Triangle> t;
    for (int y = 0; y + 1 < n; ++y)
        for (int x = 0; x + 1 < n; ++x) {
            if (!present(x, y) || !present(x + 1, y) || !present(x, y + 1) ||
                !present(x + 1, y + 1))
                continue;
            t.push_back({at(p, x, y), at(p, x + 1, y), at(p, x + 1, y + 1)});
            t.push_back({at(p, x, y), at(p, x + 1, y + 1), at(p, x, y + 1)});
        }
    return t;
}

IndexVector<VertexIndex, PointIndex> identity(std::size_t n) {
    IndexVector<VertexIndex, PointIndex> v;
    for (std::uint32_t i = 0; i < n; ++i) v.push_back(PointIndex(i));
    return v;
}

TEST(RemoveUnsampledTriangles, AFullySampledGridKeepsEveryTriangle) {
    const int n = 30;
    const std::vector<Vec3> p = grid_points(n, 0, 0);
    std::vector<Triangle> t = grid_triangles(p, n, 0, 0);
    const std::size_t before = t.size();
    EXPECT_EQ(remove_unsampled_triangles(t, p, identity(p.size()), kRank, {}), 0u);
    EXPECT_EQ(t.size(), before);
}

/// The grid points around the square hole (lo, hi)², in order around it.
std::vector<std::uint32_t> hole_outline(const std::vector<Vec3>& p, int lo, int hi) {
    std::vector<std::uint32_t> ring;
    for (int x = lo; x < hi; ++x) ring.push_back(at(p, x, lo));
    for (int y = lo; y < hi; ++y) ring.push_back(at(p, hi, y));
    for (int x = hi; x > lo; --x) ring.push_back(at(p, x, hi));
    for (int y = hi; y > lo; --y) ring.push_back(at(p, lo, y));
    return ring;
}

/// A 15 × 15 hole in the samples of a grid, closed by a fan from one corner of its outline (as
/// RsR's ears on a coarse cloud close it).
struct ClosedHole {
    static constexpr int n = 40, lo = 12, hi = 28;
    std::vector<Vec3> points = grid_points(n, lo, hi);
    std::vector<Triangle> triangles = grid_triangles(points, n, lo, hi);
    std::size_t grid = triangles.size();
    ClosedHole() {
        const std::vector<std::uint32_t> ring = hole_outline(points, lo, hi);
        for (std::size_t i = 1; i + 1 < ring.size(); ++i)
            triangles.push_back({ring[0], ring[i + 1], ring[i]});
    }
};

// The fan's triangles with an edge over twice the 46th neighbour distance (≈ 4 spacings) form
// a disk with no point inside: they go, and the hole reopens as one loop; the fan's short
// triangles near its apex and every grid triangle stay.
TEST(RemoveUnsampledTriangles, ACompletelyClosedHoleInTheDataReopens) {
    ClosedHole h;
    ASSERT_EQ(measure_mesh(h.points.size(), h.triangles).boundary_loops, 1u); // the outline
    const std::size_t removed =
        remove_unsampled_triangles(h.triangles, h.points, identity(h.points.size()), kRank, {});
    EXPECT_GT(removed, 40u);
    EXPECT_LT(removed, 62u); // of 62 fan triangles
    const MeshStats m = measure_mesh(h.points.size(), h.triangles);
    EXPECT_EQ(m.boundary_loops, 2u);
    EXPECT_EQ(m.non_manifold_vertices, 0u);
    EXPECT_EQ(m.unreferenced_vertices, 0u);
    EXPECT_EQ(m.euler(), 0); // one piece, an annulus: the grid around the reopened hole
}

// A hole that is still partly open keeps what covers it (two triangles between its corners):
// reopening it would only enlarge a hole RsR leaves open too.
TEST(RemoveUnsampledTriangles, APartlyOpenHoleKeepsItsCover) {
    const int n = 40, lo = 12, hi = 28;
    const std::vector<Vec3> p = grid_points(n, lo, hi);
    std::vector<Triangle> t = grid_triangles(p, n, lo, hi);
    t.push_back({at(p, lo, lo), at(p, hi, lo), at(p, hi, hi)});
    t.push_back({at(p, lo, lo), at(p, hi, hi), at(p, lo, hi)});
    const std::size_t before = t.size();
    EXPECT_EQ(remove_unsampled_triangles(t, p, identity(p.size()), kRank, {}), 0u);
    EXPECT_EQ(t.size(), before);
}

// A lone point inside the hole, joined to its whole outline: the overlong triangles form one
// wedge per corner, all sharing that point. At most one wedge goes, so the point keeps one fan
// (manifold) and stays a vertex.
TEST(RemoveUnsampledTriangles, ALonePointInsideStaysAManifoldVertex) {
    ClosedHole h;
    const auto inside = std::uint32_t(h.points.size());
    h.points.push_back(Vec3(20, 20, 0));
    const std::vector<std::uint32_t> ring = hole_outline(h.points, h.lo, h.hi);
    h.triangles.resize(h.grid);
    for (std::size_t i = 0; i < ring.size(); ++i)
        h.triangles.push_back({inside, ring[(i + 1) % ring.size()], ring[i]});
    const std::size_t removed =
        remove_unsampled_triangles(h.triangles, h.points, identity(h.points.size()), kRank, {});
    EXPECT_GT(removed, 0u);
    EXPECT_LT(removed, 16u); // one corner's wedge of the 64 fan triangles
    const MeshStats m = measure_mesh(h.points.size(), h.triangles);
    EXPECT_EQ(m.non_manifold_vertices, 0u);
    EXPECT_EQ(m.unreferenced_vertices, 0u);
    EXPECT_EQ(m.boundary_loops, 2u);
}

// Long, thin triangles of an anisotropic sampling (rows 5 spacings apart, points 1 apart along
// them) are within twice the bound and stay.
TEST(RemoveUnsampledTriangles, AnisotropicSamplingKeepsItsTriangles) {
    std::vector<Vec3> p;
    const int columns = 60, rows = 12;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) p.push_back(Vec3(c, 5.0 * r, 0));
    std::vector<Triangle> t;
    for (int r = 0; r + 1 < rows; ++r)
        for (int c = 0; c + 1 < columns; ++c) {
            const std::uint32_t a = std::uint32_t(r * columns + c), b = a + 1,
                                d = std::uint32_t(a + columns), e = d + 1;
            t.push_back({a, b, e});
            t.push_back({a, e, d});
        }
    const std::size_t before = t.size();
    EXPECT_EQ(remove_unsampled_triangles(t, p, identity(p.size()), kRank, {}), 0u);
    EXPECT_EQ(t.size(), before);
}

// Sixteen grids side by side (vertices and triangles over several blocks of the parallel
// loops), their triangles listed back to front: the closed holes reopen, the partly open ones
// keep their cover, and the same triangles go for 1, 2 and 8 threads.
TEST(RemoveUnsampledTriangles, AnyThreadCountRemovesTheSameTriangles) {
    std::vector<Vec3> p;
    std::vector<Triangle> t;
    const ClosedHole h;
    for (int copy = 0; copy < 16; ++copy) {
        const auto first = std::uint32_t(p.size());
        for (const Vec3& q : h.points) p.push_back(q + Vec3(50.0 * copy, 0, 0));
        // Odd copies: two triangles between the hole's corners instead of the fan.
        std::vector<Triangle> own(h.triangles.begin(),
                                  copy % 2 ? h.triangles.begin() + std::ptrdiff_t(h.grid)
                                           : h.triangles.end());
        if (copy % 2) {
            const std::uint32_t a = at(h.points, h.lo, h.lo), b = at(h.points, h.hi, h.lo),
                                c = at(h.points, h.hi, h.hi), d = at(h.points, h.lo, h.hi);
            own.insert(own.end(), {{a, b, c}, {a, c, d}});
        }
        for (const Triangle& f : own) t.push_back({f[0] + first, f[1] + first, f[2] + first});
    }
    std::reverse(t.begin(), t.end());
    ASSERT_GT(p.size(), 20000u);
    ClosedHole alone;
    const std::size_t removed_alone = remove_unsampled_triangles(
        alone.triangles, alone.points, identity(alone.points.size()), kRank, {1, nullptr});
    std::vector<Triangle> one = t;
    const std::size_t removed =
        remove_unsampled_triangles(one, p, identity(p.size()), kRank, {1, nullptr});
    EXPECT_GT(removed_alone, 40u);
    EXPECT_EQ(removed, 8 * removed_alone); // what each closed hole alone loses
    for (int threads : {2, 8}) {
        std::vector<Triangle> many = t;
        EXPECT_EQ(
            remove_unsampled_triangles(many, p, identity(p.size()), kRank, {threads, nullptr}),
            removed);
        EXPECT_EQ(many, one) << threads << " threads";
    }
}

} // namespace
} // namespace hrsr
