// D-28: closing the boundary loops of at most five edges of an output mesh, on hand-built meshes.
#include "mesh/mesh_stats.h"
#include "mesh/self_intersections.h"
#include "mesh/small_holes_fill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
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

// Two neighbouring vertices removed: a hole of 6 edges stays open (more than five points around
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

/// Each triangle split into four at its edges' midpoints, pushed out to the sphere through the
/// icosahedron's vertices: 42 vertices, 80 triangles, wound as before.
void subdivided_icosahedron(std::vector<Vec3>& v, std::vector<Triangle>& t) {
    icosahedron(v, t);
    const double radius = v[0].Norm();
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
        const auto key = std::minmax(a, b);
        const auto found = middle.find(key);
        if (found != middle.end()) return found->second;
        const Vec3 m = (v[a] + v[b]) / 2;
        v.push_back(m * (radius / m.Norm()));
        return middle[key] = std::uint32_t(v.size() - 1);
    };
    std::vector<Triangle> finer;
    for (const Triangle& f : t) {
        const std::uint32_t ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
        finer.insert(finer.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
    }
    t = finer;
}

/// Appends piece (points, triangles) to (v, t), its points shifted by `offset`; returns the
/// number of its first vertex.
std::uint32_t append_piece(std::vector<Vec3>& v, std::vector<Triangle>& t,
                           const std::vector<Vec3>& points, const std::vector<Triangle>& triangles,
                           const Vec3& offset) {
    const auto first = std::uint32_t(v.size());
    for (const Vec3& p : points) v.push_back(p + offset);
    for (const Triangle& f : triangles) t.push_back({f[0] + first, f[1] + first, f[2] + first});
    return first;
}

/// The vertex of `v` at `p` (to within rounding).
std::uint32_t vertex_at(const std::vector<Vec3>& v, const Vec3& p) {
    for (std::uint32_t i = 0; i < v.size(); ++i)
        if ((v[i] - p).Norm() < 1e-9) return i;
    return std::uint32_t(v.size());
}

