// write_ply and AtomicFile: round trips through our reader, the exact file layout, validation,
// and all-or-nothing writes.
#include "errors.h"
#include "io/atomic_file.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"

#include "temp_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace hrsr::io {
namespace {

namespace fs = std::filesystem;

using hrsr::testing::TempFolder;

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void put_file(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

/// Header of a PLY file: everything up to and including "end_header\n".
std::string header_of(const std::string& bytes) {
    const std::string end = "end_header\n";
    const auto at = bytes.find(end);
    return at == std::string::npos ? "" : bytes.substr(0, at + end.size());
}

bool same_bits(const Vec3& a, const Vec3& b) {
    for (int k = 0; k < 3; ++k) {
        if (std::memcmp(&a[k], &b[k], sizeof(double)) != 0) return false;
    }
    return true;
}

/// Random points; with `float_values`, each coordinate is exactly a float.
std::vector<Vec3> random_points(std::size_t n, bool float_values, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> mantissa(-1, 1);
    std::uniform_int_distribution<int> exponent(-30, 30);
    std::vector<Vec3> points(n);
    for (Vec3& p : points) {
        for (int k = 0; k < 3; ++k) {
            const double v = std::ldexp(mantissa(rng), exponent(rng));
            p[k] = float_values ? double(static_cast<float>(v)) : v;
        }
    }
    return points;
}

std::vector<Vec3> random_normals(std::size_t n, unsigned seed) {
    std::vector<Vec3> normals = random_points(n, true, seed);
    for (Vec3& v : normals) {
        const double len = v.Norm();
        v = len > 0 ? v / len : Vec3(0, 0, 1);
        for (int k = 0; k < 3; ++k) v[k] = double(static_cast<float>(v[k]));
    }
    return normals;
}

// ---------------------------------------------------------------------------------------------
// Round trips

TEST(WritePly, FloatRoundTripWithNormalsIsBitExact) {
    TempFolder folder;
    const std::string path = folder.path("cloud.ply");
    const std::vector<Vec3> positions = random_points(1000, true, 1);
    const std::vector<Vec3> normals = random_normals(1000, 2);
    write_ply(path, positions, normals, {}, CoordinatePrecision::Float);
    const PointSet read = read_point_set(path);
    EXPECT_EQ(read.precision, CoordinatePrecision::Float);
    ASSERT_EQ(read.size(), positions.size());
    ASSERT_EQ(read.normals.size(), normals.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        ASSERT_TRUE(same_bits(read.positions[i], positions[i])) << i;
        ASSERT_TRUE(same_bits(read.normals[i], normals[i])) << i;
    }
}

TEST(WritePly, DoubleRoundTripWithoutNormalsIsBitExact) {
    TempFolder folder;
    const std::string path = folder.path("cloud.ply");
    std::vector<Vec3> positions = random_points(1000, false, 3);
    positions.push_back(Vec3(5e-324, -0.0, 1.7976931348623157e308)); // extremes survive too
    write_ply(path, positions, {}, {}, CoordinatePrecision::Double);
    const PointSet read = read_point_set(path);
    EXPECT_EQ(read.precision, CoordinatePrecision::Double);
    EXPECT_FALSE(read.has_normals());
    ASSERT_EQ(read.size(), positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        ASSERT_TRUE(same_bits(read.positions[i], positions[i])) << i;
    }
}

TEST(WritePly, FloatPrecisionRoundsDoubles) {
    TempFolder folder;
    const std::string path = folder.path("cloud.ply");
    write_ply(path, {Vec3(0.1, 0.2, 0.3)}, {}, {}, CoordinatePrecision::Float);
    const PointSet read = read_point_set(path);
    ASSERT_EQ(read.size(), 1u);
    EXPECT_EQ(read.positions[0], Vec3(double(0.1f), double(0.2f), double(0.3f)));
}

TEST(WritePly, LargeCloudsCrossBufferBoundaries) {
    TempFolder folder;
    for (const auto precision : {CoordinatePrecision::Float, CoordinatePrecision::Double}) {
        const std::string path = folder.path("big.ply");
        const std::vector<Vec3> positions =
            random_points(200003, precision == CoordinatePrecision::Float, 4);
        const std::vector<Vec3> normals = random_normals(positions.size(), 5);
        write_ply(path, positions, normals, {}, precision);
        const PointSet read = read_point_set(path);
        ASSERT_EQ(read.size(), positions.size());
        ASSERT_EQ(read.normals.size(), positions.size());
        for (std::size_t i = 0; i < positions.size(); ++i) {
            ASSERT_TRUE(same_bits(read.positions[i], positions[i])) << i;
            ASSERT_TRUE(same_bits(read.normals[i], normals[i])) << i;
        }
    }
}

TEST(WritePly, EmptyCloud) {
    TempFolder folder;
    const std::string path = folder.path("empty.ply");
    write_ply(path, {}, {}, {}, CoordinatePrecision::Float);
    EXPECT_EQ(read_point_set(path).size(), 0u);
}

// ---------------------------------------------------------------------------------------------
// File layout

TEST(WritePly, HeaderOfACloudWithNormals) {
    TempFolder folder;
    const std::string path = folder.path("cloud.ply");
    write_ply(path, random_points(3, true, 6), random_normals(3, 7), {},
              CoordinatePrecision::Float);
    const std::string bytes = slurp(path);
    const std::string expected = "ply\nformat binary_little_endian 1.0\n"
                                 "comment written by hrsr " HRSR_VERSION "\n"
                                 "element vertex 3\n"
                                 "property float x\nproperty float y\nproperty float z\n"
                                 "property float nx\nproperty float ny\nproperty float nz\n"
                                 "end_header\n";
    EXPECT_EQ(header_of(bytes), expected);
    EXPECT_EQ(bytes.size(), expected.size() + 3 * 6 * 4);
}

TEST(WritePly, HeaderOfADoubleMesh) {
    TempFolder folder;
    const std::string path = folder.path("mesh.ply");
    const std::vector<Triangle> triangles = {{0, 1, 2}, {2, 1, 3}};
    write_ply(path, random_points(4, false, 8), {}, triangles, CoordinatePrecision::Double);
    const std::string bytes = slurp(path);
    const std::string expected = "ply\nformat binary_little_endian 1.0\n"
                                 "comment written by hrsr " HRSR_VERSION "\n"
                                 "element vertex 4\n"
                                 "property double x\nproperty double y\nproperty double z\n"
                                 "element face 2\nproperty list uchar int vertex_indices\n"
                                 "end_header\n";
    EXPECT_EQ(header_of(bytes), expected);
    EXPECT_EQ(bytes.size(), expected.size() + 4 * 3 * 8 + 2 * (1 + 3 * 4));
}

TEST(WritePly, MeshRoundTripAndFaceBytes) {
    TempFolder folder;
    const std::string path = folder.path("mesh.ply");
    std::vector<Vec3> positions = {Vec3(1, -2, 0.5), Vec3(0, 0, 0), Vec3(0, 1, 0)};
    for (int i = 0; i < 300; ++i) positions.push_back(Vec3(i, i, i));
    write_ply(path, positions, {}, {{0, 1, 258}, {2, 1, 0}}, CoordinatePrecision::Float);

    const PointSet read = read_point_set(path); // the reader ignores the faces after vertices
    ASSERT_EQ(read.size(), positions.size());
    EXPECT_EQ(read.positions[0], positions[0]);
    EXPECT_EQ(read.positions[302], positions[302]);

    const std::string bytes = slurp(path);
    const std::string payload = bytes.substr(header_of(bytes).size());
    const unsigned char first_vertex[12] = {0x00, 0x00, 0x80, 0x3f,  // 1.0f
                                            0x00, 0x00, 0x00, 0xc0,  // -2.0f
                                            0x00, 0x00, 0x00, 0x3f}; // 0.5f
    EXPECT_EQ(std::memcmp(payload.data(), first_vertex, 12), 0);
    const unsigned char first_face[13] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 0x02, 0x01, 0, 0};
    ASSERT_EQ(payload.size(), positions.size() * 12 + 2 * 13);
    EXPECT_EQ(std::memcmp(payload.data() + positions.size() * 12, first_face, 13), 0);
}

// ---------------------------------------------------------------------------------------------
// Validation and failures

TEST(WritePly, MismatchedNormalsAreRejectedBeforeAnyFile) {
    TempFolder folder;
    EXPECT_THROW(write_ply(folder.path("a.ply"), random_points(3, true, 1), random_normals(2, 1),
                           {}, CoordinatePrecision::Float),
                 std::invalid_argument);
    EXPECT_TRUE(folder.entries().empty());
}

TEST(WritePly, OutOfRangeIndexIsRejectedBeforeAnyFile) {
    TempFolder folder;
    const std::string path = folder.path("a.ply");
    put_file(path, "old");
    EXPECT_THROW(
        write_ply(path, random_points(3, true, 1), {}, {{0, 1, 3}}, CoordinatePrecision::Float),
        std::invalid_argument);
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.ply"});
    EXPECT_EQ(slurp(path), "old");
}

TEST(WritePly, ReplacesAnExistingFile) {
    TempFolder folder;
    const std::string path = folder.path("a.ply");
    put_file(path, "old content");
    write_ply(path, {Vec3(1, 2, 3)}, {}, {}, CoordinatePrecision::Double);
    EXPECT_EQ(read_point_set(path).positions.at(0), Vec3(1, 2, 3));
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.ply"});
}

TEST(WritePly, NonexistentFolderThrowsIoError) {
    TempFolder folder;
    const std::string path = folder.path("no/such/folder/a.ply");
    try {
        write_ply(path, {Vec3(1, 2, 3)}, {}, {}, CoordinatePrecision::Double);
        FAIL() << "expected IoError";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
    }
    EXPECT_TRUE(folder.entries().empty());
}

// ---------------------------------------------------------------------------------------------
// AtomicFile

TEST(AtomicFile, TemporaryFileSitsNextToTheDestination) {
    TempFolder folder;
    AtomicFile file(folder.path("out.ply"));
    const std::vector<std::string> entries = folder.entries();
    ASSERT_EQ(entries.size(), 1u);
    EXPECT_EQ(entries[0].rfind("out.ply.tmp-" + std::to_string(getpid()) + "-", 0), 0u)
        << entries[0];
}

TEST(AtomicFile, NotCommittedLeavesNoFile) {
    TempFolder folder;
    {
        AtomicFile file(folder.path("out.ply"));
        file.stream() << "partial data";
    }
    EXPECT_TRUE(folder.entries().empty());
}

TEST(AtomicFile, NotCommittedLeavesTheDestinationUntouched) {
    TempFolder folder;
    const std::string path = folder.path("out.ply");
    put_file(path, "old");
    {
        AtomicFile file(path);
        file.stream() << "new";
    }
    EXPECT_EQ(slurp(path), "old");
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.ply"});
}

TEST(AtomicFile, CommitReplacesTheDestination) {
    TempFolder folder;
    const std::string path = folder.path("out.ply");
    put_file(path, "old");
    {
        AtomicFile file(path);
        file.stream() << "new";
        file.commit();
    }
    EXPECT_EQ(slurp(path), "new");
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.ply"});
}

// A destination that is not a regular file is written, not replaced: `-o /dev/null` run as root
// once turned the machine's /dev/null into a regular file (session 53).
TEST(AtomicFile, PipeIsWrittenNotReplaced) {
    TempFolder folder;
    const std::string path = folder.path("pipe");
    ASSERT_EQ(mkfifo(path.c_str(), 0600), 0);
    // The read end first, without waiting for a writer; the pipe's buffer holds the bytes.
    const int reader = open(path.c_str(), O_RDONLY | O_NONBLOCK);
    ASSERT_GE(reader, 0);
    {
        AtomicFile file(path);
        file.stream() << "through the pipe";
        file.commit();
    }
    char bytes[64] = {};
    const ssize_t got = read(reader, bytes, sizeof bytes - 1);
    close(reader);
    EXPECT_EQ(std::string(bytes, std::size_t(std::max<ssize_t>(got, 0))), "through the pipe");
    EXPECT_TRUE(std::filesystem::is_fifo(path));
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"pipe"}); // no temporary file left
}

