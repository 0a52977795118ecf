// Per-point attributes: every scalar vertex property of a PLY (any type, ascii or binary, either
// byte order) and OBJ vertex colours are read with their name, type and value; the PLY writer
// writes them back unchanged; several files read together must have the same attributes.
#include "errors.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"

#include "read_bytes.h"
#include "temp_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace hrsr::io {
namespace {

using hrsr::testing::read_bytes;
using hrsr::testing::TempFolder;

struct Column {
    const char* type;
    const char* name;
    ScalarType expected;
    std::vector<double> values; // one per point (3 points)
};

/// One property of each PLY type, with values at the edges of each type's range.
std::vector<Column> every_type() {
    return {
        {"uchar", "red", ScalarType::UInt8, {0, 128, 255}},
        {"ushort", "green", ScalarType::UInt16, {0, 256, 65535}},
        {"uint8", "alpha", ScalarType::UInt8, {255, 1, 0}},
        {"char", "label", ScalarType::Int8, {-128, 0, 127}},
        {"short", "classification", ScalarType::Int16, {-32768, 7, 32767}},
        {"int", "segment", ScalarType::Int32, {-2147483648.0, 5, 2147483647.0}},
        {"uint", "id", ScalarType::UInt32, {0, 17, 4294967295.0}},
        {"float", "intensity", ScalarType::Float32, {0.25, -1.5, 3.0e38}},
        {"double", "gps_time", ScalarType::Float64, {1e-300, 123456789.123456789, -0.1}},
    };
}

std::string put(const std::string& type, double v, bool big_endian) {
    unsigned char b[8];
    std::size_t n = 0;
    const auto raw = [&](auto value) {
        n = sizeof value;
        std::memcpy(b, &value, n);
    };
    if (type == "uchar" || type == "uint8") raw(static_cast<std::uint8_t>(v));
    if (type == "char") raw(static_cast<std::int8_t>(v));
    if (type == "ushort") raw(static_cast<std::uint16_t>(v));
    if (type == "short") raw(static_cast<std::int16_t>(v));
    if (type == "int") raw(static_cast<std::int32_t>(v));
    if (type == "uint") raw(static_cast<std::uint32_t>(v));
    if (type == "float") raw(static_cast<float>(v));
    if (type == "double") raw(v);
    const std::uint16_t one = 1;
    const bool host_big = *reinterpret_cast<const unsigned char*>(&one) == 0;
    if (host_big != big_endian) std::reverse(b, b + n);
    return std::string(reinterpret_cast<const char*>(b), n);
}

/// Three points with x y z and `columns` interleaved (x, columns..., y, z), plus a list
/// property, in the given format.
std::string ply_with(const std::vector<Column>& columns, const std::string& format) {
    std::string h = "ply\nformat " + format + " 1.0\nelement vertex 3\nproperty float x\n";
    for (const Column& c : columns) h += std::string("property ") + c.type + " " + c.name + "\n";
    h += "property float y\nproperty float z\nproperty list uchar float texture\nend_header\n";
    std::ostringstream data;
    data.precision(17);
    const bool big = format == "binary_big_endian";
    for (int i = 0; i < 3; ++i) {
        if (format == "ascii") {
            data << i;
            for (const Column& c : columns) data << " " << c.values[static_cast<std::size_t>(i)];
            data << " " << 2 * i << " " << 3 * i << " 2 0.5 0.25\n";
        } else {
            data << put("float", i, big);
            for (const Column& c : columns)
                data << put(c.type, c.values[static_cast<std::size_t>(i)], big);
            data << put("float", 2 * i, big) << put("float", 3 * i, big) << put("uchar", 2, big)
                 << put("float", 0.5, big) << put("float", 0.25, big);
        }
    }
    return h + data.str();
}

void expect_columns(const PointSet& p, const std::vector<Column>& columns) {
    ASSERT_EQ(p.attributes.size(), columns.size());
    for (std::size_t j = 0; j < columns.size(); ++j) {
        const PointAttribute& a = p.attributes[j];
        EXPECT_EQ(a.name, columns[j].name);
        EXPECT_EQ(a.type, columns[j].expected) << a.name;
        ASSERT_EQ(a.size(), 3u) << a.name;
        for (std::size_t i = 0; i < 3; ++i) {
            const double expected = columns[j].expected == ScalarType::Float32
                                        ? double(float(columns[j].values[i]))
                                        : columns[j].values[i];
            EXPECT_EQ(a.value(i), expected) << a.name << " of point " << i;
        }
    }
}

TEST(PointAttributes, EveryScalarPropertyOfEveryTypeIsReadInEveryFormat) {
    for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
        SCOPED_TRACE(format);
        const PointSet p = read_bytes(read_ply, ply_with(every_type(), format));
        ASSERT_EQ(p.size(), 3u);
        EXPECT_EQ(p.positions[2], Vec3(2, 4, 6));
        expect_columns(p, every_type());
        // The list property is left out, and the user is told.
        ASSERT_EQ(p.warnings.size(), 1u);
        EXPECT_NE(p.warnings[0].find("'texture' is a list"), std::string::npos) << p.warnings[0];
    }
}

