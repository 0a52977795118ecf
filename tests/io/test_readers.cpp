// Point-set readers: PLY (ascii, binary both endiannesses), XYZ, OBJ, dispatch by extension.
// Every malformed input must give an IoError naming the file, never a crash.
#include "errors.h"
#include "io/point_set_reader.h"

#include "read_bytes.h"
#include "temp_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace hrsr::io {
namespace {

namespace fs = std::filesystem;

const std::string kName = "cloud.ply";

// ---------------------------------------------------------------------------------------------
// Helpers

using hrsr::testing::TempFolder;

/// Builds binary PLY payloads in either byte order.
class Bytes {
public:
    explicit Bytes(bool big_endian) : big_endian_(big_endian) {}

    Bytes& text(const std::string& s) {
        data_ += s;
        return *this;
    }
    template <class T>
    Bytes& put(T value) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        const std::uint16_t one = 1;
        const bool host_big = *reinterpret_cast<const unsigned char*>(&one) == 0;
        if (host_big != big_endian_) {
            std::reverse(b, b + sizeof(T));
        }
        data_.append(reinterpret_cast<const char*>(b), sizeof(T));
        return *this;
    }
    /// `value` stored as the named PLY type.
    Bytes& put_as(const std::string& type, double value) {
        if (type == "char" || type == "int8") return put(static_cast<std::int8_t>(value));
        if (type == "uchar" || type == "uint8") return put(static_cast<std::uint8_t>(value));
        if (type == "short" || type == "int16") return put(static_cast<std::int16_t>(value));
        if (type == "ushort" || type == "uint16") return put(static_cast<std::uint16_t>(value));
        if (type == "int" || type == "int32") return put(static_cast<std::int32_t>(value));
        if (type == "uint" || type == "uint32") return put(static_cast<std::uint32_t>(value));
        if (type == "float" || type == "float32") return put(static_cast<float>(value));
        return put(value);
    }
    const std::string& str() const { return data_; }

private:
    bool big_endian_;
    std::string data_;
};

using testing::read_bytes;
using testing::StreamReader;

PointSet ply(const std::string& bytes) {
    return read_bytes(read_ply, bytes, {}, kName);
}

/// The message of the IoError that reading `bytes` must throw ("" and a failure otherwise).
std::string error_of(StreamReader read, const std::string& bytes, const std::string& name) {
    try {
        read_bytes(read, bytes, {}, name);
    } catch (const IoError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected IoError, got another exception: " << e.what();
        return "";
    }
    ADD_FAILURE() << "expected IoError, got none";
    return "";
}

/// Reading must fail with a message that starts with the file name and contains `word`.
void expect_error(StreamReader read, const std::string& bytes, const std::string& name,
                  const std::string& word) {
    const std::string message = error_of(read, bytes, name);
    EXPECT_EQ(message.rfind(name + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(word), std::string::npos) << "'" << word << "' not in: " << message;
}

void expect_ply_error(const std::string& bytes, const std::string& word) {
    expect_error(read_ply, bytes, kName, word);
}

/// Reading may succeed or throw IoError; anything else (or a crash) fails the test.
void expect_success_or_io_error(StreamReader read, const std::string& bytes) {
    try {
        read_bytes(read, bytes, {}, kName);
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(kName + ": ", 0), 0u) << e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not an IoError: " << e.what();
    }
}

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

std::string header(const std::string& format, const std::string& elements) {
    return "ply\nformat " + format + " 1.0\n" + elements + "end_header\n";
}

/// A vertex element with float x, y, z.
std::string float_vertex(const std::string& count) {
    return "element vertex " + count + "\nproperty float x\nproperty float y\nproperty float z\n";
}

std::string xyz_float_header(const std::string& format, const std::string& count) {
    return header(format, float_vertex(count));
}

// ---------------------------------------------------------------------------------------------
// PLY: valid files

