// D-23 and D-52: RsR's last faces of four darts closed by the diagonal whose two triangles wind
// with their corners' normals, on a hand-built rotation.
#include "knn.h"
#include "rsr/embedding.h"
#include "rsr/faces.h"
#include "rsr/geometry_check.h"
#include "rsr/small_holes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace hrsr {
namespace {

enum : std::uint32_t { A, B, C, D, E };

struct Closed {
    std::vector<rsr::LocalTriangle> triangles;
    rsr::SmallHoleStats stats;
    bool diagonal_bd_inserted = false;
};

// The faces of the edges A–B, B–C, C–D, D–A and C–E over `positions` (normals +z) after D-23:
// the quad A, B, C, D is the only face of four darts (E hangs off C so that the outer face has
// six and stays open).
Closed close_quad_abcd(const std::vector<Vec3>& positions) {
    const std::vector<Vec3> normals(positions.size(), Vec3(0, 0, 1));
    rsr::RotationSystem rotation(positions, normals);
    for (const auto& [u, v] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
             {A, B}, {B, C}, {C, D}, {D, A}, {C, E}})
        rotation.insert_edge(u, v);
    rsr::Faces faces(rotation);
    faces.label_all();
    const KnnIndex index(positions);
    rsr::GeometryCheck geometry(index, positions, normals, rotation);
    Closed closed;
    rsr::Embedding embedding{rotation, faces, geometry, closed.triangles, nullptr};
    closed.stats = rsr::close_small_holes(embedding);
    closed.diagonal_bd_inserted = rotation.adjacent(B, D);
    return closed;
}

// The quad A(0, 0) → B(0.05, 1) → C(3, 2) → D(0, 4), counter-clockwise seen from +z, is concave
// (248° at B). The diagonal A–C makes the larger smallest angle (15° against 0.95°), but it runs
// outside the quad: its triangle A, B, C winds clockwise, a fold.
TEST(RsrSmallFaces, QuadIsClosedByTheDiagonalWhoseTrianglesFaceTheNormals) {
    const std::vector<Vec3> positions{{0, 0, 0}, {0.05, 1, 0}, {3, 2, 0}, {0, 4, 0}, {6, 3, 0}};
    const Closed closed = close_quad_abcd(positions);
    EXPECT_EQ(closed.stats.quads_split + closed.stats.quads_recorded_only, 1u);
    ASSERT_EQ(closed.triangles.size(), 2u);
    for (const rsr::LocalTriangle& t : closed.triangles) {
        const Vec3 &a = positions[t[0]], &b = positions[t[1]], &c = positions[t[2]];
        EXPECT_GT(((b - a) ^ (c - a))[2], 0) << t[0] << " " << t[1] << " " << t[2];
    }
    EXPECT_TRUE(closed.diagonal_bd_inserted || closed.stats.quads_recorded_only == 1);
}

// A bow tie: A(0, 0) → B(1, 1.2) → C(1.1, 0) → D(0, 1), its sides A–B and C–D crossing. Each
// diagonal folds one triangle; as among unfolded ones, the larger smallest angle wins: A–C
// (0.738 rad against 0.679 for B–D).
TEST(RsrSmallFaces, WhereBothDiagonalsFoldTheLargerSmallestAngleWins) {
    const Closed closed =
        close_quad_abcd({{0, 0, 0}, {1, 1.2, 0}, {1.1, 0, 0}, {0, 1, 0}, {3, -1, 0}});
    ASSERT_EQ(closed.triangles.size(), 2u);
    for (const rsr::LocalTriangle& t : closed.triangles)
        EXPECT_TRUE(std::count(t.begin(), t.end(), A) && std::count(t.begin(), t.end(), C))
            << t[0] << " " << t[1] << " " << t[2];
}

} // namespace
} // namespace hrsr