// D-39: with SmallHoleScope::PiecesClosedButForThem a short loop is closed only on a piece whose
// every border loop is short and whose interior vertices outnumber its border vertices.
// - A: the icosahedron without vertex 0's star, closed but for a pentagon: closed.
// - B: the subdivided icosahedron without the stars of vertex 0 and of its neighbour between
//   it and vertex 1 (a 7-edge loop), and without one triangle on the far side: 30 interior
//   vertices against 10 on the border, but a long loop, so its triangle hole stays open.
// - D: the octahedron without one face, 3 border vertices and 3 interior: a scrap, open.
// Every rule matters: without either one a second loop would be closed. The default scope closes
// A's pentagon and the triangle holes of B and D.
TEST(FillSmallHoles, TheScopeClosesOnlyPiecesClosedButForShortLoops) {
    std::vector<Vec3> v, points;
    std::vector<Triangle> t, triangles;
    icosahedron(points, triangles);
    const std::uint32_t a = append_piece(v, t, points, without_star(triangles, 0), Vec3(0, 0, 0));

    subdivided_icosahedron(points, triangles);
    const Vec3 between = (points[0] + points[1]) / 2;
    const std::uint32_t neighbour =
        vertex_at(points, between * (points[0].Norm() / between.Norm()));
    ASSERT_LT(neighbour, points.size());
    triangles = without_star(without_star(triangles, 0), neighbour);
    const auto far_side = std::find_if(triangles.begin(), triangles.end(), [&](const Triangle& f) {
        return std::all_of(f.begin(), f.end(),
                           [&](std::uint32_t c) { return points[c].dot(between) < 0; });
    });
    ASSERT_NE(far_side, triangles.end());
    triangles.erase(far_side);
    const std::uint32_t b = append_piece(v, t, points, triangles, Vec3(10, 0, 0));

    const std::vector<Vec3> octahedron{{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    const std::vector<Triangle> without_one_face{{2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5},
                                                 {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    append_piece(v, t, octahedron, without_one_face, Vec3(20, 0, 0));
    const MeshStats before = measure_mesh(v.size(), t);
    ASSERT_EQ(before.boundary_edges, 5u + 7u + 3u + 3u);

    std::vector<Triangle> scoped = t;
    EXPECT_EQ(
        fill_small_holes(scoped, v, {}, kMaxFilledLoop, SmallHoleScope::PiecesClosedButForThem),
        1u);
    EXPECT_EQ(measure_mesh(v.size(), scoped).boundary_edges, before.boundary_edges - 5);
    for (std::size_t i = t.size(); i < scoped.size(); ++i)
        for (std::uint32_t corner : scoped[i]) EXPECT_TRUE(corner >= a && corner < b); // on A

    EXPECT_EQ(fill_small_holes(t, v), 3u);
    EXPECT_EQ(measure_mesh(v.size(), t).boundary_edges, 7u);
}

/// The surface of the cube [0, n]³, each face an n × n grid of unit squares cut into two
/// triangles along the same diagonal, wound outwards; vertices shared along the cube's edges.
void grid_cube(int n, std::vector<Vec3>& v, std::vector<Triangle>& t) {
    std::map<std::tuple<int, int, int>, std::uint32_t> index;
    auto vertex = [&](int x, int y, int z) {
        const auto [it, added] = index.emplace(std::make_tuple(x, y, z), std::uint32_t(v.size()));
        if (added) v.emplace_back(x, y, z);
        return it->second;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side <= n; side += n)
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    std::uint32_t q[4];
                    const int di[4] = {0, 1, 1, 0}, dj[4] = {0, 0, 1, 1};
                    for (int c = 0; c < 4; ++c) {
                        int p[3];
                        p[axis] = side;
                        p[(axis + 1) % 3] = i + di[c];
                        p[(axis + 2) % 3] = j + dj[c];
                        q[c] = vertex(p[0], p[1], p[2]);
                    }
                    // (axis+1, axis+2) is counter-clockwise seen from +axis.
                    if (side == n) {
                        t.push_back({q[0], q[1], q[2]});
                        t.push_back({q[0], q[2], q[3]});
                    } else {
                        t.push_back({q[0], q[2], q[1]});
                        t.push_back({q[0], q[3], q[2]});
                    }
                }
}

/// Points on a grid of spacing 1/`per_unit` over the surface of the cube [0, n]³, those strictly
/// inside the box (lo, hi) left out.
std::vector<Vec3> cube_samples(int n, int per_unit, const Vec3& lo, const Vec3& hi) {
    std::vector<Vec3> out;
    const int m = n * per_unit;
    for (int x = 0; x <= m; ++x)
        for (int y = 0; y <= m; ++y)
            for (int z = 0; z <= m; ++z) {
                if (x != 0 && x != m && y != 0 && y != m && z != 0 && z != m) continue;
                const Vec3 p(double(x) / per_unit, double(y) / per_unit, double(z) / per_unit);
                const bool inside = p[0] > lo[0] && p[0] < hi[0] && p[1] > lo[1] && p[1] < hi[1] &&
                                    p[2] > lo[2] && p[2] < hi[2];
                if (!inside) out.push_back(p);
            }
    return out;
}

// D-53: a loop longer than the scope's pinholes counts as one when it lies over sampled surface.
// A cube of side 4 (grids of unit squares) without the stars of two neighbouring vertices of its
// top face (an 8-edge loop) and without one triangle of its bottom face, sampled on a grid four
// times finer: closed but for these two loops, so both are filled, however long the longer
// loops may be. With no sample inside the 8-edge hole (a hole in the data) the piece is open and
// keeps both; so it does when the longer loops may have 7 edges at most.
TEST(FillSmallHoles, ALongerLoopOverSampledSurfaceIsAPinholeToo) {
    std::vector<Vec3> v;
    std::vector<Triangle> t;
    grid_cube(4, v, t);
    const std::uint32_t a = vertex_at(v, Vec3(1, 2, 4)), b = vertex_at(v, Vec3(2, 2, 4));
    ASSERT_LT(std::max(a, b), v.size());
    t = without_star(without_star(t, a), b);
    const auto bottom = std::find_if(t.begin(), t.end(), [&](const Triangle& f) {
        return v[f[0]][2] == 0 && v[f[1]][2] == 0 && v[f[2]][2] == 0;
    });
    ASSERT_NE(bottom, t.end());
    t.erase(bottom);
    ASSERT_EQ(measure_mesh(v.size(), t).boundary_edges, 8u + 3u);
    const int rank = 4;

    const std::vector<Vec3> everywhere = cube_samples(4, 4, Vec3(9, 9, 9), Vec3(9, 9, 9));
    for (std::size_t longest : {std::size_t(8), std::size_t(20)}) {
        std::vector<Triangle> sampled = t;
        EXPECT_EQ(fill_small_holes(sampled, v, {}, kMaxFilledLoop,
                                   SmallHoleScope::PiecesClosedButForThem, {1, nullptr},
                                   {longest, &everywhere, rank}),
                  2u);
        expect_closed_sphere(v, sampled);
        EXPECT_TRUE(self_intersecting_pairs(v, sampled, {}).empty());
    }
    // The 8-edge loop lies in the box (0, 1)–(3, 3) of the top face (z = 4).
    const std::vector<Vec3> around_a_hole = cube_samples(4, 4, Vec3(0, 1, 3.5), Vec3(3, 3, 4.5));
    std::vector<Triangle> kept = t;
    EXPECT_EQ(fill_small_holes(kept, v, {}, kMaxFilledLoop, SmallHoleScope::PiecesClosedButForThem,
                               {1, nullptr}, {20, &around_a_hole, rank}),
              0u);
    EXPECT_EQ(fill_small_holes(kept, v, {}, kMaxFilledLoop, SmallHoleScope::PiecesClosedButForThem,
                               {1, nullptr}, {7, &everywhere, rank}),
              0u);
    EXPECT_EQ(kept, t);

    // The same hole on the face x = 0 too, both sampled but for the top one: the piece has a
    // border that is no pinhole, so neither long loop is filled (nor the triangle hole).
    const std::uint32_t c = vertex_at(v, Vec3(0, 1, 2)), d = vertex_at(v, Vec3(0, 2, 2));
    ASSERT_LT(std::max(c, d), v.size());
    std::vector<Triangle> two = without_star(without_star(t, c), d);
    const std::vector<Triangle> before = two;
    EXPECT_EQ(fill_small_holes(two, v, {}, kMaxFilledLoop, SmallHoleScope::PiecesClosedButForThem,
                               {1, nullptr}, {20, &around_a_hole, rank}),
              0u);
    EXPECT_EQ(two, before);
    // Sampled everywhere, both long loops and the triangle hole are filled.
    EXPECT_EQ(fill_small_holes(two, v, {}, kMaxFilledLoop, SmallHoleScope::PiecesClosedButForThem,
                               {1, nullptr}, {20, &everywhere, rank}),
              3u);
    expect_closed_sphere(v, two);
}

// Thousands of pieces (vertices and triangles over several blocks of the parallel loops), their
// triangles listed back to front: a triangle hole and a pentagon (closed), a pentagon pierced by
// a triangle (every fan crosses the mesh: open), a 6-edge loop (open) and an octahedron without
// a face (closed by the default scope only). The same mesh for 1, 2 and 8 threads.
TEST(FillSmallHoles, AnyThreadCountClosesTheSameHoles) {
    std::vector<Vec3> icosahedron_points,
        octahedron_points{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::vector<Triangle> full,
        octahedron{{2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    icosahedron(icosahedron_points, full);
    std::vector<Triangle> without_one = full;
    without_one.erase(without_one.begin() + 7);
    std::vector<Vec3> pierced_points = icosahedron_points;
    std::vector<Triangle> pierced = without_star(full, 0);
    const Vec3 axis = pierced_points[0] / pierced_points[0].Norm();
    const Vec3 side = (axis ^ Vec3(0, 0, 1)) / (axis ^ Vec3(0, 0, 1)).Norm();
    pierced_points.insert(pierced_points.end(),
                          {axis * 0.2 - side * 0.05, axis * 0.2 + side * 0.05, axis * 3.0});
    pierced.push_back({12, 13, 14});

    std::vector<Vec3> v;
    std::vector<Triangle> t;
    std::size_t closable = 0, closable_in_scope = 0;
    for (int piece = 0; piece < 4000; ++piece) {
        const Vec3 offset(8.0 * (piece % 64), 8.0 * (piece / 64), 0);
        switch (piece % 5) {
        case 0:
            append_piece(v, t, icosahedron_points, without_one, offset);
            break;
        case 1:
            append_piece(v, t, icosahedron_points, without_star(full, 0), offset);
            break;
        case 2:
            append_piece(v, t, pierced_points, pierced, offset);
            break;
        case 3:
            append_piece(v, t, icosahedron_points, without_star(without_star(full, 0), 1), offset);
            break;
        default:
            append_piece(v, t, octahedron_points, octahedron, offset);
        }
        closable += piece % 5 == 0 || piece % 5 == 1 || piece % 5 == 4;
        closable_in_scope += piece % 5 == 0 || piece % 5 == 1;
    }
    std::reverse(t.begin(), t.end());
    ASSERT_GT(v.size(), 40000u);

    for (SmallHoleScope scope : {SmallHoleScope::Every, SmallHoleScope::PiecesClosedButForThem}) {
        std::vector<Triangle> one = t;
        const std::size_t closed = fill_small_holes(one, v, {}, kMaxFilledLoop, scope);
        EXPECT_EQ(closed, scope == SmallHoleScope::Every ? closable : closable_in_scope);
        for (int threads : {2, 8}) {
            std::vector<Triangle> many = t;
            EXPECT_EQ(fill_small_holes(many, v, {}, kMaxFilledLoop, scope, {threads, nullptr}),
                      closed);
            EXPECT_EQ(many, one) << threads << " threads";
        }
    }
}

} // namespace
} // namespace hrsr