TEST(PlyAscii, CrlfCommentsAndAnyWhitespace) {
    const std::string file = "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\n"
                             "obj_info scanner 7\r\nelement vertex 3\r\nproperty float x\r\n"
                             "property float y\r\nproperty float z\r\nproperty float nx\r\n"
                             "property float ny\r\nproperty float nz\r\nend_header\r\n"
                             "1 2 3 0 0 1\r\n"
                             "-1.5\t2.25   3e2 0 1 0\r\n"
                             "0.1 0.2\r\n 0.3 1 0 0\r\n"; // items are not tied to lines
    const PointSet p = ply(file);
    ASSERT_EQ(p.size(), 3u);
    ASSERT_EQ(p.normals.size(), 3u);
    EXPECT_EQ(p.positions[0], Vec3(1, 2, 3));
    EXPECT_EQ(p.positions[1], Vec3(-1.5, 2.25, 300));
    EXPECT_EQ(p.normals[1], Vec3(0, 1, 0));
    // float properties hold float values
    EXPECT_EQ(p.positions[2], Vec3(double(0.1f), double(0.2f), double(0.3f)));
    EXPECT_EQ(p.normals[2], Vec3(1, 0, 0));
    EXPECT_EQ(p.precision, CoordinatePrecision::Float);
}

TEST(PlyAscii, SkipsElementsBeforeVertexAndExtraProperties) {
    const std::string file = header("ascii", "element face 2\n"
                                             "property list uchar int vertex_indices\n"
                                             "element material 1\nproperty float shininess\n"
                                             "element vertex 2\nproperty double x\n"
                                             "property list int float weights\n"
                                             "property double y\nproperty double z\n"
                                             "property uchar red\nelement edge 1\n"
                                             "property int vertex1\n") +
                             "3 0 1 2\n4 0 1 2 3\n0.5\n"
                             "0.1 2 7 8 0.2 0.3 255\n"
                             "1 0 2 3 0\n"
                             "this edge is not read\n";
    const PointSet p = ply(file);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p.positions[0], Vec3(0.1, 0.2, 0.3));
    EXPECT_EQ(p.positions[1], Vec3(1, 2, 3));
    EXPECT_FALSE(p.has_normals());
    EXPECT_EQ(p.precision, CoordinatePrecision::Double);
}

TEST(PlyAscii, NanAndInfAreValues) {
    const PointSet p = ply(xyz_float_header("ascii", "2") + "nan inf -inf\n1 +2 -3\n");
    ASSERT_EQ(p.size(), 2u);
    EXPECT_TRUE(std::isnan(p.positions[0][0]));
    EXPECT_EQ(p.positions[0][1], HUGE_VAL);
    EXPECT_EQ(p.positions[0][2], -HUGE_VAL);
    EXPECT_EQ(p.positions[1], Vec3(1, 2, -3));
}

TEST(PlyBinary, BigEndianDoublesWithIntListCountsBeforeVertex) {
    const double values[] = {0.1, -1e300, M_PI, 5e-324, -0.0, 123456789.123456789};
    Bytes b(/*big_endian=*/true);
    b.text(header("binary_big_endian", "element face 2\n"
                                       "property list int uint vertex_indices\n"
                                       "property short flags\n"
                                       "element vertex 2\nproperty double x\n"
                                       "property double y\nproperty double z\n"));
    b.put<std::int32_t>(3).put<std::uint32_t>(0).put<std::uint32_t>(1).put<std::uint32_t>(2);
    b.put<std::int16_t>(-1);
    b.put<std::int32_t>(4);
    for (std::uint32_t i = 0; i < 4; ++i) b.put(i);
    b.put<std::int16_t>(7);
    for (const double v : values) b.put(v);
    const PointSet p = ply(b.str());
    ASSERT_EQ(p.size(), 2u);
    for (int i = 0; i < 6; ++i) EXPECT_TRUE(same_bits(p.positions[i / 3][i % 3], values[i])) << i;
    EXPECT_FALSE(p.has_normals());
    EXPECT_EQ(p.precision, CoordinatePrecision::Double);
}

