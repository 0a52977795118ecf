// The shared real scans in their own formats (../shared/data/las, pcd): read as LAS, LAZ tiles
// and PCD they give the points (and colours) of the PLY conversions staged beside them.
// Skipped when the shared data is absent.
#include "io/point_set_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace hrsr::io {
namespace {

namespace fs = std::filesystem;

std::string shared(const std::string& relative) {
    const fs::path p = fs::path(HRSR_SHARED_DATA) / relative;
    return fs::exists(p) ? p.string() : std::string();
}

const PointAttribute& attribute(const PointSet& p, const std::string& name) {
    for (const PointAttribute& a : p.attributes)
        if (a.name == name) return a;
    throw std::runtime_error("no attribute " + name);
}

/// The LAZ tiles in byte order of their names (r.laz, r0.laz, r00.laz, ...).
std::vector<std::string> laz_tiles(const std::string& folder) {
    std::vector<std::string> tiles;
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().extension() == ".laz") tiles.push_back(entry.path().string());
    std::sort(tiles.begin(), tiles.end());
    return tiles;
}

TEST(SharedScanFormats, LionLasHasThePointsAndColoursOfTheLionPly) {
    const std::string las = shared("las/lion_takanawa_rgb.las");
    const std::string ply = shared("scans/lion_takanawa_rgb.ply");
    if (las.empty() || ply.empty()) GTEST_SKIP() << "shared data not available";
    const PointSet a = read_point_set(las), b = read_point_set(ply);
    ASSERT_EQ(a.size(), 341989u);
    ASSERT_EQ(b.size(), a.size());
    std::size_t moved = 0, recoloured = 0;
    for (const char* c : {"red", "green", "blue"})
        EXPECT_EQ(attribute(a, c).type, ScalarType::UInt16);
    for (std::size_t i = 0; i < a.size(); ++i) {
        for (int k = 0; k < 3; ++k) moved += float(a.positions[i][k]) != float(b.positions[i][k]);
        for (const char* c : {"red", "green", "blue"})
            recoloured += std::floor(attribute(a, c).value(i) / 256) != attribute(b, c).value(i);
    }
    EXPECT_EQ(moved, 0u);
    EXPECT_EQ(recoloured, 0u);
}

TEST(SharedScanFormats, LazTilesTogetherAreTheMergedLas) {
    const std::string las = shared("las/lion_takanawa_rgb.las");
    const std::string folder = shared("las/lion_takanawa_laz_tiles");
    if (las.empty() || folder.empty()) GTEST_SKIP() << "shared data not available";
    const std::vector<std::string> tiles = laz_tiles(folder);
    ASSERT_EQ(tiles.size(), 200u);
    const PointSet merged = read_point_set(las), tiled = read_point_sets(tiles);
    ASSERT_EQ(tiled.size(), merged.size());
    EXPECT_EQ(tiled.positions, merged.positions);
    ASSERT_EQ(tiled.attributes.size(), merged.attributes.size());
    for (std::size_t j = 0; j < merged.attributes.size(); ++j) {
        EXPECT_EQ(tiled.attributes[j].name, merged.attributes[j].name);
        EXPECT_EQ(tiled.attributes[j].bytes, merged.attributes[j].bytes)
            << merged.attributes[j].name;
    }
}

TEST(SharedScanFormats, OrganizedKinectPcdIsTheScenePly) {
    const std::string pcd = shared("pcd/milk_cartoon_all_small_clorox.pcd");
    const std::string ply = shared("scans/kinect_milk_cartoon_scene.ply");
    if (pcd.empty() || ply.empty()) GTEST_SKIP() << "shared data not available";
    const PointSet a = read_point_set(pcd), b = read_point_set(ply);
    EXPECT_EQ(a.size(), 241407u);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.precision, CoordinatePrecision::Float);
    ASSERT_EQ(a.attributes.size(), 4u); // rgba
    EXPECT_EQ(a.attributes[3].name, "alpha");
    ASSERT_EQ(a.warnings.size(), 1u);
    EXPECT_NE(a.warnings[0].find("65793 of 307200 points have NaN"), std::string::npos)
        << a.warnings[0];
}

TEST(SharedScanFormats, LaserPcdIsTheTablePlyWithItsOwnFields) {
    const std::string pcd = shared("pcd/table_scene_lms400.pcd");
    const std::string ply = shared("scans/table_scene_lms400.ply");
    if (pcd.empty() || ply.empty()) GTEST_SKIP() << "shared data not available";
    const PointSet a = read_point_set(pcd), b = read_point_set(ply);
    EXPECT_EQ(a.positions, b.positions);
    ASSERT_EQ(a.attributes.size(), 3u);
    for (const PointAttribute& x : a.attributes) EXPECT_EQ(x.type, ScalarType::Float32);
    EXPECT_EQ(a.attributes[0].name, "intensity");
    EXPECT_EQ(a.attributes[2].name, "sid");
}

} // namespace
} // namespace hrsr::io
