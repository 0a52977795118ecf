// The exact pair test of self_intersections.h: orientation predicates, each case of CGAL's rule,
// configurations where a double evaluation is wrong, and folded meshes.
#include "mesh/exact_predicates.h"
#include "mesh/self_intersections.h"
#include "mesh/triangle_against_faces.h"
#include "mesh/triangle_grid.h"
#include "mesh/triangle_intersection.h"

#include "fold_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace hrsr {
namespace {

using testing::TestMesh;

bool intersect(const Corners& a, const Triangle& ia, const Corners& b, const Triangle& ib) {
    const bool result = mesh_triangles_intersect(a, ia, b, ib);
    EXPECT_EQ(mesh_triangles_intersect(b, ib, a, ia), result) << "not symmetric";
    return result;
}

// Triangles with no shared vertex: ids 0-2 and 3-5.
bool apart_intersect(const Corners& a, const Corners& b) {
    return intersect(a, {0, 1, 2}, b, {3, 4, 5});
}

const Corners kUnit{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};

TEST(ExactPredicates, SignsFollowTheRightHand) {
    EXPECT_EQ(exact::orient3d(kUnit[0], kUnit[1], kUnit[2], Vec3(0.2, 0.2, 1)), 1);
    EXPECT_EQ(exact::orient3d(kUnit[0], kUnit[1], kUnit[2], Vec3(0.2, 0.2, -1)), -1);
    EXPECT_EQ(exact::orient3d(kUnit[0], kUnit[1], kUnit[2], Vec3(5, -7, 0)), 0);
    EXPECT_EQ(exact::orient2d(kUnit[0], kUnit[1], kUnit[2], 0, 1), 1);
    EXPECT_EQ(exact::orient2d(kUnit[0], kUnit[1], kUnit[2], 1, 0), -1);
    EXPECT_TRUE(exact::collinear(Vec3(1, 2, 3), Vec3(2, 4, 6), Vec3(-1, -2, -3)));
    EXPECT_TRUE(exact::collinear(Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(7, 0, 1)));
    EXPECT_FALSE(exact::collinear(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1e-300, 0)));
}

TEST(ExactPredicates, ExtremeExponentsAreExact) {
    // The filter cannot decide these (no permanent, or one that may have underflowed).
    const Vec3 o(0, 0, 0), far(1e300, 0, 0), near(0, 1e-300, 0);
    EXPECT_EQ(exact::orient3d(o, far, near, Vec3(3e299, 5e-301, 0)), 0);
    EXPECT_EQ(exact::orient3d(o, far, near, Vec3(3e299, 5e-301, 1e-320)), 1); // subnormal
    EXPECT_EQ(exact::orient3d(o, far, near, Vec3(-3e299, 5e-301, -1e-320)), -1);
    EXPECT_EQ(exact::orient2d(o, far, Vec3(-1e-320, 4e-320, 0), 0, 1), 1);
    EXPECT_EQ(
        exact::orient2d(Vec3(1, 1, 0), Vec3(1 + 0x1p-52, 1, 0), Vec3(1, 1 - 0x1p-52, 0), 0, 1), -1);
}

TEST(ExactPredicates, CoplanarFloatsAreCoplanarWhereDoublesSayNot) {
    const std::array<Vec3, 4> p = testing::coplanar_float_points();
    const double in_doubles = ((p[1] - p[0]) ^ (p[2] - p[0])).dot(p[3] - p[0]);
    EXPECT_NE(in_doubles, 0.0); // rounding: the fixture's point
    EXPECT_EQ(exact::orient3d(p[0], p[1], p[2], p[3]), 0);
    EXPECT_EQ(exact::orient3d(p[3], p[0], p[1], p[2]), 0);
    // One float step off the plane, either way.
    const Vec3 up(p[3][0], p[3][1], double(std::nextafter(float(p[3][2]), 1e9f)));
    const Vec3 down(p[3][0], p[3][1], double(std::nextafter(float(p[3][2]), -1e9f)));
    EXPECT_EQ(exact::orient3d(p[0], p[1], p[2], up), -exact::orient3d(p[0], p[1], p[2], down));
    EXPECT_NE(exact::orient3d(p[0], p[1], p[2], up), 0);
}

