// Issue 7, item 5: every seed and every input that once crashed a fuzz target (tests/data/fuzz/)
// replayed through the same target bodies in the normal build (and the sanitizer build).
#include "fuzz_targets.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace hrsr {
namespace {

using Target = void (*)(const std::uint8_t*, std::size_t);

std::size_t replay(const std::string& folder, Target target) {
    const fs::path dir = fs::path(HRSR_FUZZ_DATA) / folder;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir)) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) {
        std::ifstream in(f, std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), {}};
        EXPECT_NO_THROW(target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()))
            << f;
    }
    return files.size();
}

TEST(FuzzReplay, Readers) {
    EXPECT_GE(replay("read_ply", fuzz::read_ply_bytes), 3u);
    EXPECT_GE(replay("read_xyz", fuzz::read_xyz_bytes), 1u);
    EXPECT_GE(replay("read_obj", fuzz::read_obj_bytes), 1u);
    EXPECT_GE(replay("read_pts", fuzz::read_pts_bytes), 1u);
    EXPECT_GE(replay("read_pcd", fuzz::read_pcd_bytes), 3u);
    EXPECT_GE(replay("read_las", fuzz::read_las_bytes), 2u);
}

TEST(FuzzReplay, MeshCheck) {
    EXPECT_GE(replay("check_mesh", fuzz::check_mesh_bytes), 3u);
}

TEST(FuzzReplay, Reconstruction) {
    EXPECT_GE(replay("reconstruct", fuzz::reconstruct_bytes), 2u);
}

} // namespace
} // namespace hrsr
