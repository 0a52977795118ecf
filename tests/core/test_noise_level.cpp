// D-33: the noise measure that decides whether HRsR works on smoothed positions.
#include "knn.h"
#include "options.h"
#include "preprocess/noise_level.h"
#include "samplers.h"

#include <gtest/gtest.h>

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

} // namespace
} // namespace hrsr
