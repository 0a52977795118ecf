// The shared lion capture through `hrsr reconstruct` as one LAS file and as its 200 LAZ tiles in
// one call: the same mesh, and every vertex carries the intensity, class and 16-bit colour of
// the input point at its position (the first of equal points). Skipped without ../shared/data.
// (The suite's name keeps it out of the sanitizer run, as the other real-scan tests.)
#include "cli_runner.h"
#include "io/point_set_reader.h"
#include "temp_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace hrsr {
namespace {

using testing::Outcome;
using testing::slurp;

std::string shared(const std::string& relative) {
    const fs::path p = fs::path(HRSR_SHARED_DATA) / relative;
    return fs::exists(p) ? p.string() : std::string();
}

TEST(RealScansFormats, LazTilesGiveTheMeshOfTheMergedLasWithEveryPointsValues) {
    const std::string las = shared("las/lion_takanawa_rgb.las");
    const std::string tiles_folder = shared("las/lion_takanawa_laz_tiles");
    if (las.empty() || tiles_folder.empty()) GTEST_SKIP() << "shared data not available";
    std::vector<std::string> tiles;
    for (const auto& entry : fs::directory_iterator(tiles_folder))
        if (entry.path().extension() == ".laz") tiles.push_back(entry.path().string());
    std::sort(tiles.begin(), tiles.end());
    std::string tile_args;
    for (const std::string& t : tiles) tile_args += " " + t;

    testing::TempFolder folder;
    const auto run = [&](const std::string& inputs, const std::string& out) {
        return testing::run(HRSR_EXE, "reconstruct -q" + inputs + " -o " + folder.path(out),
                            folder.root());
    };
    const Outcome a = run(" " + las, "las.ply");
    ASSERT_EQ(a.exit_code, 0) << a.err;
    const Outcome b = run(tile_args, "tiles.ply");
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_EQ(slurp(folder.path("tiles.ply")), slurp(folder.path("las.ply")));

    const PointSet input = io::read_point_set(las);
    const PointSet mesh = io::read_point_set(folder.path("las.ply"));
    ASSERT_EQ(mesh.attributes.size(), input.attributes.size());
    std::map<std::array<double, 3>, std::size_t> first;
    for (std::size_t i = 0; i < input.size(); ++i)
        first.emplace(std::array<double, 3>{input.positions[i][0], input.positions[i][1],
                                            input.positions[i][2]},
                      i);
    std::size_t unknown = 0, wrong = 0;
    for (std::size_t v = 0; v < mesh.size(); ++v) {
        const auto it =
            first.find({mesh.positions[v][0], mesh.positions[v][1], mesh.positions[v][2]});
        if (it == first.end()) {
            ++unknown;
            continue;
        }
        for (std::size_t j = 0; j < input.attributes.size(); ++j)
            if (mesh.attributes[j].name != input.attributes[j].name ||
                mesh.attributes[j].type != input.attributes[j].type ||
                mesh.attributes[j].value(v) != input.attributes[j].value(it->second))
                ++wrong;
    }
    EXPECT_GT(mesh.size(), 340000u);
    EXPECT_EQ(unknown, 0u);
    EXPECT_EQ(wrong, 0u);
}

} // namespace
} // namespace hrsr