TEST(PlyBinary, FacesBeforeVerticesAreSkipped) {
    Bytes b(false);
    b.text(header("binary_little_endian", "element face 2\n"
                                          "property list uchar int vertex_indices\n" +
                                              float_vertex("3")));
    b.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    b.put<std::uint8_t>(3).put<std::int32_t>(2).put<std::int32_t>(1).put<std::int32_t>(0);
    for (int i = 0; i < 9; ++i) b.put(static_cast<float>(i) * 0.5f);
    const PointSet p = ply(b.str());
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p.positions[0], Vec3(0, 0.5, 1));
    EXPECT_EQ(p.positions[2], Vec3(3, 3.5, 4));
    EXPECT_EQ(p.precision, CoordinatePrecision::Float);
}

TEST(PlyBinary, EveryIntegerTypeWorksAsListCount) {
    for (const std::string type : {"char", "uchar", "short", "ushort", "int", "uint", "int8",
                                   "uint8", "int16", "uint16", "int32", "uint32"}) {
        for (const bool big : {false, true}) {
            Bytes b(big);
            b.text(header(big ? "binary_big_endian" : "binary_little_endian",
                          "element blob 2\nproperty list " + type + " double data\n" +
                              "element vertex 1\nproperty float x\nproperty float y\n"
                              "property float z\n"));
            b.put_as(type, 2).put(1.0).put(2.0);
            b.put_as(type, 0);
            b.put(1.0f).put(2.0f).put(3.0f);
            const PointSet p = ply(b.str());
            ASSERT_EQ(p.size(), 1u) << type;
            EXPECT_EQ(p.positions[0], Vec3(1, 2, 3)) << type;
        }
    }
}

TEST(PlyBinary, ExtraScalarPropertiesAreSkipped) {
    Bytes b(false);
    b.text(header("binary_little_endian",
                  "element vertex 2\nproperty float x\nproperty uchar red\nproperty uchar green\n"
                  "property uchar blue\nproperty float y\nproperty float z\n"
                  "property float nx\nproperty float ny\nproperty float nz\n"
                  "property double quality\n"));
    for (int i = 0; i < 2; ++i) {
        b.put(1.0f + i).put<std::uint8_t>(255).put<std::uint8_t>(0).put<std::uint8_t>(9);
        b.put(2.0f + i).put(3.0f + i).put(0.0f).put(0.6f).put(0.8f).put(42.0);
    }
    const PointSet p = ply(b.str());
    ASSERT_EQ(p.size(), 2u);
    ASSERT_EQ(p.normals.size(), 2u);
    EXPECT_EQ(p.positions[1], Vec3(2, 3, 4));
    EXPECT_EQ(p.normals[1], Vec3(0, double(0.6f), double(0.8f)));
}

TEST(PlyBinary, ListPropertyInsideVertex) {
    Bytes b(false);
    b.text(header("binary_little_endian",
                  "element vertex 2\nproperty float x\nproperty list ushort float weights\n"
                  "property float y\nproperty float z\nproperty uchar red\n"
                  "property float nx\nproperty float ny\nproperty float nz\n"));
    b.put(1.0f).put<std::uint16_t>(3).put(9.0f).put(9.0f).put(9.0f).put(2.0f).put(3.0f);
    b.put<std::uint8_t>(1).put(1.0f).put(0.0f).put(0.0f);
    b.put(4.0f).put<std::uint16_t>(0).put(5.0f).put(6.0f);
    b.put<std::uint8_t>(1).put(0.0f).put(0.0f).put(-1.0f);
    const PointSet p = ply(b.str());
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p.positions[0], Vec3(1, 2, 3));
    EXPECT_EQ(p.positions[1], Vec3(4, 5, 6));
    ASSERT_EQ(p.normals.size(), 2u);
    EXPECT_EQ(p.normals[1], Vec3(0, 0, -1));
}

TEST(PlyBinary, SmallIntegerCoordinates) {
    Bytes b(true);
    b.text(header("binary_big_endian", "element vertex 2\nproperty uchar x\nproperty short y\n"
                                       "property char z\n"));
    b.put<std::uint8_t>(200).put<std::int16_t>(-30000).put<std::int8_t>(-5);
    b.put<std::uint8_t>(0).put<std::int16_t>(1234).put<std::int8_t>(127);
    const PointSet p = ply(b.str());
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p.positions[0], Vec3(200, -30000, -5));
    EXPECT_EQ(p.positions[1], Vec3(0, 1234, 127));
    EXPECT_EQ(p.precision, CoordinatePrecision::Double);
}

