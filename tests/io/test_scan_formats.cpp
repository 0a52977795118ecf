// The scanner formats: Leica PTS, PCL PCD (ascii, binary, binary_compressed; packed colour;
// NaN pixels) and LAS/LAZ (versions 1.2 and 1.4, point formats 0-10, through LASzip). Each test
// writes its own small files; every attribute value of every point is checked by index. Bad
// files give an IoError naming the file and the problem.
#include "errors.h"
#include "io/point_set_reader.h"

#include "read_bytes.h"
#include "temp_folder.h"

#include <gtest/gtest.h>

#ifdef HRSR_HAVE_LASZIP
#include <laszip/laszip_api.h>
#endif
#ifdef HRSR_HAVE_LZF
extern "C" {
#include <liblzf/lzf.h>
}
#endif

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace hrsr::io {
namespace {

using hrsr::testing::TempFolder;

/// Bad files are named "scan" in the messages.
PointSet read(testing::StreamReader reader, const std::string& bytes, ReadOptions options = {}) {
    return testing::read_bytes(reader, bytes, options, "scan");
}

/// Reading must throw an IoError starting with the file name and containing `word`.
void expect_error(PointSet (*reader)(std::istream&, const std::string&, const ReadOptions&),
                  const std::string& bytes, const std::string& word) {
    try {
        read(reader, bytes);
        ADD_FAILURE() << "no error; expected one about '" << word << "'";
    } catch (const IoError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("scan: ", 0), 0u) << m;
        EXPECT_NE(m.find(word), std::string::npos) << "'" << word << "' not in: " << m;
    }
}

const PointAttribute* find(const PointSet& p, const std::string& name) {
    for (const PointAttribute& a : p.attributes)
        if (a.name == name) return &a;
    return nullptr;
}

std::vector<std::string> names(const PointSet& p) {
    std::vector<std::string> n;
    for (const PointAttribute& a : p.attributes) n.push_back(a.name);
    return n;
}

// ---------------------------------------------------------------------------------------------
// PTS

TEST(PtsReader, IntensityAndColourOfEveryPoint) {
    const PointSet p = read(read_pts, "3\n1 2 3 -2048 255 0 10\n4 5 6 0 1 2 3\n"
                                      "7 8 9.5 2047 9 8 7\n");
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p.positions[2], Vec3(7, 8, 9.5));
    EXPECT_EQ(p.precision, CoordinatePrecision::Double);
    ASSERT_EQ(names(p), (std::vector<std::string>{"intensity", "red", "green", "blue"}));
    EXPECT_EQ(p.attributes[0].type, ScalarType::Int16);
    EXPECT_EQ(p.attributes[1].type, ScalarType::UInt8);
    const double expected[4][3] = {{-2048, 0, 2047}, {255, 1, 9}, {0, 2, 8}, {10, 3, 7}};
    for (std::size_t j = 0; j < 4; ++j)
        for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(p.attributes[j].value(i), expected[j][i]);
}

TEST(PtsReader, BlocksFloatIntensityAndPlainPoints) {
    const PointSet two_blocks = read(read_pts, "2\n0 0 0 0.5\n1 0 0 0.25\n1\n0 1 0 1\n");
    ASSERT_EQ(two_blocks.size(), 3u);
    ASSERT_EQ(names(two_blocks), std::vector<std::string>{"intensity"});
    EXPECT_EQ(two_blocks.attributes[0].type, ScalarType::Float32);
    EXPECT_EQ(two_blocks.attributes[0].value(1), 0.25);
    const PointSet plain = read(read_pts, "2\r\n0 0 0\r\n1 2 3\r\n");
    EXPECT_EQ(plain.size(), 2u);
    EXPECT_TRUE(plain.attributes.empty());
    const PointSet rgb_only = read(read_pts, "1\n0 0 0 1 2 3\n");
    EXPECT_EQ(names(rgb_only), (std::vector<std::string>{"red", "green", "blue"}));
    EXPECT_TRUE(read(read_pts, "1\n0 0 0 1 2 3 4\n", {false}).attributes.empty());
}

