#include "errors.h"
#include "preprocess/components.h"
#include "preprocess/preprocess.h"
#include "samplers.h"

#include <gtest/gtest.h>

namespace hrsr {
namespace {

// A small flat patch of `side`² points with spacing 0.01 at `offset`, normals (0, 0, z_sign).
PointSet patch(std::size_t side, const Vec3& offset, double z_sign = 1.0) {
    PointSet p = testing::sample_plane(side, 0.01);
    for (Vec3& q : p.positions) q += offset;
    for (Vec3& n : p.normals) n *= z_sign;
    return p;
}

TEST(Components, AFarOutlierClusterIsRemovedByTheRCut) {
    PointSet s = testing::sample_sphere(8000);
    // Above the north pole and below the south pole, with normals that agree with the
    // nearest sphere points: only their length separates them (the r cut, not the normal filter).
    testing::append(s, patch(6, Vec3(0, 0, 40)));
    testing::append(s, patch(2, Vec3(0, 0, -30), -1.0));
    PreprocessReport report;
    const PreparedCloud c = preprocess(s, {}, {}, report);
    EXPECT_EQ(c.size(), 8000u);
    EXPECT_EQ(report.count(PointFate::SmallComponent), 40u);
    for (std::size_t i = 8000; i < s.size(); ++i)
        EXPECT_EQ(report.fate[i], PointFate::SmallComponent);
    EXPECT_EQ(report.components_kept, 1u);
    EXPECT_EQ(report.components_dropped, 2u);
    EXPECT_GT(report.edges_cut, 0u);
    EXPECT_GT(report.cut_length, 0.0);
    EXPECT_LT(report.cut_length, 20.0);
}

TEST(Components, TwoLargeSeparatedObjectsAreBothKept) {
    PointSet s = testing::sample_sphere(6000);
    testing::append(s, testing::sample_torus(6000));
    for (std::size_t i = 6000; i < s.size(); ++i) s.positions[i] += Vec3(10, 0, 0);
    PreprocessReport report;
    const PreparedCloud c = preprocess(s, {}, {}, report);
    EXPECT_EQ(c.size(), 12000u);
    EXPECT_EQ(report.components_kept, 2u);
    ASSERT_EQ(report.component_sizes.size(), 2u);
    EXPECT_EQ(report.component_sizes[0], 6000u);
    EXPECT_EQ(report.component_sizes[1], 6000u);
}

TEST(Components, DuplicatesFollowTheirRepresentative) {
    PointSet s = testing::sample_sphere(3000);
    testing::append(s, patch(4, Vec3(40, 0, 0)));
    s.positions.push_back(s.positions[3005]); // duplicate of a dropped point
    s.normals.push_back(s.normals[3005]);
    s.positions.push_back(s.positions[5]); // duplicate of a kept point
    s.normals.push_back(s.normals[5]);
    PreprocessReport report;
    preprocess(s, {}, {}, report);
    EXPECT_EQ(report.fate[3016], PointFate::SmallComponent);
    EXPECT_EQ(report.duplicate_of[3016], 3005u);
    EXPECT_EQ(report.fate[3017], PointFate::Duplicate);
    EXPECT_EQ(report.duplicate_of[3017], 5u);
    // Accounting (ALGORITHM.md §13 item 10): every input point has exactly one fate.
    std::size_t total = 0;
    for (auto f : {PointFate::Kept, PointFate::NonFinite, PointFate::Duplicate, PointFate::NoNormal,
                   PointFate::SmallComponent})
        total += report.count(f);
    EXPECT_EQ(total, s.size());
}

TEST(Components, EverythingTooSmallIsAClearError) {
    // Three far-apart patches of 36 points: with k = 10 every neighbourhood stays inside its
    // patch, so the cloud splits into three components below min(N, 100) = 100 points.
    PointSet s = patch(6, Vec3(0, 0, 0));
    testing::append(s, patch(6, Vec3(50, 0, 0)));
    testing::append(s, patch(6, Vec3(0, 50, 0)));
    PreprocessOptions o;
    o.k = 10;
    PreprocessReport report;
    EXPECT_THROW(preprocess(s, o, {}, report), InvalidInput);
    EXPECT_EQ(report.count(PointFate::SmallComponent), 108u);
}

TEST(Components, OptionsAreValidatedByName) {
    PreprocessOptions o;
    o.k = 1;
    PreprocessReport report;
    try {
        preprocess(testing::sample_sphere(100), o, {}, report);
        FAIL();
    } catch (const InvalidOption& e) {
        EXPECT_EQ(e.option, OptionId::K);
        EXPECT_EQ(std::string(e.what()).rfind("k must be", 0), 0u);
    }
    o = {};
    o.r = -1;
    EXPECT_THROW(preprocess(testing::sample_sphere(100), o, {}, report), InvalidOption);
}

// D-35: two parallel sheets 0.03 apart (three spacings) with the same normals: 70 neighbours
// reach across, so the kNN graph joins them, but no edge across is within a reach of 0.025.
struct TwoSheets {
    std::vector<Vec3> positions, normals;
    explicit TwoSheets(std::size_t lower_side, std::size_t upper_side) {
        for (const PointSet& p :
             {patch(lower_side, Vec3(0, 0, 0)), patch(upper_side, Vec3(0.05, 0.05, 0.03))}) {
            positions.insert(positions.end(), p.positions.begin(), p.positions.end());
            normals.insert(normals.end(), p.normals.begin(), p.normals.end());
        }
    }
    ComponentSplit split(const std::vector<double>& reach) const {
        const CsrGraph graph = neighbour_graph(positions, 70, {});
        return split_components(graph, positions, positions, normals, PreprocessOptions{}, {},
                                reach);
    }
};

TEST(Components, EdgesBeyondTheInputReachKeepSheetsApart) {
    const TwoSheets sheets(20, 20);
    const ComponentSplit joined = sheets.split({});
    EXPECT_EQ(joined.count, 1u);
    EXPECT_EQ(joined.edges_beyond_reach, 0u);
    const ComponentSplit apart = sheets.split(std::vector<double>(sheets.positions.size(), 0.025));
    ASSERT_EQ(apart.count, 2u);
    EXPECT_EQ(apart.sizes, (std::vector<std::size_t>{400, 400}));
    EXPECT_GT(apart.edges_beyond_reach, 0u);
    for (std::size_t i = 0; i < sheets.positions.size(); ++i)
        EXPECT_EQ(apart.label[i], i < 400 ? 0u : 1u);
}

TEST(Components, APieceTooSmallToStandAloneRejoinsBeyondTheReach) {
    // 49 points: apart, under the 100 points a component needs; joined as before D-35 rather
    // than dropped.
    const TwoSheets sheets(20, 7);
    const ComponentSplit split = sheets.split(std::vector<double>(sheets.positions.size(), 0.025));
    ASSERT_EQ(split.count, 1u);
    EXPECT_EQ(split.sizes, (std::vector<std::size_t>{449}));
    EXPECT_EQ(split.dropped_components, 0u);
    EXPECT_EQ(split.edges_beyond_reach, 0u);
}

} // namespace
} // namespace hrsr