// Points for the filters' tests: uniform, on a coarse integer grid (exact zeros), nearly on
// the plane of the first three (rounded), and of extreme exponents.
std::vector<Vec3> filter_test_points(std::mt19937& random, int kind, std::size_t n) {
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> grid(-2, 2);
    std::vector<Vec3> p;
    for (std::size_t i = 0; i < n; ++i) {
        if (kind == 0) p.emplace_back(unit(random), unit(random), unit(random));
        if (kind == 1) p.emplace_back(grid(random), grid(random), grid(random));
        if (kind == 2) {
            if (i < 3) {
                p.emplace_back(unit(random), unit(random), unit(random));
                continue;
            }
            const double s = unit(random), t = unit(random);
            const Vec3 q = p[0] + (p[1] - p[0]) * s + (p[2] - p[0]) * t;
            p.emplace_back(float(q[0]), float(q[1]), float(q[2]) + grid(random) * 1e-12);
        }
        if (kind == 3)
            p.emplace_back(std::ldexp(unit(random), grid(random) * 500),
                           std::ldexp(unit(random), grid(random) * 500), unit(random) * 1e-310);
    }
    return p;
}

TEST(ExactPredicates, PlaneSidesDecideAsOrient3d) {
    std::mt19937 random(5);
    for (int kind = 0; kind < 4; ++kind) {
        std::size_t decided = 0, tested = 0;
        for (int plane = 0; plane < 200; ++plane) {
            const std::vector<Vec3> p = filter_test_points(random, kind, 53);
            const exact::PlaneSides sides(p[0], p[1], p[2]);
            for (std::size_t i = 0; i < p.size(); ++i) {
                const int side = sides.side(p[i]);
                ++tested;
                if (side == 2) continue;
                ++decided;
                ASSERT_EQ(side, exact::orient3d(p[0], p[1], p[2], p[i]))
                    << "kind " << kind << ", plane " << plane << ", point " << i;
            }
        }
        // Never deciding would pass the check above: the filter must decide most of the
        // uniform cases (the plane's own corners are exact zeros it may leave undecided).
        if (kind == 0) {
            EXPECT_GT(double(decided) / double(tested), 0.9);
        }
    }
}

TEST(TriangleIntersection, OneTriangleAgainstManyAnswersAsThePairTest) {
    // Triangles on a small grid of points, sharing corners often, against every other.
    std::mt19937 random(3);
    std::size_t intersecting = 0, beside = 0;
    for (int kind : {0, 1, 2}) {
        const std::vector<Vec3> points = filter_test_points(random, kind, 12);
        std::uniform_int_distribution<std::uint32_t> corner(0, 11);
        std::vector<Triangle> triangles;
        while (triangles.size() < 300) {
            const Triangle t{corner(random), corner(random), corner(random)};
            if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) triangles.push_back(t);
        }
        const TriangleGeometry g(points, triangles);
        for (const Triangle& t : triangles) {
            if (g.degenerate(t)) continue;
            const TriangleAgainstFaces against(g, t);
            for (const Triangle& b : triangles) {
                if (g.degenerate(b)) continue;
                const bool expected = g.intersect_unboxed(t, b);
                ASSERT_EQ(against.intersects(b), expected);
                (expected ? intersecting : beside) += 1;
            }
        }
    }
    EXPECT_GT(intersecting, 1000U);
    EXPECT_GT(beside, 1000U);
}

TEST(TriangleIntersection, ApartTrianglesThatTouchAtAPointIntersect) {
    const Corners touching{Vec3(0.25, 0.25, 0), Vec3(0, 0, 1), Vec3(1, 1, 1)};
    EXPECT_TRUE(apart_intersect(kUnit, touching));
    Corners lifted = touching;
    lifted[0][2] = 1e-300;
    EXPECT_FALSE(apart_intersect(kUnit, lifted));
    const Corners at_corner{Vec3(1, 0, 0), Vec3(2, 0, 1), Vec3(2, 1, 1)}; // a copy of a corner
    EXPECT_TRUE(apart_intersect(kUnit, at_corner));
}

TEST(TriangleIntersection, ApartTrianglesAlongAnEdgeIntersect) {
    EXPECT_TRUE(apart_intersect(kUnit, {Vec3(0.2, 0, 0), Vec3(0.6, 0, 0), Vec3(0.4, 0, 1)}));
    EXPECT_TRUE(apart_intersect(kUnit, {Vec3(0.2, 0, 0), Vec3(0.6, 0, 0), Vec3(0.4, -1, 0)}));
    EXPECT_FALSE(apart_intersect(kUnit, {Vec3(1.2, 0, 0), Vec3(1.6, 0, 0), Vec3(1.4, 0, 1)}));
}

TEST(TriangleIntersection, CoplanarApartTrianglesIntersectWhenTheyOverlap) {
    EXPECT_TRUE(apart_intersect(kUnit, {Vec3(0.1, 0.1, 0), Vec3(0.2, 0.1, 0), Vec3(0.1, 0.2, 0)}));
    EXPECT_TRUE(apart_intersect(kUnit, {Vec3(-1, 0.2, 0), Vec3(2, 0.2, 0), Vec3(0.5, 5, 0)}));
    EXPECT_FALSE(apart_intersect(kUnit, {Vec3(1, 1, 0), Vec3(2, 1, 0), Vec3(1, 2, 0)}));
}