TEST(PtsReader, BadFilesAreErrors) {
    expect_error(read_pts, "3\n0 0 0\n1 1 1\n", "wrong point count");
    expect_error(read_pts, "1\n0 0 0\n1 1 1\n", "wrong point count");
    expect_error(read_pts, "2\n0 0 0 1\n1 1 1\n", "found 3 numbers");
    expect_error(read_pts, "0 0 0\n", "before the first point count");
    expect_error(read_pts, "1\n0 0 zero\n", "'zero'");
    expect_error(read_pts, "1\n0 0 0 1 300 0 0\n", "0-255");
    expect_error(read_pts, "", "no point count");
    expect_error(read_pts, "2.5\n0 0 0\n", "point count");
}

// ---------------------------------------------------------------------------------------------
// PCD

/// A small organized cloud (2 x 3, one NaN pixel) with normals, packed rgba, an intensity and a
/// label; `packed` is the colour of point i as PCL packs it (0xAARRGGBB).
struct PcdCloud {
    std::vector<float> x = {0, 1, std::numeric_limits<float>::quiet_NaN(), 3, 4.5f, 5},
                       y = {0, 0, 0, 1, 1, 1}, z = {1, 1, 1, 2, 2, 2.25f};
    std::vector<std::uint32_t> packed = {0xff102030, 0x00ffffff, 0x01020304,
                                         0x80000000, 0xff0000ff, 0x7f7f7f7f};
    std::vector<float> intensity = {0.5f, 1, 2, -3, 1e-3f, 7};
    std::vector<std::int16_t> label = {-1, 2, 3, 32767, -32768, 0};
    std::size_t size() const { return x.size(); }

    std::string header(const std::string& data, const std::string& rgb_type = "U") const {
        return "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n"
               "FIELDS x y z normal_x normal_y normal_z rgba intensity label _\n"
               "SIZE 4 4 4 4 4 4 4 4 2 1\nTYPE F F F F F F " +
               rgb_type +
               " F I U\nCOUNT 1 1 1 1 1 1 1 1 1 1\nWIDTH 3\nHEIGHT 2\n"
               "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 6\nDATA " +
               data + "\n";
    }
    template <class T>
    static void put(std::string& s, T v) {
        s.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    /// The bytes of field `f` of point i.
    std::string field(std::size_t f, std::size_t i) const {
        std::string s;
        switch (f) {
        case 0:
            put(s, x[i]);
            break;
        case 1:
            put(s, y[i]);
            break;
        case 2:
            put(s, z[i]);
            break;
        case 3:
            put(s, 0.0f);
            break;
        case 4:
            put(s, 0.0f);
            break;
        case 5:
            put(s, 1.0f);
            break;
        case 6:
            put(s, packed[i]);
            break;
        case 7:
            put(s, intensity[i]);
            break;
        case 8:
            put(s, label[i]);
            break;
        default:
            put(s, std::uint8_t(0xAB));
            break;
        }
        return s;
    }
    std::string binary() const {
        std::string s = header("binary");
        for (std::size_t i = 0; i < size(); ++i)
            for (std::size_t f = 0; f < 10; ++f) s += field(f, i);
        return s;
    }
    /// Field-major (PCL's binary_compressed layout) before compression.
    std::string columns() const {
        std::string s;
        for (std::size_t f = 0; f < 10; ++f)
            for (std::size_t i = 0; i < size(); ++i) s += field(f, i);
        return s;
    }
    std::string ascii() const {
        std::ostringstream s;
        s.precision(9);
        s << header("ascii");
        for (std::size_t i = 0; i < size(); ++i)
            s << x[i] << " " << y[i] << " " << z[i] << " 0 0 1 " << packed[i] << " " << intensity[i]
              << " " << label[i] << " 171\n";
        return s.str();
    }
};

void expect_pcd_cloud(const PointSet& p, const PcdCloud& c) {
    ASSERT_EQ(p.size(), 5u); // the NaN pixel is skipped
    ASSERT_EQ(p.normals.size(), 5u);
    EXPECT_EQ(p.precision, CoordinatePrecision::Float);
    ASSERT_EQ(names(p),
              (std::vector<std::string>{"red", "green", "blue", "alpha", "intensity", "label"}));
    EXPECT_EQ(find(p, "label")->type, ScalarType::Int16);
    EXPECT_EQ(find(p, "intensity")->type, ScalarType::Float32);
    EXPECT_EQ(find(p, "red")->type, ScalarType::UInt8);
    std::size_t k = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        if (std::isnan(c.x[i])) continue;
        EXPECT_EQ(p.positions[k], Vec3(c.x[i], c.y[i], c.z[i])) << i;
        EXPECT_EQ(p.normals[k], Vec3(0, 0, 1));
        EXPECT_EQ(find(p, "red")->value(k), double((c.packed[i] >> 16) & 0xff)) << i;
        EXPECT_EQ(find(p, "green")->value(k), double((c.packed[i] >> 8) & 0xff)) << i;
        EXPECT_EQ(find(p, "blue")->value(k), double(c.packed[i] & 0xff)) << i;
        EXPECT_EQ(find(p, "alpha")->value(k), double(c.packed[i] >> 24)) << i;
        EXPECT_EQ(find(p, "intensity")->value(k), double(c.intensity[i])) << i;
        EXPECT_EQ(find(p, "label")->value(k), double(c.label[i])) << i;
        ++k;
    }
    ASSERT_EQ(p.warnings.size(), 1u);
    EXPECT_NE(p.warnings[0].find("1 of 6 points have NaN"), std::string::npos) << p.warnings[0];
}

