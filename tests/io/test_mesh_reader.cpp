// Reading PLY meshes (vertices and faces) for `hrsr check`.
#include "errors.h"
#include "io/mesh_reader.h"
#include "io/ply_writer.h"

#include "temp_folder.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>

namespace hrsr::io {
namespace {

using hrsr::testing::TempFolder;

MeshFile parse(const std::string& bytes) {
    std::istringstream in(bytes);
    return read_ply_mesh(in, "mesh.ply");
}

std::string error_of(const std::string& bytes) {
    try {
        parse(bytes);
    } catch (const IoError& e) {
        return e.what();
    }
    return "(no error)";
}

const std::string kAsciiHeader = "ply\nformat ascii 1.0\nelement vertex 5\n"
                                 "property float x\nproperty float y\nproperty float z\n";
const std::string kVertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n";

TEST(MeshReader, AsciiPolygonsBecomeFansAndOtherPropertiesAreSkipped) {
    const MeshFile m = parse(kAsciiHeader +
                             "element face 2\nproperty uchar red\n"
                             "property list uchar int vertex_indices\nend_header\n" +
                             kVertices + "7 4 0 1 2 3\n9 3 1 4 2\n");
    ASSERT_EQ(m.points.size(), 5u);
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
    EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
    EXPECT_EQ(m.triangles[2], (Triangle{1, 4, 2}));
    EXPECT_EQ(m.polygons_triangulated, 1u);
}

TEST(MeshReader, VertexIndexNameAndUnsignedTypes) {
    const MeshFile m =
        parse(kAsciiHeader + "element face 1\nproperty list uint uint vertex_index\nend_header\n" +
              kVertices + "3 4 3 2\n");
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.triangles[0], (Triangle{4, 3, 2}));
}

TEST(MeshReader, PointCloudHasNoTriangles) {
    const MeshFile m = parse(kAsciiHeader + "end_header\n" + kVertices);
    EXPECT_EQ(m.points.size(), 5u);
    EXPECT_TRUE(m.triangles.empty());
}

TEST(MeshReader, BinaryRoundTripOfOurWriter) {
    TempFolder folder;
    const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    const std::vector<Vec3> n = {Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1), Vec3(0, 0, 1)};
    const std::vector<Triangle> t = {{0, 1, 2}, {0, 3, 1}, {3, 2, 1}};
    const std::string path = folder.path("m.ply");
    write_ply(path, p, n, t, CoordinatePrecision::Double);
    const MeshFile m = read_mesh(path);
    EXPECT_EQ(m.points.positions, p);
    EXPECT_EQ(m.points.normals, n);
    EXPECT_EQ(m.triangles, t);
}

TEST(MeshReader, BinaryFacesBeforeVerticesBigEndian) {
    std::string bytes = "ply\nformat binary_big_endian 1.0\nelement face 1\n"
                        "property list uchar int vertex_indices\nelement vertex 3\n"
                        "property float x\nproperty float y\nproperty float z\nend_header\n";
    const auto put_be = [&bytes](std::uint32_t u) {
        for (int s = 24; s >= 0; s -= 8) bytes += char((u >> s) & 0xff);
    };
    bytes += char(3);
    put_be(2);
    put_be(0);
    put_be(1);
    for (float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) {
        std::uint32_t u;
        std::memcpy(&u, &f, 4);
        put_be(u);
    }
    const MeshFile m = parse(bytes);
    ASSERT_EQ(m.points.size(), 3u);
    EXPECT_EQ(m.points.positions[1], Vec3(1, 0, 0));
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.triangles[0], (Triangle{2, 0, 1}));
}

TEST(MeshReader, BadFacesAreClearErrors) {
    const std::string face = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    EXPECT_NE(error_of(kAsciiHeader + face + kVertices + "3 0 1 5\n").find("refers to vertex 5"),
              std::string::npos);
    EXPECT_NE(error_of(kAsciiHeader + face + kVertices + "3 0 -1 2\n").find("invalid vertex index"),
              std::string::npos);
    EXPECT_NE(error_of(kAsciiHeader + face + kVertices + "2 0 1\n").find("2 corners"),
              std::string::npos);
    EXPECT_NE(error_of(kAsciiHeader + face + kVertices + "3 0 1\n").find("truncated"),
              std::string::npos);
    EXPECT_NE(error_of(kAsciiHeader +
                       "element face 1\nproperty list uchar int corners\n"
                       "end_header\n" +
                       kVertices + "3 0 1 2\n")
                  .find("no 'vertex_indices'"),
              std::string::npos);
    EXPECT_EQ(error_of(kAsciiHeader + face + kVertices + "3 0 1 2\n"), "(no error)");
}

TEST(MeshReader, OnlyPlyFilesAndErrorsNameThePath) {
    TempFolder folder;
    const std::string obj = folder.write("m.obj", "v 0 0 0\n");
    try {
        read_mesh(obj);
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(obj, 0), 0u);
        EXPECT_NE(std::string(e.what()).find("supported: .ply"), std::string::npos);
    }
    EXPECT_THROW(read_mesh(folder.path("missing.ply")), IoError);
    EXPECT_THROW(read_mesh(folder.root().string()), IoError);
}

} // namespace
} // namespace hrsr::io