TEST(AtomicFile, TwoFilesForTheSameDestinationDoNotCollide) {
    TempFolder folder;
    const std::string path = folder.path("out.ply");
    AtomicFile first(path);
    AtomicFile second(path);
    first.stream() << "first";
    second.stream() << "second";
    second.commit();
    EXPECT_EQ(slurp(path), "second");
    first.commit();
    EXPECT_EQ(slurp(path), "first");
}

TEST(AtomicFile, NonexistentFolderThrowsIoErrorNamingTheDestination) {
    TempFolder folder;
    const std::string path = folder.path("missing/out.ply");
    try {
        AtomicFile file(path);
        FAIL() << "expected IoError";
    } catch (const IoError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(std::strerror(ENOENT)), std::string::npos) << message;
    }
}

TEST(AtomicFile, FailedRenameThrowsAndCleansUp) {
    TempFolder folder;
    const std::string path = folder.path("out.ply");
    fs::create_directory(path); // a non-empty directory cannot be replaced by a file
    put_file(folder.path("out.ply/keep"), "x");
    {
        AtomicFile file(path);
        file.stream() << "data";
        try {
            file.commit();
            FAIL() << "expected IoError";
        } catch (const IoError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
        }
    }
    EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.ply"});
    EXPECT_TRUE(fs::is_directory(path));
}

} // namespace
} // namespace hrsr::io
