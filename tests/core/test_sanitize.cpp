#include "errors.h"
#include "options.h"
#include "preprocess/near_duplicates.h"
#include "preprocess/sanitize.h"
#include "samplers.h"
#include "spatial_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace hrsr {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Sanitize, DropsAndCountsNonFinitePoints) {
    PointSet s = testing::sample_sphere(100);
    s.positions[3] = Vec3(kNaN, 0, 0);
    s.positions[10] = Vec3(0, kInf, 0);
    s.positions[11] = Vec3(0, 0, -kInf);
    PreprocessReport report;
    const SanitizedCloud c = sanitize(s, {}, report);
    EXPECT_EQ(report.count(PointFate::NonFinite), 3u);
    EXPECT_EQ(report.fate[3], PointFate::NonFinite);
    EXPECT_EQ(c.positions.size(), 97u);
    EXPECT_EQ(c.input_index.size(), 97u);
    EXPECT_FALSE(report.warnings.empty());
    // Normals of the finite points are still used.
    EXPECT_EQ(report.normal_origin, NormalOrigin::Input);
    EXPECT_EQ(c.normals.size(), 97u);
}

TEST(Sanitize, MergesExactDuplicatesIntoTheFirstOccurrence) {
    PointSet s = testing::sample_sphere(50);
    s.positions.push_back(s.positions[7]); // 50
    s.normals.push_back(s.normals[7]);
    s.positions.push_back(s.positions[7]); // 51
    s.normals.push_back(s.normals[7]);
    s.positions.insert(s.positions.begin(), s.positions[20]); // 0 duplicates old 20, now 21
    s.normals.insert(s.normals.begin(), s.normals[20]);
    PreprocessReport report;
    const SanitizedCloud c = sanitize(s, {}, report);
    EXPECT_EQ(report.count(PointFate::Duplicate), 3u);
    EXPECT_EQ(report.fate[0], PointFate::Kept); // first occurrence represents
    EXPECT_EQ(report.fate[21], PointFate::Duplicate);
    EXPECT_EQ(report.duplicate_of[21], 0u);
    EXPECT_EQ(report.duplicate_of[51], 8u); // old index 7 shifted by one
    EXPECT_EQ(report.duplicate_of[52], 8u);
    EXPECT_EQ(c.positions.size(), 50u);
    for (std::size_t a = 1; a < c.input_index.size(); ++a)
        EXPECT_LT(c.input_index.values()[a - 1], c.input_index.values()[a]);
}

TEST(Sanitize, NormalisesToUnitDiagonalAroundTheBoxCentre) {
    PointSet s;
    s.positions = {{1e12, 1e12, 1e12}, {1e12 + 3, 1e12, 1e12}, {1e12, 1e12 + 4, 1e12}};
    PreprocessReport report;
    const SanitizedCloud c = sanitize(s, {}, report);
    EXPECT_DOUBLE_EQ(report.bbox_diagonal, 5.0);
    EXPECT_NEAR(c.positions[0][0], -0.3, 1e-12);
    EXPECT_NEAR(c.positions[1][0], 0.3, 1e-12);
    EXPECT_NEAR(c.positions[2][1], 0.4, 1e-12);
}

TEST(Sanitize, EmptyOrAllInvalidIsAnError) {
    PreprocessReport report;
    EXPECT_THROW(sanitize(PointSet{}, {}, report), InvalidInput);
    PointSet s;
    s.positions = {{kNaN, 0, 0}, {0, kInf, 0}};
    EXPECT_THROW(sanitize(s, {}, report), InvalidInput);
}

TEST(Sanitize, UnusableNormalsFallBackToEstimationWithAWarning) {
    PreprocessReport report;
    PointSet mismatched = testing::sample_sphere(100);
    mismatched.normals.pop_back();
    SanitizedCloud c = sanitize(mismatched, {}, report);
    EXPECT_EQ(report.normal_origin, NormalOrigin::Estimated);
    EXPECT_NE(report.normals_fallback_reason.find("99 normals for 100 points"), std::string::npos);
    EXPECT_TRUE(c.normals.empty());
    EXPECT_FALSE(report.warnings.empty());

    for (Vec3 bad : {Vec3(0, 0, 0), Vec3(kNaN, 0, 1), Vec3(0, kInf, 0)}) {
        PointSet s = testing::sample_sphere(100);
        s.normals[42] = bad;
        PreprocessReport r;
        c = sanitize(s, {}, r);
        EXPECT_EQ(r.normal_origin, NormalOrigin::Estimated);
        EXPECT_TRUE(c.normals.empty());
    }
}

