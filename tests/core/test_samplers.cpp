// The analytic test clouds hold the points they are asked for, graded or not: the topology
// grid's sizes (5k … 1M) and the tests' names speak of those counts.
#include "samplers.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace hrsr {
namespace {

using testing::Density;

TEST(Samplers, EveryShapeHoldsAboutTheCountAskedForUniformOrGraded) {
    for (const char* shape : {"sphere", "torus", "double_torus", "triple_torus"})
        for (Density density : {Density::Uniform, Density::Graded})
            for (std::size_t n : {5000u, 20000u}) {
                const PointSet s = testing::sample_surface(shape, n, density);
                SCOPED_TRACE(std::string(shape) + (density == Density::Graded ? " graded " : " ") +
                             std::to_string(n));
                ASSERT_EQ(s.positions.size(), s.normals.size());
                // The multi-torus thins to an expected count (±2 %); its grading draws at random.
                EXPECT_NEAR(double(s.size()), double(n), 0.04 * double(n));
            }
}

TEST(Samplers, GradedMultiTorusThinsOutAlongX) {
    // Acceptance falls from 1 to 0.1 along x: the first third of the extent holds several times
    // the points of the last third (the uniform cloud holds about as many in both).
    for (Density density : {Density::Uniform, Density::Graded}) {
        const PointSet s = testing::sample_multi_torus(20000, 2, density);
        const double extent = 1.2 + 1.0 + 0.4;
        std::array<std::size_t, 2> ends{0, 0};
        for (const Vec3& p : s.positions) {
            if (p[0] < -extent / 3) ++ends[0];
            if (p[0] > extent / 3) ++ends[1];
        }
        const double ratio = double(ends[0]) / double(ends[1]);
        if (density == Density::Uniform)
            EXPECT_NEAR(ratio, 1.0, 0.1);
        else
            EXPECT_GT(ratio, 3.0);
    }
}

} // namespace
} // namespace hrsr