TEST(PcdReader, AsciiAndBinaryGiveEveryFieldOfEveryMeasuredPoint) {
    const PcdCloud c;
    expect_pcd_cloud(read(read_pcd, c.ascii()), c);
    expect_pcd_cloud(read(read_pcd, c.binary()), c);
}

TEST(PcdReader, PackedFloatRgbIsUnpacked) {
    // PCL stores rgb as a float whose bits are 0x00RRGGBB.
    std::string s =
        "VERSION .7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F F\nWIDTH 1\nDATA binary\n";
    const float xyz[3] = {1, 2, 3};
    const std::uint32_t bits = 0x00C08040;
    s.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    s.append(reinterpret_cast<const char*>(&bits), 4);
    const PointSet p = read(read_pcd, s);
    ASSERT_EQ(names(p), (std::vector<std::string>{"red", "green", "blue"}));
    EXPECT_EQ(p.attributes[0].value(0), 0xC0);
    EXPECT_EQ(p.attributes[1].value(0), 0x80);
    EXPECT_EQ(p.attributes[2].value(0), 0x40);
    EXPECT_TRUE(read(read_pcd, s, {false}).attributes.empty());
}

#ifdef HRSR_HAVE_LZF
std::string compressed(const PcdCloud& c, std::string columns) {
    std::vector<char> out(columns.size() * 2 + 64);
    const unsigned n =
        lzf_compress(columns.data(), unsigned(columns.size()), out.data(), unsigned(out.size()));
    std::string s = c.header("binary_compressed");
    PcdCloud::put(s, std::uint32_t(n));
    PcdCloud::put(s, std::uint32_t(columns.size()));
    return s + std::string(out.data(), n);
}

TEST(PcdReader, BinaryCompressedGivesTheSamePoints) {
    const PcdCloud c;
    expect_pcd_cloud(read(read_pcd, compressed(c, c.columns())), c);
}

TEST(PcdReader, CorruptOrTruncatedCompressedBlocksAreErrors) {
    const PcdCloud c;
    const std::string good = compressed(c, c.columns());
    expect_error(read_pcd, good.substr(0, good.size() - 5), "truncated");
    std::string lying = good;
    const std::size_t data = good.find("DATA binary_compressed\n") + 23;
    lying[data + 4] = char(lying[data + 4] + 4); // the uncompressed size
    expect_error(read_pcd, lying, "wrong point count");
    std::string corrupt = good;
    for (std::size_t i = data + 8; i < corrupt.size(); ++i) corrupt[i] = char(0xff);
    expect_error(read_pcd, corrupt, "corrupt compressed block");
    // An empty compressed block that claims points (found by fuzz_read_pcd).
    std::string empty = good.substr(0, data);
    PcdCloud::put(empty, std::uint32_t(0));
    PcdCloud::put(empty, std::uint32_t(c.columns().size()));
    expect_error(read_pcd, empty, "corrupt compressed block");
}
#endif