TEST(Sanitize, NonUnitNormalsAreNormalisedAndCounted) {
    PointSet s = testing::sample_sphere(100);
    s.normals[1] *= 3.0;
    s.normals[2] *= 1e-6;
    PreprocessReport report;
    const SanitizedCloud c = sanitize(s, {}, report);
    EXPECT_EQ(report.normals_renormalised, 2u);
    for (const Vec3& n : c.normals) EXPECT_NEAR(n.Norm(), 1.0, 1e-12);
}

TEST(Sanitize, ReestimateIgnoresInputNormals) {
    PreprocessOptions o;
    o.normals = NormalSource::Reestimate;
    PreprocessReport report;
    const SanitizedCloud c = sanitize(testing::sample_sphere(100), o, report);
    EXPECT_EQ(report.normal_origin, NormalOrigin::Estimated);
    EXPECT_TRUE(c.normals.empty());
    EXPECT_TRUE(report.warnings.empty());
}

// The grid search looks at 8 of the 27 neighbouring cells; the greedy answer must be the one of
// an exhaustive search: each point's representative is the smallest earlier representative
// within the tolerance, or itself. Points sit at exactly the tolerance, just inside and just
// outside it, along every axis and diagonal, around cell corners and the middles of cells.
TEST(NearDuplicates, GridSearchAgreesWithExhaustiveSearch) {
    const double tolerance = 0.25;
    std::mt19937 random(7);
    std::uniform_int_distribution<int> grid(-6, 6);
    std::uniform_int_distribution<int> pick(0, 7);
    std::uniform_real_distribution<double> jitter(-1, 1);
    const double offsets[] = {0.0,
                              tolerance,
                              tolerance * (1 - 1e-12),
                              tolerance * (1 + 1e-12),
                              tolerance / std::sqrt(3.0),
                              0.5 * tolerance,
                              1e-9,
                              0.999 * tolerance};
    std::vector<Vec3> points;
    for (int k = 0; k < 3000; ++k) {
        // Anchors on multiples of half a cell (corners and middles of the 2 x tolerance grid).
        const Vec3 anchor(grid(random) * tolerance, grid(random) * tolerance,
                          grid(random) * tolerance);
        Vec3 direction(jitter(random), jitter(random), jitter(random));
        if (k % 3 == 0) direction = Vec3(k % 2 ? 1 : -1, 0, 0); // along an axis
        if (direction.Norm() == 0) direction = Vec3(1, 0, 0);
        points.push_back(anchor + direction / direction.Norm() * offsets[pick(random)]);
    }
    const std::vector<std::uint32_t> fast = near_duplicate_representatives(points, tolerance);
    std::vector<std::uint32_t> exhaustive(points.size());
    std::size_t merged = 0;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        exhaustive[i] = i;
        for (std::uint32_t r = 0; r < i; ++r)
            if (exhaustive[r] == r &&
                (points[r] - points[i]).SquaredNorm() <= tolerance * tolerance) {
                exhaustive[i] = r;
                ++merged;
                break;
            }
    }
    EXPECT_EQ(fast, exhaustive);
    EXPECT_GT(merged, 1000u); // the case is not vacuous
    EXPECT_LT(merged, points.size() - 500);
}

