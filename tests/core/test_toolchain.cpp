// Guards against compiler defects that would silently change our numbers.
#include "point_set.h"

#include <gtest/gtest.h>

namespace hrsr {
namespace {

// Not inlined, so the loop is compiled on its own, as in the code where it was found.
__attribute__((noinline)) void round_to_float(Vec3& v) {
    for (int k = 0; k < 3; ++k) v[k] = double(static_cast<float>(v[k]));
}

// GCC 12.2 -O2 with SLP vectorisation compiled round_to_float() as if only v[2] were
// rounded. CMakeLists.txt disables SLP vectorisation for GCC; this test fails without it.
TEST(Toolchain, FloatRoundingInAVectorisableLoopIsNotElided) {
    volatile double x = 0.9999887491194096, y = 0.0047435887889324029;
    Vec3 v(x, y, 0.1);
    round_to_float(v);
    EXPECT_EQ(v[0], double(static_cast<float>(x)));
    EXPECT_EQ(v[1], double(static_cast<float>(y)));
    EXPECT_EQ(v[2], double(static_cast<float>(0.1)));
}

} // namespace
} // namespace hrsr
