// Issue 7, item 1: option values at and beyond their limits, through reconstruct() for both
// methods: an InvalidOption naming the option, or a documented result.
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

const PointSet& small_sphere() {
    static const PointSet s = testing::sample_sphere(150);
    return s;
}

void expect_option_error(const ReconstructionOptions& o, const std::string& option) {
    for (Method m : kMethods)
        expect_error(attempt(small_sphere(), m, o), Attempt::BadOption, option + " must",
                     std::string(name(m)) + ", " + option);
}

TEST(OptionEdges, KBelowThreeOrAboveTheLimitIsRejected) {
    for (int k : {0, 1, 2, 1001, -5}) {
        ReconstructionOptions o;
        o.rsr.preprocess.k = k;
        expect_option_error(o, "k");
    }
}

// k = N − 1, N or more than N: the neighbourhoods are every other point; same mesh.
TEST(OptionEdges, KAtOrAboveThePointCountIsClampedToTheOtherPoints) {
    const std::size_t n = small_sphere().size();
    for (Method m : kMethods) {
        ReconstructionOptions o;
        o.rsr.preprocess.k = int(n) - 1;
        const Attempt reference = attempt(small_sphere(), m, o);
        expect_closed(reference, small_sphere(), 0, n, name(m));
        for (int k : {int(n), int(n) + 1, 1000}) {
            o.rsr.preprocess.k = k;
            const Attempt a = attempt(small_sphere(), m, o);
            expect_closed(a, small_sphere(), 0, n, name(m));
            EXPECT_TRUE(testing::same_connectivity(a.mesh, reference.mesh)) << name(m) << k;
        }
    }
}

// Checked for both methods (reconstruct() validates every option, even one RsR does not use).
TEST(OptionEdges, CollapseRatioOutsideZeroOneIsRejected) {
    for (double ratio : {0.0, -0.1, 1.5, std::numeric_limits<double>::quiet_NaN(),
                         std::numeric_limits<double>::infinity()}) {
        ReconstructionOptions o;
        o.collapse.collapse_ratio = ratio;
        expect_option_error(o, "collapse_ratio");
    }
}

TEST(OptionEdges, CollapseRatioOneCollapsesNothing) {
    const PointSet s = testing::sample_sphere(1000);
    ReconstructionOptions o;
    o.collapse.collapse_ratio = 1.0;
    const Attempt a = attempt(s, Method::Hrsr, o);
    expect_closed(a, s, 0, 1000, "hrsr");
    EXPECT_EQ(a.report.coarse_points, 1000u);
    EXPECT_EQ(a.report.reexpansion.records, 0u);
}

TEST(OptionEdges, NegativeOrNonFiniteLMinIsRejected) {
    for (double l : {-1.0, -1e-300, std::numeric_limits<double>::quiet_NaN()}) {
        ReconstructionOptions o;
        o.reexpand.l_min = l;
        expect_option_error(o, "l_min");
    }
    for (double percent : {-1.0, 100.5}) {
        ReconstructionOptions o;
        o.l_min_percent = percent;
        expect_option_error(o, "l_min");
    }
}

// l_min longer than the diagonal: no split is replayed; the coarse mesh, snapped to input
// points, is the result (the coarsest level of detail), still closed.
TEST(OptionEdges, LMinLongerThanTheDiagonalGivesTheCoarseMesh) {
    const PointSet s = testing::sample_sphere(6000);
    ReconstructionOptions o;
    o.reexpand.l_min = 100.0; // the diagonal is about 3.5
    const Attempt a = attempt(s, Method::Hrsr, o);
    expect_closed(a, s, 0, a.report.coarse_points, "hrsr");
    EXPECT_EQ(a.report.coarse_points, 750u); // 12.5 %
    EXPECT_TRUE(a.report.reexpansion.stopped_at_l_min);
    EXPECT_EQ(a.report.reexpansion.replayed, 0u);
    o.l_min_percent = 100.0;
    o.reexpand.l_min = 0;
    expect_closed(attempt(s, Method::Hrsr, o), s, 0, 750u, "hrsr, 100%");
}

TEST(OptionEdges, HandlesBelowMinusOneIsRejected) {
    for (int h : {-2, -100}) {
        ReconstructionOptions o;
        o.rsr.handles = h;
        expect_option_error(o, "handles");
    }
}

} // namespace
} // namespace hrsr