// The same at the real tolerance (1e-11 in normalised units), where p / width is no longer
// exact: points a few ulps from a cell's middle, on both signs, with partners at about the
// tolerance along an axis and a diagonal (the last distances the test accepts and the first it
// rejects both occur).
TEST(NearDuplicates, GridSearchIsExactAtTheRealTolerance) {
    const double tolerance = constants::kNearDuplicateDistance, width = 2 * tolerance;
    std::mt19937 random(11);
    std::uniform_real_distribution<double> where(0.2, 0.5);
    std::uniform_int_distribution<int> ulps(-3, 3), sign(0, 1);
    auto nudge = [&](double x) {
        for (int k = ulps(random); k != 0; k += k > 0 ? -1 : 1)
            x = std::nextafter(x, k > 0 ? 1.0 : -1.0);
        return x;
    };
    std::vector<Vec3> points;
    for (int cluster = 0; cluster < 300; ++cluster) {
        Vec3 p;
        for (int axis = 0; axis < 3; ++axis) {
            const double x = (sign(random) ? -1 : 1) * where(random);
            p[axis] = nudge((std::floor(x / width) + 0.5) * width); // near a cell's middle
        }
        points.push_back(p);
        const int axis = cluster % 3;
        Vec3 q = p;
        q[axis] = nudge(p[axis] + (cluster % 2 ? tolerance : -tolerance));
        points.push_back(q);
        const double d = tolerance / std::sqrt(3.0);
        points.push_back(Vec3(nudge(p[0] + d), nudge(p[1] - d), nudge(p[2] + d)));
    }
    const std::vector<std::uint32_t> fast = near_duplicate_representatives(points, tolerance);
    std::vector<std::uint32_t> exhaustive(points.size());
    std::size_t merged = 0;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        exhaustive[i] = i;
        for (std::uint32_t r = 0; r < i && exhaustive[i] == i; ++r)
            if (exhaustive[r] == r &&
                (points[r] - points[i]).SquaredNorm() <= tolerance * tolerance)
                exhaustive[i] = r;
        merged += exhaustive[i] != i;
    }
    EXPECT_EQ(fast, exhaustive);
    EXPECT_GT(merged, 100u); // both outcomes occur
    EXPECT_LT(merged, 500u);
}

// The representatives of every point, found by brute force along a sort by x (for clouds too
// large to compare all pairs).
std::vector<std::uint32_t> representatives_by_sweep(const std::vector<Vec3>& points,
                                                    double tolerance) {
    std::vector<std::uint32_t> by_x(points.size()), representative(points.size());
    for (std::uint32_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
    std::sort(by_x.begin(), by_x.end(),
              [&](std::uint32_t a, std::uint32_t b) { return points[a][0] < points[b][0]; });
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        representative[i] = i;
        const auto first =
            std::lower_bound(by_x.begin(), by_x.end(), points[i][0] - tolerance,
                             [&](std::uint32_t a, double x) { return points[a][0] < x; });
        for (auto r = first; r != by_x.end() && points[*r][0] <= points[i][0] + tolerance; ++r)
            if (*r < representative[i] && representative[*r] == *r &&
                (points[*r] - points[i]).SquaredNorm() <= tolerance * tolerance)
                representative[i] = *r;
    }
    return representative;
}

// The parallel screen (near_screen.h) keeps every pair within the tolerance, also across the
// faces of its cells (a million tolerances wide) and at their corners: 40,000 points, a fifth
// of them paired at just under or just over the tolerance across a face, at 1, 2 and 8 threads.
TEST(NearDuplicates, ScreenedSearchIsExactAcrossTheScreensCells) {
    const double tolerance = constants::kNearDuplicateDistance, face = 1e6 * tolerance;
    std::mt19937 random(5);
    std::uniform_real_distribution<double> where(-0.5, 0.5), off(-2, 2);
    std::uniform_int_distribution<int> pick(0, 3);
    std::vector<Vec3> points;
    while (points.size() < 40000) {
        Vec3 p(where(random), where(random), where(random));
        points.push_back(p);
        if (points.size() % 5 != 0) continue;
        const int axes = 1 + pick(random) % 3; // a face, an edge or a corner of a cell
        Vec3 q = p;
        for (int axis = 0; axis < axes; ++axis) {
            p[axis] = std::round(p[axis] / face) * face + off(random) * tolerance;
            const double step =
                tolerance / std::sqrt(double(axes)) * (pick(random) < 2 ? 0.999 : 1.001);
            q[axis] = p[axis] + (p[axis] < std::round(p[axis] / face) * face ? step : -step);
        }
        points.back() = p;
        points.push_back(q);
    }
    const std::vector<std::uint32_t> expected = representatives_by_sweep(points, tolerance);
    std::size_t merged = 0;
    for (std::uint32_t i = 0; i < expected.size(); ++i) merged += expected[i] != i;
    EXPECT_GT(merged, 1000u);
    EXPECT_LT(merged, 7000u);
    for (int threads : {1, 2, 8})
        EXPECT_EQ(near_duplicate_representatives(points, tolerance, {threads, nullptr}), expected)
            << threads << " threads";
}

