// Checks on the project's shared real scans; skipped when ../shared/data is absent.
#include "io/point_set_reader.h"
#include "preprocess/preprocess.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace hrsr {
namespace {

std::string shared(const std::string& relative) {
    const std::filesystem::path p = std::filesystem::path(HRSR_SHARED_DATA) / relative;
    return std::filesystem::exists(p) ? p.string() : std::string();
}

// Bunny range scans without normals: our estimated, oriented normals against the scanner's
// (range-grid) normals of the same points, up to one global sign.
TEST(RealScans, BunnyOrientationAgreesWithScannerNormals) {
    const std::string raw = shared("scans/bunny_rangescans_merged.ply");
    const std::string with_normals = shared("scans/bunny_rangescans_merged_normals.ply");
    if (raw.empty() || with_normals.empty()) GTEST_SKIP() << "shared data not available";
    const PointSet cloud = io::read_point_set(raw);
    const PointSet reference = io::read_point_set(with_normals);
    ASSERT_FALSE(cloud.has_normals());
    ASSERT_EQ(cloud.size(), reference.size());

    PreprocessReport report;
    const PreparedCloud c = preprocess(cloud, {}, {}, report);
    std::size_t positive = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
        if (c.normals[i].dot(reference.normals[c.input_index.values()[i].value()]) > 0) ++positive;
    const double agreement = double(std::max(positive, c.size() - positive)) / double(c.size());
    RecordProperty("orientation_agreement", std::to_string(agreement));
    RecordProperty("points_kept", std::to_string(c.size()));
    EXPECT_GE(agreement, 0.99);
    EXPECT_GT(c.size(), cloud.size() * 99 / 100);
}

} // namespace
} // namespace hrsr
