#include "preprocess/preprocess.h"
#include "samplers.h"

#include <gtest/gtest.h>

namespace hrsr {
namespace {

PreparedCloud run(const PointSet& s, DistanceMode mode, int threads, PreprocessReport& report) {
    PreprocessOptions o;
    o.distance = mode;
    Execution exec;
    exec.threads = threads;
    return preprocess(s, o, exec, report);
}

TEST(Determinism, SameResultForOneAndTwoThreads) {
    PointSet s =
        testing::without_normals(testing::sample_torus(20000, 1.0, 0.3, testing::Density::Graded));
    testing::append(s, testing::without_normals(testing::sample_sphere(50, 0.01, Vec3(9, 9, 9))));
    for (DistanceMode mode : {DistanceMode::Tangent, DistanceMode::Euclidean}) {
        PreprocessReport r1, r2;
        const PreparedCloud a = run(s, mode, 1, r1);
        const PreparedCloud b = run(s, mode, 2, r2);
        ASSERT_EQ(a.input_index, b.input_index);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            ASSERT_EQ(a.normals[i], b.normals[i]) << i; // bit-identical
            ASSERT_EQ(a.smoothed[i], b.smoothed[i]) << i;
        }
        EXPECT_EQ(r1.fate, r2.fate);
        EXPECT_EQ(r1.orientation_flips, r2.orientation_flips);
        EXPECT_EQ(r1.cut_length, r2.cut_length);
        EXPECT_EQ(r1.smoothing_mean_shift, r2.smoothing_mean_shift);
    }
}

} // namespace
} // namespace hrsr
