// Issue 7, item 1: degenerate clouds through the core (both methods). Each gives a clear error
// naming the problem or a correct trivial result; never a crash, a hang or an empty mesh.
#include "fold_fates.h"
#include "mesh/self_intersections.h"
#include "robustness.h"
#include "samplers.h"

#include <gtest/gtest.h>

#include <limits>

namespace hrsr {
namespace {

using testing::attempt;
using testing::Attempt;
using testing::expect_closed;
using testing::expect_error;
using testing::kMethods;
using testing::name;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

PointSet points(std::initializer_list<Vec3> positions, bool normals) {
    PointSet s;
    for (const Vec3& p : positions) {
        s.positions.push_back(p);
        if (normals) s.normals.emplace_back(0, 0, 1);
    }
    return s;
}

PointSet sphere() {
    return testing::sample_sphere(3000);
}

TEST(DegenerateClouds, EmptyCloud) {
    for (Method m : kMethods)
        expect_error(attempt(PointSet{}, m), Attempt::BadInput, "the point cloud is empty",
                     name(m));
}

TEST(DegenerateClouds, OneAndTwoPointsNameTheProblem) {
    const Vec3 a(0, 0, 0), b(1, 0, 0);
    for (Method m : kMethods) {
        expect_error(attempt(points({a}, true), m), Attempt::BadInput, "from the 1 usable points",
                     name(m));
        expect_error(attempt(points({a, b}, true), m), Attempt::BadInput,
                     "from the 2 usable points", name(m));
        // Without normals the first problem is that none can be estimated.
        expect_error(attempt(points({a, b}, false), m), Attempt::BadInput,
                     "at least 3 are needed to estimate normals", name(m));
    }
}

// Three points close into the two sides of a triangle, and four coplanar ones into the two sides
// of a square. Two faces on the same three corners cover each other (a pair, as CGAL counts a
// face and its reverse; session 17), so D-32 cuts one and a single triangle is left, every point
// a vertex. The two sides of a square overlap unless both take the same diagonal: D-32 then takes
// a corner out and, since filling its hole would repeat the other side's face, one triangle is
// left; the corner lies flat on it, against its normal, and goes back across its edge (D-60): a
// square of two triangles, every point a vertex. No intersecting pair is ever written.
TEST(DegenerateClouds, ThreeOrFourCoplanarPointsGiveAPolygon) {
    for (bool normals : {true, false})
        for (Method m : kMethods) {
            const PointSet three = points({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, normals);
            const Attempt a = attempt(three, m);
            expect_valid_mesh(a, three, name(m));
            EXPECT_EQ(a.report.mesh.faces, 1u) << name(m);
            EXPECT_EQ(a.report.mesh.vertices, 3u) << name(m);
            EXPECT_EQ(a.report.mesh.boundary_edges, 3u) << name(m);
            EXPECT_TRUE(a.report.dropped_fold.empty()) << name(m);
            const PointSet four = points({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, normals);
            const Attempt b = attempt(four, m);
            expect_valid_mesh(b, four, name(m));
            EXPECT_TRUE(b.report.dropped_fold.empty()) << name(m);
            EXPECT_EQ(b.report.mesh.vertices, 4u) << name(m);
            if (b.report.mesh.faces == 4u) {
                expect_closed(b, four, 0, 4, name(m));
            } else {
                EXPECT_EQ(b.report.mesh.faces, 2u) << name(m);
                EXPECT_EQ(b.report.mesh.boundary_edges, 4u) << name(m);
                EXPECT_EQ(b.report.mesh.components.size(), 1u) << name(m);
            }
            std::vector<Vec3> positions;
            for (std::uint32_t i : b.mesh.vertex_input_index)
                positions.push_back(four.positions[i]);
            EXPECT_TRUE(self_intersecting_pairs(positions, b.mesh.triangles, {}).empty());
        }
}

TEST(DegenerateClouds, AllPointsIdentical) {
    PointSet same;
    for (int i = 0; i < 500; ++i) {
        same.positions.emplace_back(1, 2, 3);
        same.normals.emplace_back(0, 0, 1);
    }
    for (Method m : kMethods) {
        expect_error(attempt(same, m), Attempt::BadInput, "from the 1 usable points", name(m));
        expect_error(attempt(testing::without_normals(same), m), Attempt::BadInput,
                     "only 1 distinct point", name(m));
    }
}

TEST(DegenerateClouds, EveryPointDuplicatedGivesTheSameMesh) {
    const PointSet once = sphere();
    PointSet twice = once;
    testing::append(twice, once);
    for (Method m : kMethods) {
        const Attempt a = attempt(once, m), b = attempt(twice, m);
        expect_closed(b, twice, 0, 3000, name(m));
        EXPECT_TRUE(testing::same_connectivity(a.mesh, b.mesh)) << name(m);
        EXPECT_EQ(b.report.preprocess.count(PointFate::Duplicate), 3000u);
        EXPECT_EQ(b.report.vertex_reference_ratio, 1.0); // duplicates share their vertex
    }
}

// Regression (D-25): a sphere with every point doubled 1e-12 x the diagonal away came out of
// RsR as 566 pieces with 4,637 boundary edges. Such near-duplicates are now merged like exact
// ones; from 1e-10 x the diagonal on they are points of their own, and the sphere stays closed.
TEST(DegenerateClouds, NearDuplicates) {
    const PointSet once = sphere();
    const double diagonal = 2 * std::sqrt(3.0); // the sphere's bounding box, to a few %
    for (double distance : {1e-13, 1e-12, 1e-10}) {
        const bool merged = distance < 1e-11;
        PointSet twice = once;
        for (std::size_t i = 0; i < once.size(); ++i) {
            twice.positions.push_back(once.positions[i] + Vec3(distance * diagonal, 0, 0));
            twice.normals.push_back(once.normals[i]);
        }
        for (bool normals : {true, false})
            for (Method m : kMethods) {
                const PointSet& in = normals ? twice : testing::without_normals(twice);
                const Attempt a = attempt(in, m);
                const std::string context = std::string(name(m)) + " at " +
                                            std::to_string(distance) +
                                            (normals ? "" : " without normals");
                // Every point a vertex but those D-32 takes out of folds (fold_fates.h).
                std::size_t folds = 0; // distinct points: a merged duplicate shares its fate
                for (std::uint32_t i : a.report.dropped_fold)
                    folds += a.report.preprocess.fate[i] != PointFate::Duplicate;
                expect_closed(a, in, 0, (merged ? 3000 : 6000) - folds, context);
                EXPECT_EQ(a.report.preprocess.count(PointFate::Duplicate), merged ? 3000u : 0u)
                    << context;
                EXPECT_EQ(a.has_warning("bounding-box diagonal to another point"), merged);
                testing::expect_r_v(a.report, 1.0, context);
            }
    }
}

TEST(DegenerateClouds, NonFiniteCoordinatesAreDroppedAndCounted) {
    const PointSet clean = sphere();
    PointSet dirty = clean;
    const std::vector<Vec3> bad{{kNan, 0, 0}, {kInf, 0, 0}, {0, -kInf, 0}, {0, 0, kNan}};
    for (const Vec3& p : bad) {
        dirty.positions.push_back(p);
        dirty.normals.emplace_back(0, 0, 1);
    }
    for (Method m : kMethods) {
        const Attempt a = attempt(dirty, m), b = attempt(clean, m);
        expect_closed(a, dirty, 0, 3000, name(m));
        EXPECT_EQ(a.report.preprocess.count(PointFate::NonFinite), 4u);
        EXPECT_TRUE(testing::same_connectivity(a.mesh, b.mesh)) << name(m);
        expect_error(attempt(points({{kNan, 0, 0}, {0, kInf, 0}}, true), m), Attempt::BadInput,
                     "none of the 2 points has finite coordinates", name(m));
    }
}

// Unusable input normals (NaN, ±Inf, zero) make the whole cloud's normals estimated, with a
// warning; non-unit ones are normalised and change nothing.
TEST(DegenerateClouds, UnusableOrNonUnitNormals) {
    const PointSet clean = sphere();
    std::vector<std::pair<Vec3, std::string>> cases{{Vec3(kNan, 0, 0), "1 non-finite"},
                                                    {Vec3(0, kInf, 0), "1 non-finite"},
                                                    {Vec3(0, 0, -kInf), "1 non-finite"},
                                                    {Vec3(0, 0, 0), "1 zero-length"}};
    for (Method m : kMethods) {
        for (const auto& [normal, warning] : cases) {
            PointSet s = clean;
            s.normals[17] = normal;
            const Attempt a = attempt(s, m);
            expect_closed(a, s, 0, 3000, name(m));
            EXPECT_EQ(a.report.preprocess.normal_origin, NormalOrigin::Estimated);
            EXPECT_TRUE(a.has_warning(warning)) << warning;
        }
        PointSet scaled = clean;
        for (std::size_t i = 0; i < scaled.size(); ++i) scaled.normals[i] *= 0.5 + double(i % 7);
        const Attempt a = attempt(scaled, m), b = attempt(clean, m);
        expect_closed(a, scaled, 0, 3000, name(m));
        EXPECT_GT(a.report.preprocess.normals_renormalised, 2000u);
        EXPECT_EQ(a.report.mesh.faces, b.report.mesh.faces) << name(m);
    }
}

TEST(DegenerateClouds, NormalCountDifferentFromPointsFallsBackToEstimation) {
    PointSet s = sphere();
    s.normals.resize(100);
    for (Method m : kMethods) {
        const Attempt a = attempt(s, m);
        expect_closed(a, s, 0, 3000, name(m));
        EXPECT_TRUE(a.has_warning("100 normals for 3000 points"));
    }
}

TEST(DegenerateClouds, CollinearCloud) {
    PointSet line;
    for (int i = 0; i < 300; ++i) {
        line.positions.emplace_back(0.01 * i, 0.02 * i, 0);
        line.normals.emplace_back(0, 0, 1);
    }
    for (Method m : kMethods) {
        expect_error(attempt(line, m), Attempt::BadInput, "no triangle could be built", name(m));
        expect_error(attempt(testing::without_normals(line), m), Attempt::BadInput,
                     "lie on one line", name(m));
    }
}

} // namespace
} // namespace hrsr