TEST(PcdReader, BadFilesAreErrors) {
    const PcdCloud c;
    const std::string binary = c.binary();
    expect_error(read_pcd, binary.substr(0, binary.size() - 3), "truncated");
    std::string type = binary;
    type.replace(type.find("TYPE F F F"), 10, "TYPE F F X");
    expect_error(read_pcd, type, "unknown type 'X'");
    std::string size = binary;
    size.replace(size.find("SIZE 4 4 4 4"), 12, "SIZE 4 4 4 3");
    expect_error(read_pcd, size, "unknown type 'F' of size 3");
    std::string points = binary;
    points.replace(points.find("POINTS 6"), 8, "POINTS 7");
    expect_error(read_pcd, points, "wrong point count");
    const std::string ascii = c.ascii();
    expect_error(read_pcd, ascii.substr(0, ascii.rfind('\n', ascii.size() - 2) + 1),
                 "wrong point count");
    expect_error(read_pcd, ascii + "1 2 3 0 0 1 0 0 0 0\n", "wrong point count");
    expect_error(read_pcd, "VERSION 0.7\nFIELDS a b\nSIZE 4 4\nTYPE F F\nWIDTH 0\nDATA ascii\n",
                 "no x, y and z");
    expect_error(read_pcd, "ply\nformat ascii 1.0\n", "unknown keyword 'ply'");
    expect_error(read_pcd, "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\n", "before its DATA");
    expect_error(read_pcd, "", "empty file");
    // A header running to the file's end (no newline after DATA) that claims 10^15 points: an
    // error before any block is allocated (fuzz_read_pcd found the allocation, session 27).
    expect_error(read_pcd,
                 "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\n"
                 "HEIGHT 250000000000000\nDATA binary",
                 "truncated");
    expect_error(read_pcd, c.header("zip"), "unknown DATA 'zip'");
}

// ---------------------------------------------------------------------------------------------
// LAS / LAZ

#ifdef HRSR_HAVE_LASZIP
constexpr std::uint16_t kRecordLength[11] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

/// Point i of the test clouds: georeferenced coordinates (offsets of 10^5-10^6 units at
/// millimetre scale) and every field a value that depends on i.
laszip_point point(std::size_t i, int format) {
    laszip_point p{};
    p.X = std::int32_t(1000 * i + 123);
    p.Y = -std::int32_t(7 * i * i);
    p.Z = std::int32_t(i % 13) * 250 - 1;
    p.intensity = std::uint16_t(i * 997);
    if (format >= 6)
        p.extended_classification = std::uint8_t(40 + i % 200);
    else
        p.classification = std::uint8_t(i % 32);
    p.gps_time = 1e9 + double(i) / 3.0;
    for (int c = 0; c < 4; ++c) p.rgb[c] = std::uint16_t(i * 256 + std::size_t(c) * 4099);
    return p;
}

/// A LAS (or LAZ) file of n points of `format`, written by LASzip.
std::string las_file(int format, bool compress, std::size_t n) {
    laszip_POINTER w = nullptr;
    EXPECT_EQ(laszip_create(&w), 0);
    laszip_header* h = nullptr;
    laszip_get_header_pointer(w, &h);
    h->version_major = 1;
    h->version_minor = format >= 6 ? 4 : 2;
    h->header_size = format >= 6 ? 375 : 227;
    h->offset_to_point_data = h->header_size;
    h->point_data_format = std::uint8_t(format);
    h->point_data_record_length = kRecordLength[format];
    h->number_of_point_records = format >= 6 ? 0 : std::uint32_t(n);
    h->extended_number_of_point_records = format >= 6 ? n : 0;
    h->x_scale_factor = h->y_scale_factor = h->z_scale_factor = 0.001;
    h->x_offset = 512345.0;
    h->y_offset = 5402111.0;
    h->z_offset = 120.5;
    std::ostringstream out(std::ios::binary);
    EXPECT_EQ(laszip_open_writer_stream(w, out, compress ? 1 : 0, 0), 0);
    for (std::size_t i = 0; i < n; ++i) {
        laszip_point p = point(i, format);
        if (format >= 6) p.extended_point_type = 1;
        EXPECT_EQ(laszip_set_point(w, &p), 0);
        EXPECT_EQ(laszip_write_point(w), 0);
    }
    EXPECT_EQ(laszip_close_writer(w), 0);
    laszip_destroy(w);
    return out.str();
}