/// Every scalar type as coordinate type, in the three formats.
class PlyCoordinateType : public ::testing::TestWithParam<const char*> {};

TEST_P(PlyCoordinateType, ReadsInEveryFormat) {
    const std::string type = GetParam();
    const bool is_signed = type[0] != 'u';
    const std::vector<double> values = {0, 1, 100, is_signed ? -100.0 : 7.0, 2, 3};
    const std::string elements = "element vertex 2\nproperty " + type + " x\nproperty " + type +
                                 " y\nproperty " + type + " z\n";
    for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        Bytes b(format == "binary_big_endian");
        b.text(header(format, elements));
        for (const double v : values) {
            if (format == "ascii") {
                b.text(std::to_string(static_cast<int>(v)) + " ");
            } else {
                b.put_as(type, v);
            }
        }
        const PointSet p = ply(b.str());
        ASSERT_EQ(p.size(), 2u) << format;
        EXPECT_EQ(p.positions[0], Vec3(values[0], values[1], values[2])) << format;
        EXPECT_EQ(p.positions[1], Vec3(values[3], values[4], values[5])) << format;
        const bool is_float = type == "float" || type == "float32";
        EXPECT_EQ(p.precision, is_float ? CoordinatePrecision::Float : CoordinatePrecision::Double);
    }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, PlyCoordinateType,
                         ::testing::Values("char", "int8", "uchar", "uint8", "short", "int16",
                                           "ushort", "uint16", "int", "int32", "uint", "uint32",
                                           "float", "float32", "double", "float64"));

TEST(Ply, PartialNormalsAreIgnored) {
    const PointSet p = ply(header("ascii", "element vertex 1\nproperty float x\nproperty float y\n"
                                           "property float z\nproperty float nx\n"
                                           "property float ny\n") +
                           "1 2 3 4 5\n");
    ASSERT_EQ(p.size(), 1u);
    EXPECT_FALSE(p.has_normals());
}

TEST(Ply, MixedCoordinateTypesGiveDoublePrecision) {
    const PointSet p = ply(header("ascii", "element vertex 1\nproperty float x\n"
                                           "property float y\nproperty double z\n") +
                           "1 2 3\n");
    EXPECT_EQ(p.precision, CoordinatePrecision::Double);
}

TEST(Ply, ZeroVerticesIsAnEmptySet) {
    for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        const PointSet p = ply(xyz_float_header(format, "0"));
        EXPECT_EQ(p.size(), 0u) << format;
        EXPECT_FALSE(p.has_normals());
    }
}

// ---------------------------------------------------------------------------------------------
// PLY: malformed files

TEST(PlyMalformed, EmptyFile) {
    expect_ply_error("", "empty");
}

TEST(PlyMalformed, NotAPlyFile) {
    expect_ply_error("PLY\nformat ascii 1.0\n", "not a PLY file");
    expect_ply_error("pl", "not a PLY file");
    expect_ply_error("plywood\n", "not a PLY file");
}

TEST(PlyMalformed, RandomBytes) {
    std::mt19937 rng(12345);
    for (int trial = 0; trial < 200; ++trial) {
        std::string bytes(1 + rng() % 4096, '\0');
        for (char& c : bytes) c = static_cast<char>(rng());
        const std::string message = error_of(read_ply, bytes, kName);
        EXPECT_EQ(message.rfind(kName + ": ", 0), 0u) << message;
        expect_success_or_io_error(read_xyz, bytes);
        expect_success_or_io_error(read_obj, bytes);
    }
}

TEST(PlyMalformed, MagicFollowedByRandomBytes) {
    std::mt19937 rng(777);
    for (int trial = 0; trial < 200; ++trial) {
        std::string bytes = trial % 2 ? "ply\n" : "ply\r\nformat binary_little_endian 1.0\n";
        const std::size_t n = 1 + rng() % 2048;
        for (std::size_t i = 0; i < n; ++i) bytes += static_cast<char>(rng());
        const std::string message = error_of(read_ply, bytes, kName);
        EXPECT_EQ(message.rfind(kName + ": ", 0), 0u) << message;
    }
}