TEST(PointAttributes, NoAttributesOptionReadsOnlyGeometry) {
    const PointSet p =
        read_bytes(read_ply, ply_with(every_type(), "binary_little_endian"), {false});
    EXPECT_EQ(p.size(), 3u);
    EXPECT_TRUE(p.attributes.empty());
    EXPECT_EQ(p.positions[1], Vec3(1, 2, 3));
}

TEST(PointAttributes, AsciiValueOutsideItsTypeIsAnErrorNamingTheProperty) {
    std::vector<Column> columns = {{"uchar", "red", ScalarType::UInt8, {0, 256, 1}}};
    try {
        read_bytes(read_ply, ply_with(columns, "ascii"));
        FAIL() << "no error";
    } catch (const IoError& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("cloud: ", 0), 0u) << m;
        EXPECT_NE(m.find("vertex 2 of 3"), std::string::npos) << m;
        EXPECT_NE(m.find("'red'"), std::string::npos) << m;
        EXPECT_NE(m.find("uchar"), std::string::npos) << m;
    }
    // Without attributes the same file reads (its geometry is fine).
    EXPECT_EQ(read_bytes(read_ply, ply_with(columns, "ascii"), {false}).size(), 3u);
}

TEST(PointAttributes, GeometryNamesAreNeverAttributes) {
    // Incomplete normals (nx only) are neither normals nor an attribute (the writer's nx).
    const std::string bytes = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                              "property float y\nproperty float z\nproperty float nx\n"
                              "property float quality\nend_header\n1 2 3 0.5 9\n";
    const PointSet p = read_bytes(read_ply, bytes);
    EXPECT_FALSE(p.has_normals());
    ASSERT_EQ(p.attributes.size(), 1u);
    EXPECT_EQ(p.attributes[0].name, "quality");
    EXPECT_EQ(p.attributes[0].value(0), 9.0);
}

TEST(PointAttributes, ObjVertexColoursBecomeUcharRgb) {
    const PointSet unit = read_bytes(read_obj, "v 0 0 0 1 0.5 0\nv 1 0 0 0 0 1\nvn 0 0 1\n");
    ASSERT_EQ(unit.attributes.size(), 3u);
    EXPECT_EQ(unit.attributes[0].name, "red");
    EXPECT_EQ(unit.attributes[2].name, "blue");
    for (const PointAttribute& a : unit.attributes) EXPECT_EQ(a.type, ScalarType::UInt8);
    EXPECT_EQ(unit.attributes[0].value(0), 255.0);
    EXPECT_EQ(unit.attributes[1].value(0), 128.0); // round(0.5 * 255)
    EXPECT_EQ(unit.attributes[2].value(1), 255.0);

    const PointSet bytes = read_bytes(read_obj, "v 0 0 0 255 10 0\nv 1 0 0 3 2 1\n");
    ASSERT_EQ(bytes.attributes.size(), 3u);
    EXPECT_EQ(bytes.attributes[0].value(0), 255.0);
    EXPECT_EQ(bytes.attributes[1].value(0), 10.0);
    EXPECT_EQ(bytes.attributes[2].value(1), 1.0);

    // Some vertices without colour: none kept, with a warning; "v x y z w" is no colour.
    const PointSet partial = read_bytes(read_obj, "v 0 0 0 1 1 1\nv 1 0 0\n");
    EXPECT_TRUE(partial.attributes.empty());
    EXPECT_EQ(partial.warnings.size(), 1u);
    const PointSet weighted = read_bytes(read_obj, "v 0 0 0 1\nv 1 0 0 1\n");
    EXPECT_TRUE(weighted.attributes.empty());
    EXPECT_TRUE(read_bytes(read_obj, "v 0 0 0 1 1 1\n", {false}).attributes.empty());
}