TEST(TriangleIntersection, ASharedVertexAloneIsNoIntersection) {
    const Triangle ia{0, 1, 2}, ib{0, 3, 4};
    // Fan neighbours, a sharp dihedral, and a triangle touching only at the vertex.
    EXPECT_FALSE(intersect(kUnit, ia, {kUnit[0], Vec3(0, 1, 0.1), Vec3(-1, 0, 0)}, ib));
    EXPECT_FALSE(intersect(kUnit, ia, {kUnit[0], Vec3(0.5, 0.5, 0.01), Vec3(0, 0.5, 1)}, ib));
    EXPECT_FALSE(intersect(kUnit, ia, {kUnit[0], Vec3(-1, -1, 0), Vec3(-1, -2, 3)}, ib));
}

TEST(TriangleIntersection, ASharedVertexAndAnyOtherContactIsAnIntersection) {
    const Triangle ia{0, 1, 2}, ib{0, 3, 4};
    // b's far edge crosses a; b inside a's wedge in a's plane; b's far corner on a's edge.
    EXPECT_TRUE(intersect(kUnit, ia, {kUnit[0], Vec3(0.3, 0.3, -1), Vec3(0.3, 0.3, 1)}, ib));
    EXPECT_TRUE(intersect(kUnit, ia, {kUnit[0], Vec3(0.2, 0.1, 0), Vec3(0.1, 0.2, 0)}, ib));
    EXPECT_TRUE(intersect(kUnit, ia, {kUnit[0], Vec3(0.5, 0.5, 0), Vec3(1, 1, 1)}, ib));
}

TEST(TriangleIntersection, ASharedEdgeIntersectsWhenFoldedFlat) {
    const Triangle ia{0, 1, 2}, ib{1, 0, 3};
    EXPECT_FALSE(intersect(kUnit, ia, {kUnit[1], kUnit[0], Vec3(0.5, -1, 0)}, ib));   // flat
    EXPECT_FALSE(intersect(kUnit, ia, {kUnit[1], kUnit[0], Vec3(0.5, 1, 0.01)}, ib)); // sharp
    EXPECT_TRUE(intersect(kUnit, ia, {kUnit[1], kUnit[0], Vec3(0.5, 1, 0)}, ib));     // folded
    EXPECT_TRUE(intersect(kUnit, ia, {kUnit[1], kUnit[0], Vec3(0.1, 0.1, 0)}, ib));   // inside
}

TEST(TriangleIntersection, ADuplicateCoversItsTwin) {
    EXPECT_TRUE(intersect(kUnit, {0, 1, 2}, kUnit, {2, 1, 0}));
}

TEST(TriangleIntersection, FloatCoordinatesAreDecidedExactly) {
    const TestMesh fold = testing::flat_fold_on_floats();
    EXPECT_EQ(self_intersecting_pairs(fold.positions, fold.triangles, {}),
              std::vector<TrianglePair>{TrianglePair(0, 1)});
    TestMesh touch = testing::touching_on_floats();
    EXPECT_EQ(self_intersecting_pairs(touch.positions, touch.triangles, {}).size(), 1u);
    // One float step up: on the side of the other corners, no contact.
    touch.positions[3][2] = double(std::nextafter(float(touch.positions[3][2]), 1e9f));
    EXPECT_TRUE(self_intersecting_pairs(touch.positions, touch.triangles, {}).empty());
}

TEST(TriangleIntersection, FoldedFixturesHaveTheirPairs) {
    for (const TestMesh& m :
         {testing::pushed_vertex(), testing::crossing_sheets(), testing::boundary_fold()}) {
        const std::vector<TrianglePair> pairs =
            self_intersecting_pairs(m.positions, m.triangles, {});
        EXPECT_GE(pairs.size(), 2u);
        EXPECT_EQ(self_intersecting_pairs(m.positions, m.triangles, {1, nullptr}), pairs);
    }
}

TEST(TriangleIntersection, CopiesAtOnePositionAreOneVertexUnlessByIndex) {
    TestMesh m; // two fans sharing one point through two vertex copies
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0),    Vec3(0, 1, 0),
                   Vec3(0, 0, 0), Vec3(-1, 0, 0.5), Vec3(0, -1, 0.5)};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    EXPECT_TRUE(self_intersecting_pairs(m.positions, m.triangles, {}).empty());
    EXPECT_EQ(intersecting_pairs_by_index(m.positions, m.triangles, {}).size(), 1u);
}

} // namespace
} // namespace hrsr
