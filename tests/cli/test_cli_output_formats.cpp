// `hrsr reconstruct -o` by extension: ascii PLY (--ascii), OBJ and OFF hold the same vertices,
// triangles and colours as the binary PLY of the same run; an unknown extension is refused
// before any work, and nothing is written.
#include "cli_runner.h"
#include "io/mesh_reader.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"
#include "temp_folder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace hrsr {
namespace {

using testing::Outcome;
using testing::slurp;

class CliOutputFormats : public ::testing::Test {
protected:
    void SetUp() override {
        // The sample with colour and an intensity, reconstructed once as binary PLY.
        PointSet p = io::read_point_set(HRSR_SAMPLE);
        const char* const names[3] = {"red", "green", "blue"};
        for (std::size_t c = 0; c < 3; ++c) {
            PointAttribute a(names[c], ScalarType::UInt8);
            for (std::size_t i = 0; i < p.size(); ++i) a.append(double((i * (c + 3)) % 256));
            p.attributes.push_back(std::move(a));
        }
        PointAttribute intensity("intensity", ScalarType::Float32);
        for (std::size_t i = 0; i < p.size(); ++i) intensity.append(double(i) / 8);
        p.attributes.push_back(std::move(intensity));
        io::write_ply(path("in.ply"), p.positions, p.normals, {}, p.precision, p.attributes);
        ASSERT_EQ(run("out.ply").exit_code, 0);
        binary_ = io::read_mesh(path("out.ply"));
        binary_points_ = io::read_point_set(path("out.ply"));
    }
    Outcome run(const std::string& out, const std::string& options = "") {
        return testing::run(HRSR_EXE,
                            "reconstruct -q " + path("in.ply") + " -o " + path(out) + " " + options,
                            folder_.root());
    }
    std::string path(const std::string& name) const { return folder_.path(name); }

    testing::TempFolder folder_;
    io::MeshFile binary_;
    PointSet binary_points_;
};

TEST_F(CliOutputFormats, AsciiPlyHoldsTheSameValues) {
    ASSERT_EQ(run("ascii.ply", "--ascii").exit_code, 0);
    EXPECT_EQ(slurp(path("ascii.ply")).find("format ascii 1.0\n"), 4u);
    const io::MeshFile mesh = io::read_mesh(path("ascii.ply"));
    const PointSet points = io::read_point_set(path("ascii.ply"));
    EXPECT_EQ(mesh.triangles, binary_.triangles);
    EXPECT_EQ(points.positions, binary_points_.positions);
    EXPECT_EQ(points.normals, binary_points_.normals);
    ASSERT_EQ(points.attributes.size(), 4u);
    for (std::size_t j = 0; j < 4; ++j) {
        EXPECT_EQ(points.attributes[j].name, binary_points_.attributes[j].name);
        EXPECT_EQ(points.attributes[j].type, binary_points_.attributes[j].type);
        EXPECT_EQ(points.attributes[j].bytes, binary_points_.attributes[j].bytes);
    }
}

/// The `f` lines of an OBJ (1-based, "a//a" or "a"), 0-based.
std::vector<Triangle> obj_faces(const std::string& text) {
    std::vector<Triangle> faces;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("f ", 0) != 0) continue;
        std::istringstream words(line.substr(2));
        Triangle t{};
        for (std::uint32_t& v : t) {
            std::string corner;
            words >> corner;
            v = std::uint32_t(std::stoul(corner.substr(0, corner.find('/')))) - 1;
        }
        faces.push_back(t);
    }
    return faces;
}

TEST_F(CliOutputFormats, ObjHoldsPositionsNormalsColourAndFaces) {
    const Outcome r = run("mesh.OBJ");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("hrsr: warning: OBJ has no room for the per-vertex 'intensity'"),
              std::string::npos)
        << r.err;
    const PointSet obj = io::read_point_set(path("mesh.OBJ"));
    ASSERT_EQ(obj.size(), binary_points_.size());
    ASSERT_EQ(obj.attributes.size(), 3u); // colour, back as uchar
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < obj.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            wrong += float(obj.positions[i][k]) != float(binary_points_.positions[i][k]);
            wrong += std::abs(obj.normals[i][k] - binary_points_.normals[i][k]) > 1e-6;
        }
        for (std::size_t c = 0; c < 3; ++c)
            wrong += obj.attributes[c].value(i) != binary_points_.attributes[c].value(i);
    }
    EXPECT_EQ(wrong, 0u);
    EXPECT_EQ(obj_faces(slurp(path("mesh.OBJ"))), binary_.triangles);
}

TEST_F(CliOutputFormats, OffHoldsPositionsColourAndFaces) {
    ASSERT_EQ(run("mesh.off").exit_code, 0);
    std::istringstream off(slurp(path("mesh.off")));
    std::string magic;
    std::size_t vertices = 0, faces = 0, edges = 1;
    off >> magic >> vertices >> faces >> edges;
    EXPECT_EQ(magic, "COFF");
    ASSERT_EQ(vertices, binary_points_.size());
    ASSERT_EQ(faces, binary_.triangles.size());
    EXPECT_EQ(edges, 0u);
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < vertices; ++i) {
        double xyz[3];
        int rgba[4];
        off >> xyz[0] >> xyz[1] >> xyz[2] >> rgba[0] >> rgba[1] >> rgba[2] >> rgba[3];
        for (int k = 0; k < 3; ++k) wrong += float(xyz[k]) != float(binary_points_.positions[i][k]);
        for (std::size_t c = 0; c < 3; ++c)
            wrong += rgba[c] != int(binary_points_.attributes[c].value(i));
        wrong += rgba[3] != 255;
    }
    EXPECT_EQ(wrong, 0u);
    std::vector<Triangle> triangles(faces);
    for (Triangle& t : triangles) {
        int corners = 0;
        off >> corners >> t[0] >> t[1] >> t[2];
        EXPECT_EQ(corners, 3);
    }
    EXPECT_TRUE(off.good());
    EXPECT_EQ(triangles, binary_.triangles);
}

TEST_F(CliOutputFormats, UnknownExtensionIsAUsageErrorBeforeAnyWork) {
    const Outcome r = run("mesh.stl");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown extension .stl"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(path("mesh.stl")));
}

} // namespace
} // namespace hrsr