TEST(PointAttributes, WriterWritesEveryAttributeBackUnchanged) {
    TempFolder folder;
    const PointSet in = read_bytes(read_ply, ply_with(every_type(), "binary_big_endian"));
    const std::vector<Vec3> normals(3, Vec3(0, 0, 1));
    write_ply(folder.path("out.ply"), in.positions, normals, {{0, 1, 2}}, in.precision,
              in.attributes);
    const PointSet out = read_point_set(folder.path("out.ply"));
    EXPECT_EQ(out.positions, in.positions);
    EXPECT_TRUE(out.has_normals());
    expect_columns(out, every_type());
    EXPECT_TRUE(out.warnings.empty());

    // An attribute whose size or name is wrong is refused.
    PointAttribute short_one("quality", ScalarType::Float32);
    short_one.append(1);
    EXPECT_THROW(write_ply(folder.path("bad.ply"), in.positions, {}, {}, in.precision, {short_one}),
                 std::invalid_argument);
    PointAttribute named_x = gather(in.attributes[0], {0, 1, 2});
    named_x.name = "nx";
    EXPECT_THROW(write_ply(folder.path("bad.ply"), in.positions, {}, {}, in.precision, {named_x}),
                 std::invalid_argument);
}

TEST(PointAttributes, GatherFollowsTheIndexMap) {
    PointAttribute a("label", ScalarType::Int16);
    for (double v : {10.0, -20.0, 30.0}) a.append(v);
    const PointAttribute g = gather(a, {2, 0, 0, 1});
    ASSERT_EQ(g.size(), 4u);
    EXPECT_EQ(g.type, ScalarType::Int16);
    EXPECT_EQ(g.value(0), 30.0);
    EXPECT_EQ(g.value(1), 10.0);
    EXPECT_EQ(g.value(2), 10.0);
    EXPECT_EQ(g.value(3), -20.0);
}

TEST(PointAttributes, SeveralFilesAreOneCloudWithTheSameAttributes) {
    TempFolder folder;
    std::vector<Column> first = every_type(), second = every_type();
    for (Column& c : second) std::reverse(c.values.begin(), c.values.end());
    const std::string a = folder.write("a.ply", ply_with(first, "ascii"));
    const std::string b = folder.write("b.ply", ply_with(second, "binary_little_endian"));
    const PointSet both = read_point_sets({a, b});
    ASSERT_EQ(both.size(), 6u);
    EXPECT_EQ(both.positions[3], Vec3(0, 0, 0));
    ASSERT_EQ(both.attributes.size(), first.size());
    for (std::size_t j = 0; j < first.size(); ++j)
        for (std::size_t i = 0; i < 3; ++i) {
            EXPECT_EQ(both.attributes[j].value(i),
                      read_bytes(read_ply, ply_with(first, "ascii")).attributes[j].value(i));
            EXPECT_EQ(both.attributes[j].value(3 + i), first[j].expected == ScalarType::Float32
                                                           ? double(float(second[j].values[i]))
                                                           : second[j].values[i]);
        }
    // Warnings name the file they are about.
    ASSERT_EQ(both.warnings.size(), 2u);
    EXPECT_EQ(both.warnings[1].rfind(b + ": ", 0), 0u) << both.warnings[1];
}

TEST(PointAttributes, FilesWithDifferentAttributesAreAnErrorNamingTheFile) {
    TempFolder folder;
    const std::vector<Column> colour = {{"uchar", "red", ScalarType::UInt8, {1, 2, 3}}};
    const std::vector<Column> wide = {{"ushort", "red", ScalarType::UInt16, {1, 2, 3}}};
    const std::string a = folder.write("a.ply", ply_with(colour, "ascii"));
    const std::string b = folder.write("b.ply", ply_with(wide, "ascii"));
    const std::string c = folder.write("c.xyz", "0 0 1\n0 1 0\n");
    for (const std::string& other : {b, c}) {
        try {
            read_point_sets({a, other});
            FAIL() << "no error for " << other;
        } catch (const IoError& e) {
            const std::string m = e.what();
            EXPECT_EQ(m.rfind(other + ": ", 0), 0u) << m;
            EXPECT_NE(m.find("attributes"), std::string::npos) << m;
            EXPECT_NE(m.find(a), std::string::npos) << m;
        }
    }
    // Without attributes, the same files are one cloud.
    EXPECT_EQ(read_point_sets({a, b, c}, {false}).size(), 8u);
    // Normals in one file only: an error too.
    const std::string n = folder.write("n.xyz", "0 0 1 0 0 1\n");
    EXPECT_THROW(read_point_sets({c, n}, {false}), IoError);
}

} // namespace
} // namespace hrsr::io