/// A valid file with lists before and inside the vertex element, damaged in many ways.
std::string fuzz_seed(bool big_endian) {
    Bytes b(big_endian);
    b.text(header(big_endian ? "binary_big_endian" : "binary_little_endian",
                  "element face 3\nproperty list uchar int vertex_indices\n"
                  "element vertex 4\nproperty float x\nproperty list short double w\n"
                  "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
                  "property float nz\n"));
    for (int f = 0; f < 3; ++f) b.put<std::uint8_t>(3).put(0).put(1).put(f + 1);
    for (int v = 0; v < 4; ++v) {
        b.put(1.0f * v).put<std::int16_t>(static_cast<std::int16_t>(v));
        for (int k = 0; k < v; ++k) b.put(0.25 * k);
        b.put(2.0f).put(3.0f).put(0.0f).put(0.0f).put(1.0f);
    }
    return b.str();
}

TEST(PlyMalformed, DamagedFilesNeverCrash) {
    std::mt19937 rng(4242);
    for (const bool big : {false, true}) {
        const std::string seed = fuzz_seed(big);
        ASSERT_EQ(ply(seed).size(), 4u);
        for (std::size_t n = 0; n < seed.size(); ++n) {
            expect_success_or_io_error(read_ply, seed.substr(0, n));
        }
        for (int trial = 0; trial < 2000; ++trial) {
            std::string damaged = seed;
            for (int k = 0; k < 1 + trial % 4; ++k) {
                damaged[rng() % damaged.size()] = static_cast<char>(rng());
            }
            expect_success_or_io_error(read_ply, damaged);
        }
    }
}

TEST(PlyMalformed, BinaryCountLargerThanData) {
    Bytes b(false);
    b.text(xyz_float_header("binary_little_endian", "5"));
    for (int i = 0; i < 9; ++i) b.put(1.0f);
    expect_ply_error(b.str(), "truncated binary data: vertex 4 of 5 is incomplete");
}

TEST(PlyMalformed, BinaryTruncatedMidVertex) {
    Bytes b(true);
    b.text(xyz_float_header("binary_big_endian", "3"));
    for (int i = 0; i < 8; ++i) b.put(1.0f);
    expect_ply_error(b.str(), "truncated binary data: vertex 3 of 3");
}

TEST(PlyMalformed, BinaryTruncatedInElementBeforeVertex) {
    Bytes b(false);
    b.text(header("binary_little_endian", "element face 10\n"
                                          "property list uchar int vertex_indices\n" +
                                              float_vertex("1")));
    b.put<std::uint8_t>(3).put(0).put(1).put(2);
    expect_ply_error(b.str(), "truncated binary data: face 2 of 10");
    Bytes scalar(false);
    scalar.text(header("binary_little_endian",
                       "element pair 10\nproperty int a\nproperty int b\n" + float_vertex("1")));
    scalar.put(1).put(2).put(3);
    expect_ply_error(scalar.str(), "truncated binary data: pair 2 of 10");
}

TEST(PlyMalformed, AsciiCountLargerThanData) {
    expect_ply_error(xyz_float_header("ascii", "5") + "1 2 3\n4 5 6\n7 8 9\n",
                     "truncated ascii data");
    expect_ply_error(xyz_float_header("ascii", "2") + "1 2 3\n4 5\n", "vertex 2 of 2");
}

TEST(PlyMalformed, AsciiNonNumericValue) {
    const std::string file = xyz_float_header("ascii", "2") + "1 2 3\n4 five 6\n";
    expect_ply_error(file, "'five' is not a number");
    expect_ply_error(file, "line 9");
    expect_ply_error(file, "property 'y'");
}

TEST(PlyMalformed, AsciiInvalidListLength) {
    expect_ply_error(header("ascii", "element face 1\nproperty list uchar int vertex_indices\n" +
                                         float_vertex("0")) +
                         "-3 1 2 3\n",
                     "invalid list length");
}

