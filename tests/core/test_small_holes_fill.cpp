// D-28: closing the boundary loops of at most five edges of an output mesh, on hand-built meshes.
#include "mesh/mesh_stats.h"
#include "mesh/self_intersections.h"
#include "mesh/small_holes_fill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hrsr {
namespace {

/// The regular icosahedron: 12 vertices, 20 triangles wound counter-clockwise from outside;
/// every vertex has degree 5.
void icosahedron(std::vector<Vec3>& v, std::vector<Triangle>& t) {
    const double g = (1 + std::sqrt(5.0)) / 2;
    v = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    t = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
         {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
         {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
}

/// Removes every triangle around vertex `centre` (a hole as long as its degree).
std::vector<Triangle> without_star(const std::vector<Triangle>& t, std::uint32_t centre) {
    std::vector<Triangle> out;
    for (const Triangle& f : t)
        if (f[0] != centre && f[1] != centre && f[2] != centre) out.push_back(f);
    return out;
}

void expect_closed_sphere(const std::vector<Vec3>& v, const std::vector<Triangle>& t) {
    const MeshStats m = measure_mesh(v.size(), t);
    EXPECT_EQ(m.boundary_edges, 0u);
    EXPECT_EQ(m.non_manifold_edges, 0u);
    EXPECT_EQ(m.non_manifold_vertices, 0u);
    EXPECT_EQ(m.inconsistently_oriented_edges, 0u);
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_EQ(m.components[0].genus(), 0);
}

TEST(FillSmallHoles, TheIcosahedronIsClosedAsItIs) {
    std::vector<Vec3> v;
    std::vector<Triangle> t;
    icosahedron(v, t);
    expect_closed_sphere(v, t);
    EXPECT_EQ(fill_small_holes(t, v), 0u);
    EXPECT_EQ(t.size(), 20u);
}

TEST(FillSmallHoles, ATriangleHoleIsClosed) {
    std::vector<Vec3> v;
    std::vector<Triangle> t;
    icosahedron(v, t);
    t.erase(t.begin() + 7);
    EXPECT_EQ(fill_small_holes(t, v), 1u);
    EXPECT_EQ(t.size(), 20u);
    expect_closed_sphere(v, t);
}

// Vertex 0 removed with its five triangles: a pentagon, closed by three triangles (the vertex
// stays unreferenced), coherently wound and without self-intersection.
TEST(FillSmallHoles, APentagonHoleIsClosedByAFan) {
    std::vector<Vec3> v;
    std::vector<Triangle> t;
    icosahedron(v, t);
    t = without_star(t, 0);
    ASSERT_EQ(measure_mesh(v.size(), t).boundary_edges, 5u);
    EXPECT_EQ(fill_small_holes(t, v), 1u);
    EXPECT_EQ(t.size(), 18u);
    expect_closed_sphere(v, t);
    EXPECT_TRUE(self_intersecting_pairs(v, t, {}).empty());
}

// Two neighbouring vertices removed: a hole of 8 edges stays open (more than five points around
// it is a hole in the data), and so does a pentagon when max_edges is 4.
TEST(FillSmallHoles, LargerLoopsStayOpen) {
    std::vector<Vec3> v;
    std::vector<Triangle> t;
    icosahedron(v, t);
    t = without_star(without_star(t, 0), 1);
    const std::size_t before = t.size();
    EXPECT_EQ(fill_small_holes(t, v), 0u);
    EXPECT_EQ(t.size(), before);

    icosahedron(v, t);
    t = without_star(t, 0);
    EXPECT_EQ(fill_small_holes(t, v, {}, 4), 0u);
}

// A lone triangle's outline is a 3-loop, but closing it would double the triangle.
TEST(FillSmallHoles, ALoneTriangleStaysOpen) {
    const std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    std::vector<Triangle> t{{0, 1, 2}};
    EXPECT_EQ(fill_small_holes(t, v), 0u);
    EXPECT_EQ(t.size(), 1u);
}

// A separate triangle pierces the pentagon hole: every fan would intersect it, so the hole
// stays open rather than gain a fold.
TEST(FillSmallHoles, AFillThatWouldIntersectTheMeshIsNotMade) {
    std::vector<Vec3> v;
    std::vector<Triangle> t;
    icosahedron(v, t);
    t = without_star(t, 0);
    // The hole lies around the axis from the centre through vertex 0; a thin triangle along
    // that axis crosses every triangulation of it.
    const Vec3 axis = v[0] / v[0].Norm();
    const Vec3 side = (axis ^ Vec3(0, 0, 1)) / (axis ^ Vec3(0, 0, 1)).Norm();
    const auto first = std::uint32_t(v.size());
    v.push_back(axis * 0.2 - side * 0.05);
    v.push_back(axis * 0.2 + side * 0.05);
    v.push_back(axis * 3.0);
    t.push_back({first, first + 1, first + 2});
    EXPECT_EQ(fill_small_holes(t, v), 0u);
    EXPECT_EQ(measure_mesh(v.size(), t).boundary_edges, 5u + 3u);
}

// D-39: with SmallHoleScope::PiecesClosedButForThem a short loop is closed only on a piece whose
// every border loop is short. Piece A (vertex 0's star removed) is closed but for a pentagon;
// piece B (vertices 0 and 1 removed, and one triangle far from them) has a long loop as well, so
// its triangle hole stays open, which the default scope closes.
TEST(FillSmallHoles, TheScopeLeavesPiecesWithALongerBorderOpen) {
    std::vector<Vec3> a_points, b_points;
    std::vector<Triangle> a, b;
    icosahedron(a_points, a);
    icosahedron(b_points, b);
    a = without_star(a, 0);
    b = without_star(without_star(b, 0), 1);
    const Triangle far_from_the_hole{3, 2, 6};
    b.erase(std::find(b.begin(), b.end(), far_from_the_hole));
    std::vector<Vec3> v = a_points;
    std::vector<Triangle> t = a;
    const auto shift = std::uint32_t(v.size());
    for (const Vec3& p : b_points) v.push_back(p + Vec3(10, 0, 0));
    for (const Triangle& f : b) t.push_back({f[0] + shift, f[1] + shift, f[2] + shift});
    const std::size_t border = measure_mesh(v.size(), t).boundary_edges;

    std::vector<Triangle> scoped = t;
    EXPECT_EQ(
        fill_small_holes(scoped, v, {}, kMaxFilledLoop, SmallHoleScope::PiecesClosedButForThem),
        1u);
    EXPECT_EQ(measure_mesh(v.size(), scoped).boundary_edges, border - 5);
    for (std::size_t i = t.size(); i < scoped.size(); ++i)
        for (std::uint32_t corner : scoped[i]) EXPECT_LT(corner, shift); // on piece A

    EXPECT_EQ(fill_small_holes(t, v), 2u);
    EXPECT_EQ(measure_mesh(v.size(), t).boundary_edges, border - 5 - 3);
}

} // namespace
} // namespace hrsr