// The exact duplicates are found by a parallel sort (issue 20): 200,000 points, every tenth
// repeating an earlier one and every 25th 1e-13 off one (D-25 merges it at 1e-11 of the diagonal)
// give the same fates, representatives and cloud for any thread count.
// n points in [-1, 1]³ (normals up); every `copy_every`-th is a copy of a random earlier point,
// else every `shifted_every`-th such a copy moved by `shift`.
PointSet cloud_with_copies(std::size_t n, unsigned seed, std::size_t copy_every,
                           std::size_t shifted_every, const Vec3& shift) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> where(-1, 1);
    PointSet s;
    for (std::size_t i = 0; i < n; ++i) {
        std::uniform_int_distribution<std::size_t> earlier(0, i == 0 ? 0 : i - 1);
        if (i % copy_every == copy_every - 1)
            s.positions.push_back(s.positions[earlier(random)]);
        else if (i % shifted_every == shifted_every - 1)
            s.positions.push_back(s.positions[earlier(random)] + shift);
        else
            s.positions.emplace_back(where(random), where(random), where(random));
        s.normals.emplace_back(0, 0, 1);
    }
    return s;
}

TEST(Sanitize, AnyThreadCountMergesTheSameDuplicates) {
    const PointSet s = cloud_with_copies(200000, 24, 10, 25, Vec3(1e-13, 0, 0));
    PreprocessReport one;
    const SanitizedCloud first = sanitize(s, {}, one);
    EXPECT_EQ(one.count(PointFate::Duplicate), 200000u / 10 + 200000u / 25 - 200000u / 50);
    for (int threads : {2, 8}) {
        PreprocessReport many;
        const SanitizedCloud c = sanitize(s, {}, many, {threads, nullptr});
        EXPECT_EQ(many.fate, one.fate) << threads;
        EXPECT_EQ(many.duplicate_of, one.duplicate_of) << threads;
        EXPECT_EQ(many.warnings, one.warnings) << threads;
        EXPECT_EQ(c.input_index.values(), first.input_index.values()) << threads;
        EXPECT_EQ(c.positions, first.positions) << threads;
        EXPECT_EQ(c.normals, first.normals) << threads;
    }
}

// D-40: in spatial order the duplicates are found by one pass over neighbours; the same fates,
// representatives and cloud as the sort of every point gives, with copies of points far apart in
// the input, signed zeros and non-finite points among them.
TEST(Sanitize, SpatialOrderMergesTheDuplicatesTheSortMerges) {
    // Copies, and points made non-finite (a NaN shift), among random points.
    PointSet input =
        cloud_with_copies(50000, 28, 7, 101, Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0));
    input.positions[10] = Vec3(0.0, 0.5, 0.25);
    input.positions[20] = Vec3(-0.0, 0.5, 0.25); // equal to point 10
    const PointSet ordered = reordered(input, spatial_order(input.positions, {}));
    PreprocessReport sorted, scanned;
    const SanitizedCloud a = sanitize(ordered, {}, sorted, {2, nullptr}, InputOrder::Any);
    const SanitizedCloud b = sanitize(ordered, {}, scanned, {2, nullptr}, InputOrder::Spatial);
    EXPECT_GT(sorted.count(PointFate::Duplicate), 6000u); // copies of NaN are not duplicates
    EXPECT_EQ(scanned.fate, sorted.fate);
    EXPECT_EQ(scanned.duplicate_of, sorted.duplicate_of);
    EXPECT_EQ(scanned.warnings, sorted.warnings);
    EXPECT_EQ(b.input_index.values(), a.input_index.values());
    EXPECT_EQ(b.positions, a.positions);
}

} // namespace
} // namespace hrsr
