// D-33: the noise measure that decides whether HRsR works on smoothed positions.
#include "knn.h"
#include "options.h"
#include "preprocess/noise_level.h"
#include "preprocess/smoothing.h"
#include "samplers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace hrsr {
namespace {

double noise_of(const PointSet& cloud, int threads = 0) {
    const KnnIndex index(cloud.positions);
    return relative_noise(cloud.positions, cloud.normals, index, Execution{threads, nullptr});
}

PointSet noisy_sphere(std::size_t points, double percent_of_diagonal) {
    PointSet s = testing::sample_sphere(points);
    testing::add_noise(s, percent_of_diagonal / 100.0 * testing::bounding_box_diagonal(s));
    return s;
}

// A quadric follows a clean surface's curvature, also on a coarse sample of a small sphere and
// on the torus's saddles: what is left is far below the threshold.
TEST(RelativeNoise, CleanSurfacesMeasureAlmostNothing) {
    EXPECT_LT(noise_of(testing::sample_sphere(20000)), 0.02);
    EXPECT_LT(noise_of(testing::sample_sphere(1000)), 0.02);
    EXPECT_LT(noise_of(testing::sample_torus(20000)), 0.02);
}

// σ in spacings: at 20k points on the unit sphere the spacing is about 0.025, so 0.1 % of the
// diagonal (3.46) is 0.14 spacings and 0.5 % is 0.7.
TEST(RelativeNoise, GrowsWithTheNoiseAndCrossesTheThresholdBetween) {
    const double low = noise_of(noisy_sphere(20000, 0.1));
    const double high = noise_of(noisy_sphere(20000, 0.5));
    EXPECT_LT(low, constants::kNoisyCloud);
    EXPECT_GT(high, constants::kNoisyCloud);
    EXPECT_GT(high, 2 * low);
}

// The measure does not depend on the normals' signs (estimated normals are measured before
// their orientation) nor on the thread count.
TEST(RelativeNoise, IgnoresNormalSignsAndThreadCount) {
    PointSet s = noisy_sphere(5000, 0.5);
    const double one_thread = noise_of(s, 1);
    EXPECT_EQ(noise_of(s, 2), one_thread);
    EXPECT_EQ(noise_of(s, 8), one_thread);
    for (std::size_t i = 0; i < s.normals.size(); i += 2) s.normals[i] = -s.normals[i];
    EXPECT_EQ(noise_of(s, 1), one_thread);
}

// Under 1,000 points the measure says nothing, however noisy the cloud.
TEST(RelativeNoise, SmallCloudsMeasureZero) {
    EXPECT_EQ(noise_of(noisy_sphere(999, 1.0)), 0.0);
    EXPECT_EQ(noise_of(testing::sample_sphere(10)), 0.0);
}

// D-33 with input normals: noise moves points along the sphere too, so an exact normal is the
// sphere's normal where the point was sampled, not where it lies. The average over a smoothing
// neighbourhood is closer to the sphere's normal where it lies: half the error.
double mean_angle_to_radial(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals) {
    double sum = 0;
    for (std::size_t i = 0; i < positions.size(); ++i)
        sum += std::acos(std::clamp(normals[i].dot(positions[i] / positions[i].Norm()), -1.0, 1.0));
    return sum / double(positions.size());
}

TEST(AveragedNormals, FollowTheNoisySurfaceWhereThePointsLie) {
    const PointSet s = noisy_sphere(20000, 0.5);
    const KnnIndex index(s.positions);
    const std::vector<Vec3> averaged = averaged_normals(s.normals, index, 16, {});
    const double before = mean_angle_to_radial(s.positions, s.normals);
    const double after = mean_angle_to_radial(s.positions, averaged);
    EXPECT_GT(before, 0.015);       // 1.2°: the noise is 0.7 spacings
    EXPECT_LT(after, 0.6 * before); // measured: 0.47 × before
}

// Two sheets of a thin part, a third of a spacing apart and facing away from each other: each
// point's average takes in its own sheet only, so exact normals stay exact.
TEST(AveragedNormals, LeaveOutTheOtherSideOfAThinPart) {
    PointSet s = testing::sample_plane(30);
    PointSet other = testing::sample_plane(30, 1.0, 7);
    for (Vec3& p : other.positions) p[2] = 0.3;
    for (Vec3& n : other.normals) n = Vec3(0, 0, -1);
    testing::append(s, other);
    const KnnIndex index(s.positions);
    const std::vector<Vec3> averaged = averaged_normals(s.normals, index, 32, {});
    for (std::size_t i = 0; i < s.size(); ++i)
        ASSERT_NEAR((averaged[i] - s.normals[i]).Norm(), 0.0, 1e-12) << i;
}

TEST(AveragedNormals, DoNotDependOnTheThreadCount) {
    const PointSet s = noisy_sphere(5000, 0.5);
    const KnnIndex index(s.positions);
    const std::vector<Vec3> one = averaged_normals(s.normals, index, 16, Execution{1, nullptr});
    EXPECT_EQ(averaged_normals(s.normals, index, 16, Execution{2, nullptr}), one);
    EXPECT_EQ(averaged_normals(s.normals, index, 16, Execution{8, nullptr}), one);
}

} // namespace
} // namespace hrsr