TEST(LasReader, EveryPointFormatPlainAndCompressed) {
    constexpr std::size_t n = 300;
    for (int format = 0; format <= 10; ++format)
        for (const bool compress : {false, true}) {
            SCOPED_TRACE("point format " + std::to_string(format) + (compress ? " LAZ" : " LAS"));
            const PointSet p = read(read_las, las_file(format, compress, n));
            ASSERT_EQ(p.size(), n);
            EXPECT_EQ(p.precision, CoordinatePrecision::Double);
            const bool gps = format == 1 || format >= 3;
            const bool rgb = format == 2 || format == 3 || format == 5 || format == 7 ||
                             format == 8 || format == 10;
            const bool nir = format == 8 || format == 10;
            std::vector<std::string> expected = {"intensity", "classification"};
            if (gps) expected.push_back("gps_time");
            if (rgb) expected.insert(expected.end(), {"red", "green", "blue"});
            if (nir) expected.push_back("nir");
            ASSERT_EQ(names(p), expected);
            for (std::size_t i = 0; i < n; ++i) {
                const laszip_point q = point(i, format);
                ASSERT_EQ(p.positions[i], Vec3(0.001 * q.X + 512345.0, 0.001 * q.Y + 5402111.0,
                                               0.001 * q.Z + 120.5));
                ASSERT_EQ(find(p, "intensity")->value(i), q.intensity);
                ASSERT_EQ(find(p, "classification")->value(i),
                          format >= 6 ? q.extended_classification : q.classification);
                if (gps) {
                    ASSERT_EQ(find(p, "gps_time")->value(i), q.gps_time);
                }
                if (rgb) {
                    ASSERT_EQ(find(p, "red")->value(i), q.rgb[0]);
                    ASSERT_EQ(find(p, "green")->value(i), q.rgb[1]);
                    ASSERT_EQ(find(p, "blue")->value(i), q.rgb[2]);
                }
                if (nir) {
                    ASSERT_EQ(find(p, "nir")->value(i), q.rgb[3]);
                }
            }
            EXPECT_EQ(find(p, "red") != nullptr ? find(p, "red")->type : ScalarType::UInt16,
                      ScalarType::UInt16);
        }
}

TEST(LasReader, LargeCoordinatesKeepMillimetres) {
    const PointSet p = read(read_las, las_file(0, true, 3));
    // 5,402,111 m northing at 1 mm: needs a double (a float has 0.5 m steps there).
    EXPECT_EQ(p.positions[1][1], 5402111.0 - 0.007);
    EXPECT_NE(double(float(p.positions[1][1])), p.positions[1][1]);
    EXPECT_TRUE(read(read_las, las_file(3, true, 3), {false}).attributes.empty());
}

TEST(LasReader, TruncatedCorruptOrMiscountedFilesAreErrors) {
    const std::string las = las_file(2, false, 50);
    expect_error(read_las, las.substr(0, las.size() - 10), "wrong point count");
    expect_error(read_las, las + std::string(26, '\0'), "wrong point count");
    const std::string laz = las_file(3, true, 5000);
    expect_error(read_las, laz.substr(0, laz.size() / 2), "truncated or corrupt");
    expect_error(read_las, las.substr(0, 100), "not a readable LAS/LAZ file");
    expect_error(read_las, "LASF", "not a readable LAS/LAZ file");
    expect_error(read_las, "", "not a readable LAS/LAZ file");
    std::string garbage = laz;
    for (std::size_t i = laz.size() / 3; i < laz.size(); i += 7)
        garbage[i] = char(garbage[i] ^ 0x5a);
    try {
        const PointSet p = read(read_las, garbage);
        EXPECT_EQ(p.size(), 5000u); // LAZ has no checksum: damage may decode to other values
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("scan: ", 0), 0u) << e.what();
    }
}
#endif

TEST(ScanFormats, ChosenByExtension) {
    TempFolder folder;
    const std::string pts = folder.write("a.PTS", "1\n1 2 3\n");
    EXPECT_EQ(read_point_set(pts).positions.at(0), Vec3(1, 2, 3));
    const std::string pcd = folder.write("a.pcd", PcdCloud().ascii());
    EXPECT_EQ(read_point_set(pcd).size(), 5u);
#ifdef HRSR_HAVE_LASZIP
    const std::string laz = folder.write("a.laz", las_file(1, true, 4));
    EXPECT_EQ(read_point_set(laz).size(), 4u);
    const std::string las = folder.write("a.LAS", las_file(1, false, 4));
    EXPECT_EQ(read_point_set(las).positions, read_point_set(laz).positions);
#endif
}

} // namespace
} // namespace hrsr::io