TEST(PlyMalformed, NegativeBinaryListLength) {
    Bytes b(false);
    b.text(header("binary_little_endian",
                  "element face 1\nproperty list int int vertex_indices\n" + float_vertex("0")));
    b.put(-1).put(0);
    expect_ply_error(b.str(), "negative list length");
}

TEST(PlyMalformed, MissingCoordinate) {
    expect_ply_error(header("ascii", "element vertex 1\nproperty float x\nproperty float y\n") +
                         "1 2\n",
                     "vertex element has no 'z' property");
    expect_ply_error(header("ascii", "element vertex 1\nproperty float y\nproperty float z\n"),
                     "no 'x' property");
}

TEST(PlyMalformed, CoordinateIsAList) {
    expect_ply_error(header("ascii", "element vertex 1\nproperty list uchar float x\n"
                                     "property float y\nproperty float z\n"),
                     "'x' is a list");
}

TEST(PlyMalformed, NoVertexElement) {
    expect_ply_error(header("ascii", "element face 0\nproperty list uchar int vertex_indices\n"),
                     "no 'vertex' element");
}

TEST(PlyMalformed, MissingEndHeader) {
    expect_ply_error("ply\nformat ascii 1.0\n" + float_vertex("1"), "missing end_header");
}

TEST(PlyMalformed, UnknownOrMissingFormat) {
    expect_ply_error(xyz_float_header("binary_middle_endian", "0"), "unknown format");
    expect_ply_error("ply\nformat\n" + float_vertex("0") + "end_header\n", "format");
    expect_ply_error("ply\n" + float_vertex("0") + "end_header\n", "no 'format' line");
    expect_ply_error("ply\nformat ascii 2.0\nend_header\n", "version");
}

TEST(PlyMalformed, BadHeaderLines) {
    expect_ply_error(header("ascii", "element vertex 1\nproperty flot x\n"),
                     "unknown property type 'flot'");
    expect_ply_error(header("ascii", "property float x\nelement vertex 1\n"),
                     "'property' before any 'element'");
    expect_ply_error(header("ascii", "element vertex -3\n"), "invalid count '-3'");
    expect_ply_error(header("ascii", "element vertex many\n"), "invalid count");
    expect_ply_error(header("ascii", "element vertex\n"), "needs a name and a count");
    expect_ply_error(header("ascii", "element face 1\nproperty list float int idx\n"),
                     "must be an integer");
    expect_ply_error(header("ascii", "elephant vertex 1\n"), "header line 3: unrecognised");
}

TEST(PlyMalformed, AbsurdCountsFailQuickly) {
    const auto start = std::chrono::steady_clock::now();
    const std::string absurd = "1000000000000000";
    Bytes binary(false);
    binary.text(xyz_float_header("binary_little_endian", absurd));
    for (int i = 0; i < 6; ++i) binary.put(1.0f);
    expect_ply_error(binary.str(), "vertex 3 of 1000000000000000 is incomplete");
    expect_ply_error(xyz_float_header("ascii", absurd) + "1 2 3\n", "truncated");

    Bytes scalar_before(true); // a scalar element before the vertex claims 10^15 items
    scalar_before.text(
        header("binary_big_endian",
               "element junk " + absurd + "\nproperty double a\n" + float_vertex("1")));
    scalar_before.put(1.0).put(2.0);
    expect_ply_error(scalar_before.str(), "truncated binary data: junk 3 of");

    Bytes long_list(false); // a list claiming 4 billion items
    long_list.text(header("binary_little_endian", "element face 1\n"
                                                  "property list uint int vertex_indices\n" +
                                                      float_vertex("1")));
    long_list.put<std::uint32_t>(4000000000u).put(1).put(2);
    expect_ply_error(long_list.str(), "face 1 of 1 is incomplete");
    const auto seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 5.0);
}

// ---------------------------------------------------------------------------------------------
// XYZ

