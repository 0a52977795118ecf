// Issue 7, item 1: the result does not depend on where the cloud is or on its units (D-2).
#include "robustness.h"
#include "samplers.h"

#include <gtest/gtest.h>

namespace hrsr {
namespace {

using testing::attempt;
using testing::Attempt;
using testing::expect_closed;
using testing::kMethods;
using testing::name;
using testing::same_connectivity;

PointSet moved(const PointSet& s, double scale, const Vec3& offset) {
    PointSet t = s;
    for (Vec3& p : t.positions) p = p * scale + offset;
    return t;
}

class Transforms : public ::testing::TestWithParam<bool> {
protected:
    PointSet torus() const {
        const PointSet t = testing::sample_torus(3000);
        return GetParam() ? t : testing::without_normals(t);
    }
};

// Offsets of 1e6 and 5e6 keep every coordinate's relative precision well above the spacing:
// identical connectivity. Scales by powers of ten change only rounding: identical too.
TEST_P(Transforms, OffsetsAndScalesGiveTheSameConnectivity) {
    const PointSet base = torus();
    for (Method m : kMethods) {
        const Attempt reference = attempt(base, m);
        testing::expect_valid_mesh(reference, base, name(m));
        for (double offset : {1e6, 5e6}) {
            const PointSet t = moved(base, 1.0, Vec3(offset, -offset, offset));
            EXPECT_TRUE(same_connectivity(attempt(t, m).mesh, reference.mesh))
                << name(m) << " offset " << offset;
        }
        for (double scale : {1e-9, 1e9}) {
            const PointSet t = moved(base, scale, Vec3(0, 0, 0));
            EXPECT_TRUE(same_connectivity(attempt(t, m).mesh, reference.mesh))
                << name(m) << " scale " << scale;
        }
    }
}

// At an offset of 1e12 a double keeps steps of 1.2e-4 (2e-3 of the spacing here): adding the
// offset moves the points, so the cloud itself differs from the unshifted one and so may the
// connectivity (measured: it does). What must hold: the shifted cloud gives exactly the mesh of
// the same representable points shifted back (x + 1e12 − 1e12 is exact), and a closed torus.
TEST_P(Transforms, AtOffset1e12TheMeshIsThatOfTheRoundedPoints) {
    const PointSet base = torus();
    const Vec3 offset(1e12, -1e12, 1e12);
    const PointSet far = moved(base, 1.0, offset);
    const PointSet rounded = moved(far, 1.0, -offset);
    for (Method m : kMethods) {
        const Attempt a = attempt(far, m), b = attempt(rounded, m);
        testing::expect_valid_mesh(a, far, name(m));
        EXPECT_EQ(a.report.mesh.vertices, 3000u);
        EXPECT_TRUE(same_connectivity(a.mesh, b.mesh)) << name(m);
    }
}

// (HRsR on 3,000 torus points leaves a slit, README "known gaps" 3: only RsR is closed here.)
TEST_P(Transforms, RsrClosesTheTorusAtEveryOffsetAndScale) {
    const PointSet base = torus();
    for (double offset : {0.0, 1e6, 5e6, 1e12})
        for (double scale : {1.0, 1e-9, 1e9}) {
            if (offset > 0 && scale != 1.0) continue;
            const PointSet t = moved(base, scale, Vec3(offset, -offset, offset));
            expect_closed(attempt(t, Method::Rsr), t, 1, 3000,
                          "offset " + std::to_string(offset) + " scale " + std::to_string(scale));
        }
}

INSTANTIATE_TEST_SUITE_P(Robustness, Transforms, ::testing::Bool(), [](const auto& param_info) {
    return param_info.param ? "with_normals" : "without_normals";
});

} // namespace
} // namespace hrsr
