// D-6 (mesh/outward.h): closed pieces wound inwards are turned; open pieces and outward ones are
// left; a vertex where two turned pieces touch keeps its normal (turned twice).
#include "mesh/mesh_stats.h"
#include "mesh/outward.h"

#include <gtest/gtest.h>

namespace hrsr {
namespace {

// A tetrahedron on corners (a, b, c, d), wound outwards when `outwards`.
void tetrahedron(std::vector<Triangle>& t, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                 std::uint32_t d, bool outwards) {
    const std::vector<Triangle> out{{a, c, b}, {a, b, d}, {b, c, d}, {a, d, c}};
    for (Triangle f : out) {
        if (!outwards) std::swap(f[1], f[2]);
        t.push_back(f);
    }
}

TEST(Outward, ClosedPiecesWoundInwardsTurnAndTouchingOnesTurnTheirSharedVertexTwice) {
    // Corners of a tetrahedron (0, 1, 2, 3) at the origin's side; the second shares vertex 0.
    const std::vector<Vec3> p{{0, 0, 0},  {1, 0, 0},  {0, 1, 0},  {0, 0, 1}, {-1, 0, 0},
                              {0, -1, 0}, {0, 0, -1}, {5, 0, 0},  {6, 0, 0}, {5, 1, 0},
                              {5, 0, 1},  {9, 0, 0},  {10, 0, 0}, {9, 1, 0}};
    std::vector<Triangle> triangles;
    tetrahedron(triangles, 0, 1, 2, 3, false); // inwards
    tetrahedron(triangles, 0, 4, 5, 6, true);  // checked below: whichever way it encloses
    tetrahedron(triangles, 7, 8, 9, 10, true); // outwards
    triangles.push_back({11, 13, 12});         // open, wound "inwards"
    std::vector<std::uint32_t> component;
    const MeshStats stats = measure_mesh(p.size(), triangles, &component);
    ASSERT_EQ(stats.components.size(), 4u);
    std::vector<double> before = signed_volumes(p, triangles, component, 4);
    ASSERT_LT(before[component[0]], 0);
    ASSERT_GT(before[component[8]], 0);
    // Make the second piece inward too, whatever its corner order gave.
    if (before[component[4]] > 0)
        for (std::size_t t = 4; t < 8; ++t) std::swap(triangles[t][1], triangles[t][2]);
    const std::vector<Triangle> given = triangles;
    std::vector<Vec3> normals(p.size());
    for (std::size_t v = 0; v < p.size(); ++v) normals[v] = Vec3(double(v), 1, 0);
    const std::vector<Vec3> given_normals = normals;

    EXPECT_EQ(turn_closed_components_outwards(p, stats, component, triangles, normals), 2u);
    const std::vector<double> after = signed_volumes(p, triangles, component, 4);
    for (std::size_t c = 0; c < 3; ++c) EXPECT_GT(after[c], 0) << "piece " << c;
    for (std::size_t t = 0; t < 8; ++t)
        EXPECT_EQ(triangles[t], (Triangle{given[t][0], given[t][2], given[t][1]}));
    for (std::size_t t = 8; t < given.size(); ++t) EXPECT_EQ(triangles[t], given[t]);
    EXPECT_EQ(normals[0], given_normals[0]); // in both turned pieces
    for (std::uint32_t v : {1u, 2u, 3u, 4u, 5u, 6u}) EXPECT_EQ(normals[v], -given_normals[v]);
    for (std::uint32_t v = 7; v < p.size(); ++v) EXPECT_EQ(normals[v], given_normals[v]);
}

} // namespace
} // namespace hrsr