TEST(Xyz, ThreeColumnsWithCommentsCrlfAndBlankLines) {
    const std::string text = "# scan 7\r\n"
                             "1 2 3\r\n"
                             "\r\n"
                             "  # indented comment\n"
                             "\t-0.1\t+2.5e-3   1e10  \r\n"
                             "0.1 nan inf\n"
                             "4 5 6"; // no final newline
    const PointSet p = read_bytes(read_xyz, text, {}, "scan.xyz");
    ASSERT_EQ(p.size(), 4u);
    EXPECT_FALSE(p.has_normals());
    EXPECT_EQ(p.positions[0], Vec3(1, 2, 3));
    EXPECT_EQ(p.positions[1], Vec3(-0.1, 0.0025, 1e10));
    EXPECT_EQ(p.positions[2][0], 0.1); // full double precision
    EXPECT_TRUE(std::isnan(p.positions[2][1]));
    EXPECT_TRUE(std::isinf(p.positions[2][2]));
    EXPECT_EQ(p.positions[3], Vec3(4, 5, 6));
    EXPECT_EQ(p.precision, CoordinatePrecision::Double);
}

TEST(Xyz, SixColumnsGiveNormals) {
    const PointSet p =
        read_bytes(read_xyz, "1 2 3 0 0 1\r\n4 5 6 0 1 0\r\n# end\r\n", {}, "scan.xyz");
    ASSERT_EQ(p.size(), 2u);
    ASSERT_EQ(p.normals.size(), 2u);
    EXPECT_EQ(p.positions[1], Vec3(4, 5, 6));
    EXPECT_EQ(p.normals[0], Vec3(0, 0, 1));
    EXPECT_EQ(p.normals[1], Vec3(0, 1, 0));
}

TEST(Xyz, EmptyOrCommentOnlyIsAnEmptySet) {
    EXPECT_EQ(read_bytes(read_xyz, "", {}, "scan.xyz").size(), 0u);
    EXPECT_EQ(read_bytes(read_xyz, "# nothing\n\n   \n", {}, "scan.xyz").size(), 0u);
}

TEST(Xyz, InconsistentColumns) {
    const std::string text = "# header\n1 2 3\n4 5 6\n1 2 3 0 0 1\n";
    expect_error(read_xyz, text, "scan.xyz", "line 4: found 6 numbers, but line 2 has 3");
}

TEST(Xyz, WrongColumnCount) {
    expect_error(read_xyz, "1 2 3\n\n1 2 3 4\n", "scan.xyz",
                 "line 3: expected 3 or 6 numbers, found 4");
    expect_error(read_xyz, "1 2\n", "scan.xyz", "line 1: expected 3 or 6 numbers, found 2");
}

TEST(Xyz, NonNumericToken) {
    expect_error(read_xyz, "1 2 3\r\n1 2 3\r\n1 two 3\r\n", "scan.xyz",
                 "line 3: 'two' is not a number");
    expect_error(read_xyz, "x y z\n1 2 3\n", "scan.xyz", "line 1");
    expect_error(read_xyz, "1,2,3\n", "scan.xyz", "not a number");
}

// ---------------------------------------------------------------------------------------------
// OBJ

TEST(Obj, VerticesAndNormalsAmongOtherStatements) {
    const std::string text = "# exported\r\n"
                             "mtllib scene.mtl\r\n"
                             "o cube\r\n"
                             "v 1 2 3\r\n"
                             "v 4 5 6 1.0\r\n"          // with w
                             "v 7 8 9 0.5 0.25 1.0\r\n" // with colour
                             "vt 0.5 0.5\r\n"
                             "vn 0 0 1\r\n"
                             "vn 0 1 0\r\n"
                             "vn 1 0 0\r\n"
                             "g side\r\n"
                             "usemtl red\r\n"
                             "s off\r\n"
                             "f 1/1/1 2/1/2 3/1/3\r\n"
                             "\r\n"
                             "vp 0.1\r\n";
    const PointSet p = read_bytes(read_obj, text, {}, "mesh.obj");
    ASSERT_EQ(p.size(), 3u);
    ASSERT_EQ(p.normals.size(), 3u);
    EXPECT_EQ(p.positions[0], Vec3(1, 2, 3));
    EXPECT_EQ(p.positions[1], Vec3(4, 5, 6));
    EXPECT_EQ(p.positions[2], Vec3(7, 8, 9));
    EXPECT_EQ(p.normals[0], Vec3(0, 0, 1));
    EXPECT_EQ(p.normals[2], Vec3(1, 0, 0));
    EXPECT_EQ(p.precision, CoordinatePrecision::Double);
}

