#include "errors.h"
#include "preprocess/pca_normals.h"
#include "preprocess/preprocess.h"
#include "samplers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace hrsr {
namespace {

struct Agreement {
    double sign_consistency;  ///< fraction of points agreeing with the majority sign
    double within_15_degrees; ///< fraction whose unsigned angle to the reference is < 15°
};

// Compares estimated normals with the reference normals of the input points they came from.
Agreement agreement(const PreparedCloud& cloud, const PointSet& reference) {
    std::size_t positive = 0, close = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        const double c =
            cloud.normals[i].dot(reference.normals[cloud.input_index.values()[i].value()]);
        if (c > 0) ++positive;
        if (std::abs(c) > std::cos(15 * M_PI / 180)) ++close;
    }
    const double n = double(cloud.size());
    return {std::max(double(positive), n - double(positive)) / n, double(close) / n};
}

PreparedCloud estimate_and_orient(const PointSet& s, DistanceMode mode, PreprocessReport& report) {
    PreprocessOptions o;
    o.distance = mode;
    return prepare_points(testing::without_normals(s), o, {}, report);
}

class OrientationOnAnalyticSurfaces : public ::testing::TestWithParam<DistanceMode> {};

TEST_P(OrientationOnAnalyticSurfaces, SphereIsConsistentUpToOneSign) {
    for (auto density : {testing::Density::Uniform, testing::Density::Graded}) {
        const PointSet s = testing::sample_sphere(20000, 2.0, Vec3(5, -3, 1), density);
        PreprocessReport report;
        const PreparedCloud c = estimate_and_orient(s, GetParam(), report);
        EXPECT_EQ(report.normal_origin, NormalOrigin::Estimated);
        EXPECT_EQ(report.orientation_components, 1u);
        const Agreement a = agreement(c, s);
        EXPECT_EQ(a.sign_consistency, 1.0);
        EXPECT_GT(a.within_15_degrees, 0.999);
        for (const Vec3& n : c.normals) ASSERT_NEAR(n.Norm(), 1.0, 1e-9);
    }
}

TEST_P(OrientationOnAnalyticSurfaces, TorusIsConsistentUpToOneSign) {
    for (auto density : {testing::Density::Uniform, testing::Density::Graded}) {
        const PointSet s = testing::sample_torus(30000, 1.0, 0.35, density);
        PreprocessReport report;
        const PreparedCloud c = estimate_and_orient(s, GetParam(), report);
        EXPECT_EQ(report.orientation_components, 1u);
        const Agreement a = agreement(c, s);
        EXPECT_EQ(a.sign_consistency, 1.0);
        EXPECT_GT(a.within_15_degrees, 0.999);
    }
}

INSTANTIATE_TEST_SUITE_P(BothDistanceModes, OrientationOnAnalyticSurfaces,
                         ::testing::Values(DistanceMode::Tangent, DistanceMode::Euclidean));

TEST(Orientation, HalfFlippedInputNormalsAreMadeConsistentWhenReestimating) {
    PointSet s = testing::sample_sphere(10000);
    const PointSet reference = s;
    for (std::size_t i = 0; i < s.size(); i += 2) s.normals[i] = -s.normals[i];
    PreprocessOptions o;
    o.normals = NormalSource::Reestimate;
    PreprocessReport report;
    const PreparedCloud c = prepare_points(s, o, {}, report);
    EXPECT_EQ(agreement(c, reference).sign_consistency, 1.0);
}

TEST(Orientation, InputNormalsAreKeptAsGiven) {
    const PointSet s = testing::sample_sphere(5000);
    PreprocessReport report;
    const PreparedCloud c = prepare_points(s, {}, {}, report);
    EXPECT_EQ(report.normal_origin, NormalOrigin::Input);
    EXPECT_EQ(report.orientation_flips, 0u);
    for (std::size_t i = 0; i < c.size(); ++i)
        ASSERT_NEAR(c.normals[i].dot(s.normals[c.input_index.values()[i].value()]), 1.0, 1e-12);
}