TEST(Obj, NormalCountDifferentFromVertexCountIsReturnedAsRead) {
    const PointSet p = read_bytes(read_obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n", {}, "a.obj");
    EXPECT_EQ(p.size(), 3u);
    ASSERT_EQ(p.normals.size(), 1u);
    EXPECT_EQ(p.normals[0], Vec3(0, 0, 1));
}

TEST(Obj, OnlyFacesAndTexturesGiveAnEmptySet) {
    const PointSet p = read_bytes(read_obj, "vt 0 0\nf 1 2 3\n", {}, "a.obj");
    EXPECT_EQ(p.size(), 0u);
    EXPECT_FALSE(p.has_normals());
}

TEST(Obj, MalformedVertexLines) {
    expect_error(read_obj, "v 0 0 0\r\nv 1 2\r\n", "a.obj", "line 2: 'v' needs 3 numbers, found 2");
    expect_error(read_obj, "v 0 0 0\nvn 1 x 3\n", "a.obj", "line 2: 'x' is not a number");
    expect_error(read_obj, "v\n", "a.obj", "line 1");
}

// ---------------------------------------------------------------------------------------------
// read_point_set

TEST(ReadPointSet, DispatchesByExtensionCaseInsensitively) {
    TempFolder folder;
    const std::string ply_text = xyz_float_header("ascii", "1") + "1 2 3\n";
    EXPECT_EQ(read_point_set(folder.write("a.PLY", ply_text)).positions.at(0), Vec3(1, 2, 3));
    EXPECT_EQ(read_point_set(folder.write("b.Xyz", "4 5 6\n")).positions.at(0), Vec3(4, 5, 6));
    EXPECT_EQ(read_point_set(folder.write("c.txt", "7 8 9\n")).positions.at(0), Vec3(7, 8, 9));
    // .pts is Leica's format (a count line first), not XYZ: a file without the count is refused.
    EXPECT_THROW(read_point_set(folder.write("d.pts", "1 1 1\n")), IoError);
    EXPECT_EQ(read_point_set(folder.write("f.Pts", "1\n1 1 1\n")).size(), 1u);
    EXPECT_EQ(read_point_set(folder.write("e.OBJ", "v 2 2 2\n")).size(), 1u);
}

TEST(ReadPointSet, UnknownExtension) {
    TempFolder folder;
    const std::string path = folder.write("mesh.stl", "solid x\n");
    try {
        read_point_set(path);
        FAIL() << "expected IoError";
    } catch (const IoError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        EXPECT_NE(message.find("'.stl'"), std::string::npos) << message;
        EXPECT_NE(message.find(".ply"), std::string::npos) << message;
        EXPECT_NE(message.find(".xyz"), std::string::npos) << message;
        EXPECT_NE(message.find(".obj"), std::string::npos) << message;
    }
}

TEST(ReadPointSet, NonexistentFile) {
    TempFolder folder;
    const std::string path = folder.path("missing.ply");
    try {
        read_point_set(path);
        FAIL() << "expected IoError";
    } catch (const IoError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(std::strerror(ENOENT)), std::string::npos) << message;
    }
}

TEST(ReadPointSet, Directory) {
    TempFolder folder;
    fs::create_directory(folder.path("scan.ply"));
    try {
        read_point_set(folder.path("scan.ply"));
        FAIL() << "expected IoError";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("directory"), std::string::npos) << e.what();
    }
}

TEST(ReadPointSet, ErrorsNameTheGivenPath) {
    TempFolder folder;
    const std::string path = folder.write("empty.ply", "");
    try {
        read_point_set(path);
        FAIL() << "expected IoError";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()), path + ": empty file (0 bytes)");
    }
}

} // namespace
} // namespace hrsr::io