TEST(PcaNormals, PlaneGivesItsNormal) {
    const PointSet s = testing::sample_plane(30);
    const KnnIndex index(s.positions);
    const PcaNormals pca = estimate_normals(s.positions, index, 16, {});
    EXPECT_EQ(pca.degenerate, 0u);
    for (const Vec3& n : pca.normals) EXPECT_NEAR(std::abs(n[2]), 1.0, 1e-9);
}

TEST(PcaNormals, AutomaticNeighbourhoodFollowsD5D20AndD29) {
    EXPECT_EQ(neighbour_count(1000, 0), 16);
    EXPECT_EQ(neighbour_count(640, 0), 16); // D-29: N / 40 from here down, never below 8
    EXPECT_EQ(neighbour_count(500, 0), 12);
    EXPECT_EQ(neighbour_count(100, 0), 8);
    EXPECT_EQ(neighbour_count(8, 0), 7); // never more than the other points
    EXPECT_EQ(neighbour_count(100000, 0), 50);
    EXPECT_EQ(neighbour_count(10000000, 0), 192);
    EXPECT_EQ(neighbour_count(100000, 8), 8);
}

TEST(PcaNormals, CoarseCloudSmoothsOverTheInputsShareOfTheSurfaceD44) {
    // Below 384,000 input points the input's neighbourhood is N / 2000 points, so a coarse cloud
    // of n points spans the same share with n / 2000: D-20 as on any cloud.
    EXPECT_EQ(coarse_neighbour_count(362272, 45284, 0), neighbour_count(45284, 0));
    EXPECT_EQ(coarse_neighbour_count(384000, 48000, 0), 24);
    // Above, the input's 192 neighbours are 192 / N of its surface: the 800k and 3.2M dragon
    // samples' coarse clouds at p = 1/8 both smooth over 24 points (n / 2000 gave 50 and 192).
    EXPECT_EQ(coarse_neighbour_count(800000, 100000, 0), 24);
    EXPECT_EQ(coarse_neighbour_count(3200000, 400000, 0), 24);
    EXPECT_EQ(coarse_neighbour_count(3200000, 1600000, 0), 96);
    EXPECT_EQ(coarse_neighbour_count(20000000, 2500000, 0), 24);
    // The same clamps: never below 16, D-29 on a tiny coarse cloud, never more than the others.
    EXPECT_EQ(coarse_neighbour_count(10000000, 100000, 0), 16);
    EXPECT_EQ(coarse_neighbour_count(10000000, 500, 0), 12);
    EXPECT_EQ(coarse_neighbour_count(400000, 9, 0), 8);
    // An explicit count is the user's.
    EXPECT_EQ(coarse_neighbour_count(3200000, 400000, 100), 100);
    EXPECT_EQ(coarse_neighbour_count(3200000, 50, 100), 49);
}

TEST(PcaNormals, CollinearNeighbourhoodsCopyTheNearestValidNormal) {
    // A plane patch plus a straight line of points leaving it: the line's PCA is undefined.
    PointSet s = testing::sample_plane(20);
    for (int i = 1; i <= 30; ++i) s.positions.emplace_back(40.0 + i, 10.0, 0.0);
    const KnnIndex index(s.positions);
    const PcaNormals pca = estimate_normals(s.positions, index, 4, {});
    EXPECT_GT(pca.degenerate, 0u);
    ASSERT_EQ(pca.normals.size(), s.size());
    for (const Vec3& n : pca.normals) EXPECT_NEAR(std::abs(n[2]), 1.0, 1e-6);
}

TEST(PcaNormals, ACollinearCloudIsAClearError) {
    PointSet line;
    for (int i = 0; i < 200; ++i) line.positions.emplace_back(i, 2.0 * i, -i);
    PreprocessReport report;
    try {
        prepare_points(line, {}, {}, report);
        FAIL() << "expected InvalidInput";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("line"), std::string::npos);
    }
    EXPECT_EQ(report.count(PointFate::NoNormal), 200u);
}

} // namespace
} // namespace hrsr
