// D-32: what the flips leave is cut out; the written mesh has no intersecting pair.
#include "fold_fixtures.h"
#include "io/mesh_reader.h"
#include "io/point_set_reader.h"
#include "mesh/face_quality.h"
#include "mesh/fold_removal.h"
#include "mesh/fold_repair.h"
#include "mesh/mesh_stats.h"
#include "mesh/self_intersections.h"
#include "mesh/welding.h"
#include "reconstruction.h"
#include "vertex_normals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace hrsr {
namespace {

using testing::TestMesh;

// Area-weighted vertex normals: on the folded fixtures they still face the sheet's way.
std::vector<Vec3> face_normals_at_vertices(const TestMesh& m) {
    return testing::area_weighted_vertex_normals(m.positions, m.triangles);
}

struct Removed {
    FoldRemoval removal;
    std::vector<Vec3> positions; ///< of the result's vertices
    std::vector<Triangle> triangles;
};

Removed remove(const TestMesh& m, int threads = 0) {
    Removed r;
    r.triangles = m.triangles;
    r.removal =
        remove_folds(m.positions, face_normals_at_vertices(m), r.triangles, {threads, nullptr});
    for (std::uint32_t v : r.removal.vertex_source) r.positions.push_back(m.positions[v]);
    return r;
}

std::vector<long> genera(const MeshStats& s) {
    std::vector<long> g;
    for (const ComponentTopology& c : s.components) g.push_back(c.genus());
    std::sort(g.begin(), g.end());
    return g;
}

// No pair left by the exact test, a consistently oriented manifold, each vertex in a face, the
// genus kept, and the boundary grown by at most `extra_boundary` edges.
// `joined`: pieces that join one (D-55: a sheet lying on another).
void expect_clean(const TestMesh& before, const Removed& after, std::size_t extra_boundary,
                  std::size_t joined = 0) {
    ASSERT_FALSE(self_intersecting_pairs(before.positions, before.triangles, {}).empty())
        << "the fixture has no fold";
    EXPECT_TRUE(self_intersecting_pairs(after.positions, after.triangles, {}).empty());
    EXPECT_EQ(after.removal.stats.pairs_after, 0u);
    const FoldRemovalStats& st = after.removal.stats;
    EXPECT_GT(st.vertices_removed + st.vertices_reinserted + st.faces_cut, 0u);
    const MeshStats a = measure_mesh(before.positions.size(), before.triangles);
    const MeshStats b = measure_mesh(after.positions.size(), after.triangles);
    EXPECT_EQ(b.non_manifold_edges, 0u);
    EXPECT_EQ(b.non_manifold_vertices, 0u);
    EXPECT_EQ(b.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(b.unreferenced_vertices, 0u);
    EXPECT_EQ(b.vertices, after.positions.size());
    std::vector<long> kept = genera(a);
    kept.resize(kept.size() - joined);
    EXPECT_EQ(kept, genera(b));
    EXPECT_LE(b.boundary_edges, a.boundary_edges + extra_boundary);
}

TEST(FoldRemoval, APushedVertexGoesAndItsHoleIsFilled) {
    const TestMesh m = testing::pushed_vertex();
    const Removed r = remove(m);
    expect_clean(m, r, 0);
    const FoldRemovalStats& st = r.removal.stats;
    EXPECT_EQ(st.faces_cut, 0u);
    EXPECT_GE(st.holes_refilled, 1u);
    // Each removal takes out one vertex and fills its hole (two triangles fewer); a vertex put
    // back splits a face (two more).
    EXPECT_EQ(r.positions.size(), m.positions.size() - st.vertices_removed);
    EXPECT_EQ(r.triangles.size(), m.triangles.size() - 2 * st.vertices_removed);
    EXPECT_EQ(st.vertices_removed + st.vertices_reinserted, st.holes_refilled);
}

TEST(FoldRemoval, CrossingSheetsAreCutApart) {
    const TestMesh m = testing::crossing_sheets();
    const Removed r = remove(m);
    // Two sheets crossing along a line: vertices along it go; what cannot be filled stays open.
    // What is left of the second sheet lies on the first (a thousandth of a spacing apart): its
    // points all go into the first one's faces (D-55), one sheet with every point.
    expect_clean(m, r, 32, 1); // 22 when written
    EXPECT_EQ(r.removal.stats.pieces_absorbed, 1u);
    EXPECT_EQ(r.positions.size(), m.positions.size());
}

TEST(FoldRemoval, AFoldAtABoundary) {
    const TestMesh m = testing::boundary_fold();
    const Removed r = remove(m);
    expect_clean(m, r, 4);
}

// Two faces on one place (ALGORITHM.md D-32) are a pair: the fold goes, and no point with it.
TEST(FoldRemoval, AFinThroughACopyGoes) {
    const TestMesh m = testing::fin_through_a_copy();
    ASSERT_EQ(self_intersecting_pairs(m.positions, m.triangles, {}).size(), 1u);
    const Removed r = remove(m);
    expect_clean(m, r, 0);
    EXPECT_EQ(r.positions.size(), m.positions.size());
    const std::vector<Triangle> welded =
        welded_triangles(r.triangles, same_position_representatives(r.positions));
    EXPECT_EQ(face_quality(r.positions, r.triangles, welded).duplicate_faces, 0u);
}

TEST(FoldRemoval, OverlappingSpheresAndAPiercingTriangle) {
    const TestMesh m = testing::overlapping_spheres();
    const Removed r = remove(m);
    // Every crossing face of the circle goes (each fill would cross the other sphere).
    EXPECT_TRUE(self_intersecting_pairs(r.positions, r.triangles, {}).empty());
    const MeshStats b = measure_mesh(r.positions.size(), r.triangles);
    EXPECT_EQ(b.non_manifold_edges, 0u);
    EXPECT_EQ(b.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(r.removal.stats.pairs_after, 0u);
}

TEST(FoldRemoval, FlatFoldOnFloats) {
    const TestMesh m = testing::flat_fold_on_floats();
    const Removed r = remove(m);
    EXPECT_TRUE(self_intersecting_pairs(r.positions, r.triangles, {}).empty());
    // Corner 0's fan goes and the hole is filled with (1, 2, 3); then 0 goes back beyond the
    // fill's corner at 3 (D-37's corner fill): three triangles tile the first, no point lost.
    EXPECT_EQ(r.triangles.size(), 3u);
    EXPECT_EQ(r.positions.size(), 4u);
    EXPECT_EQ(r.removal.stats.vertices_reinserted, 1u);
}

TEST(FoldRemoval, CleanMeshUnchanged) {
    const TestMesh m = testing::uv_sphere();
    const Removed r = remove(m);
    EXPECT_EQ(r.removal.stats.pairs_before, 0u);
    EXPECT_EQ(r.triangles, m.triangles);
    EXPECT_EQ(r.positions, m.positions);
}

TEST(FoldRemoval, SameResultOnOneAndTwoThreads) {
    const TestMesh m = testing::overlapping_spheres();
    const Removed one = remove(m, 1), two = remove(m, 2);
    EXPECT_EQ(one.triangles, two.triangles);
    EXPECT_EQ(one.removal.vertex_source, two.removal.vertex_source);
}

// A patch of the lion's HRsR mesh before the fold repair (tests/data/folds/README.md): two
// faces cut next to each other leave one four-edge hole that no single cut face's closing
// (close_cut) fits; the closing of small cut holes fills it across. Before it, the boundary went
// 89 -> 86 (that hole open); now 89 -> 82.
// A 554-vertex patch of the lion's mesh before the fold repair (tests/data/folds/README.md).
io::MeshFile lion_patch() {
    return io::read_mesh(std::string(HRSR_TEST_DATA) + "/folds/lion_patch_adjacent_cuts.ply");
}

// As the reconstruction does: one search, D-26's flips, then D-32 on what they left.
Removed flip_then_remove(const TestMesh& m, const std::vector<Vec3>& normals) {
    Removed r;
    r.triangles = m.triangles;
    FoldSearch search(m.positions, r.triangles, {});
    repair_folds(search, r.triangles, RsrOptions{}.fold_repair_rounds);
    r.removal = remove_folds(search, normals, r.triangles);
    for (std::uint32_t v : r.removal.vertex_source) r.positions.push_back(m.positions[v]);
    return r;
}

TEST(FoldRemoval, AHoleOfAdjacentCutsClosesAgain) {
    const io::MeshFile patch = lion_patch();
    const TestMesh m{patch.points.positions, patch.triangles};
    const Removed r = flip_then_remove(m, patch.points.normals);
    expect_clean(m, r, 0);
    const MeshStats before = measure_mesh(m.positions.size(), m.triangles);
    const MeshStats after = measure_mesh(r.positions.size(), r.triangles);
    EXPECT_LE(after.boundary_edges + 7, before.boundary_edges);
    EXPECT_EQ(after.components.size(), before.components.size());
    EXPECT_GE(r.removal.stats.holes_refilled, 1u);
}

// D-32's last step: once every fold is resolved, a vertex it took out goes back over a standing
// face near it (split into three, or with the face across one of its edges into four) where that
// fits. On this patch of the lion it took 13 vertices out and put 1 back; then 8 of them went
// back, five of them over faces turned away from their own normals (the other side of a sheet,
// or a layer turned the other way). Since D-41 a vertex goes back only over faces that face its
// normal; no such face fits around those five, so they stay out and three go back.
TEST(FoldRemoval, TakenOutVerticesGoBackOnceTheFoldsAreResolved) {
    const io::MeshFile patch = lion_patch();
    const TestMesh m{patch.points.positions, patch.triangles};
    const Removed r = flip_then_remove(m, patch.points.normals);
    expect_clean(m, r, 0);
    EXPECT_LE(r.removal.stats.vertices_removed, 11u);
    EXPECT_GE(r.removal.stats.vertices_reinserted, 3u);
    EXPECT_EQ(r.positions.size(), m.positions.size() - r.removal.stats.vertices_removed);
}

// D-32 on a clean patch of `patch_vertices` vertices given with extra vertices without a face
// (D-37's points in no triangle): `placed` of them go in, with `new_faces` faces more; the mesh
// has no intersecting pair, is manifold and consistently oriented, every vertex in a face.
struct Placed {
    MeshStats mesh;
    std::vector<std::uint32_t> vertex_source; ///< the removal's
};
Placed expect_placed(const TestMesh& m, const std::vector<Vec3>& normals,
                     std::size_t patch_vertices, std::size_t placed, std::size_t new_faces) {
    std::vector<Triangle> triangles = m.triangles;
    const FoldRemoval removal = remove_folds(m.positions, normals, triangles, {});
    EXPECT_EQ(removal.stats.pairs_before, 0u);
    EXPECT_EQ(removal.stats.points_placed, placed);
    EXPECT_EQ(removal.stats.vertices_removed, 0u);
    EXPECT_EQ(triangles.size(), m.triangles.size() + new_faces);
    std::vector<Vec3> positions;
    for (std::uint32_t v : removal.vertex_source) positions.push_back(m.positions[v]);
    EXPECT_EQ(positions.size(), patch_vertices + placed);
    EXPECT_TRUE(self_intersecting_pairs(positions, triangles, {}).empty());
    const MeshStats s = measure_mesh(positions.size(), triangles);
    EXPECT_EQ(s.non_manifold_edges + s.non_manifold_vertices, 0u);
    EXPECT_EQ(s.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(s.unreferenced_vertices, 0u);
    return {s, removal.vertex_source};
}

// D-37: vertices given without a face (points in no triangle) go into a face near them as D-32's
// put-back places what it took out: here one just above a flat patch's face goes in, one high
// above it (a spike: 0.8 spacings) and one whose normal faces away a quarter spacing above it
// (the other side of a sheet) stay out, and nothing else changes.
TEST(FoldRemoval, PointsInNoTriangleArePlacedIntoAFaceWhereTheyFit) {
    TestMesh m = testing::square_patch(8);
    const std::size_t patch_vertices = m.positions.size();
    std::vector<Vec3> normals(patch_vertices, Vec3(0, 0, 1));
    m.positions.emplace_back(0.40, 0.33, 0.01); // over a face, a tenth of a spacing up: goes in
    normals.emplace_back(0, 0, 1);
    m.positions.emplace_back(0.65, 0.30, 0.10); // over half the longest side up: stays out
    normals.emplace_back(0, 0, 1);
    m.positions.emplace_back(0.30, 0.70, 0.03); // facing away, 0.17 longest sides up: stays out
    normals.emplace_back(0, 0, -1);
    const Placed p = expect_placed(m, normals, patch_vertices, 1, 2); // a face split in three
    EXPECT_EQ(p.vertex_source.back(), patch_vertices);                // the first extra point
    EXPECT_EQ(p.mesh.boundary_edges, 32u);
}

// D-57: where the normals around a face are turned away (noise, a clump of flipped normals) no
// split of it faces its corners' normals; a point in no triangle over it still goes in, by a
// split that turns as the face does and crosses nothing.
TEST(FoldRemoval, APointGoesInWhereTheNormalsAroundItsFaceAreTurned) {
    TestMesh m = testing::square_patch(8);
    const std::size_t patch_vertices = m.positions.size();
    std::vector<Vec3> normals(patch_vertices, Vec3(0, 0, 1));
    for (int i = 3; i <= 4; ++i) // the cell from (3, 2) to (4, 3), spacing 1/8
        for (int j = 2; j <= 3; ++j) normals[std::size_t(i * 9 + j)] = Vec3(0, 0, -1);
    m.positions.emplace_back(0.40, 0.33, 0.01); // over that cell's upper triangle
    normals.emplace_back(0, 0, 1);
    const Placed p = expect_placed(m, normals, patch_vertices, 1, 2);
    EXPECT_EQ(p.mesh.boundary_edges, 32u);
}

// D-60: a point whose normal is against every face near it (a clump of flipped normals) but
// which lies flat on one (here 0.06 of its longest side up) goes in once nothing else is left to
// do; a point so turned 0.17 longest sides up stays out (D-41: the other side of a sheet).
TEST(FoldRemoval, APointLyingFlatOnAFaceGoesInWhateverItsNormal) {
    TestMesh m = testing::square_patch(8);
    const std::size_t patch_vertices = m.positions.size();
    std::vector<Vec3> normals(patch_vertices, Vec3(0, 0, 1));
    m.positions.emplace_back(0.30, 0.70, 0.01);
    normals.emplace_back(0, 0, -1);
    m.positions.emplace_back(0.65, 0.55, 0.03);
    normals.emplace_back(0, 0, -1);
    const Placed p = expect_placed(m, normals, patch_vertices, 1, 2);
    EXPECT_EQ(p.vertex_source.back(), patch_vertices);
    EXPECT_EQ(p.mesh.boundary_edges, 32u);
}

// D-37 at the border: a point beyond a concave corner of the border (a patch without its last
// cell and corner vertex) closes the corner with two triangles; the border keeps its length.
TEST(FoldRemoval, APointBeyondABorderCornerClosesIt) {
    TestMesh m = testing::square_patch(8);
    m.positions.pop_back(); // the corner (1, 1): its cell's two triangles are the last two
    m.triangles.resize(m.triangles.size() - 2);
    const std::size_t patch_vertices = m.positions.size();
    const std::size_t patch_border = measure_mesh(patch_vertices, m.triangles).boundary_edges;
    std::vector<Vec3> normals(patch_vertices, Vec3(0, 0, 1));
    m.positions.emplace_back(0.95, 0.95, 0.002);
    normals.emplace_back(0, 0, 1);
    EXPECT_EQ(expect_placed(m, normals, patch_vertices, 1, 2).mesh.boundary_edges, patch_border);
}

// D-41 at a straight border: a point just beyond a border edge joins the border, as one triangle
// across the edge or, where that triangle would be a sliver (under 15°), as the edge's face split
// in two; either way the border runs through the point (one edge more). Before D-41 both stayed
// out (no face split into three or four around them faces its way).
TEST(FoldRemoval, APointBeyondAStraightBorderJoinsIt) {
    TestMesh m = testing::square_patch(8);
    const std::size_t patch_vertices = m.positions.size();
    std::vector<Vec3> normals(patch_vertices, Vec3(0, 0, 1));
    m.positions.emplace_back(0.44, -0.03, 0.001); // a triangle across the edge y = 0
    normals.emplace_back(0, 0, 1);
    m.positions.emplace_back(0.81, -0.004, 0.0); // that triangle a sliver: the face split in two
    normals.emplace_back(0, 0, 1);
    const MeshStats s = expect_placed(m, normals, patch_vertices, 2, 2).mesh;
    EXPECT_EQ(s.boundary_edges, 34u);
    EXPECT_EQ(s.boundary_loops, 1u);
}

// `m` without vertex v and its faces (the vertices after v move down by one).
TestMesh without_fan(TestMesh m, std::uint32_t v) {
    std::vector<Triangle> kept;
    for (Triangle t : m.triangles) {
        if (std::find(t.begin(), t.end(), v) != t.end()) continue;
        for (std::uint32_t& w : t) w -= w > v;
        kept.push_back(t);
    }
    m.triangles = kept;
    m.positions.erase(m.positions.begin() + v);
    return m;
}

// `b` appended to `a`.
TestMesh joined(TestMesh a, const TestMesh& b) {
    const auto offset = std::uint32_t(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (Triangle t : b.triangles)
        a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    return a;
}

// After remove_folds on a mesh without folds: every vertex kept, no intersecting pair, a
// consistently oriented manifold. Returns the result's measure.
MeshStats kept_and_clean(const TestMesh& m, const FoldRemoval& r,
                         const std::vector<Triangle>& triangles) {
    EXPECT_EQ(r.vertex_source.size(), m.positions.size()); // no vertex lost
    std::vector<Vec3> positions;
    for (std::uint32_t v : r.vertex_source) positions.push_back(m.positions[v]);
    EXPECT_TRUE(self_intersecting_pairs(positions, triangles, {}).empty());
    const MeshStats s = measure_mesh(positions.size(), triangles);
    EXPECT_EQ(s.non_manifold_edges + s.non_manifold_vertices, 0u);
    EXPECT_EQ(s.inconsistently_oriented_edges, 0u);
    return s;
}

// `corners` and `faces` (over them) appended to m.
void add_piece(TestMesh& m, const std::vector<Vec3>& corners, const std::vector<Triangle>& faces) {
    const auto first = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), corners.begin(), corners.end());
    for (Triangle t : faces) m.triangles.push_back({first + t[0], first + t[1], first + t[2]});
}

// A grid piece of `side` × `side` points (point (i, j) at `at(i, j)`), two faces a cell,
// appended to m.
template <typename At>
void add_grid_piece(TestMesh& m, int side, At&& at) {
    std::vector<Vec3> corners;
    std::vector<Triangle> faces;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) corners.push_back(at(i, j));
    for (int j = 0; j + 1 < side; ++j)
        for (int i = 0; i + 1 < side; ++i) {
            const auto a = std::uint32_t(j * side + i);
            const auto b = a + 1, c = a + std::uint32_t(side), d = c + 1;
            faces.push_back({a, b, d});
            faces.push_back({a, d, c});
        }
    add_piece(m, corners, faces);
}

// remove_folds on `m` (normals up, no fold in it), over `triangles`.
FoldRemoval removed_facing_up(const TestMesh& m, std::vector<Triangle>& triangles) {
    triangles = m.triangles;
    const std::vector<Vec3> normals(m.positions.size(), Vec3(0, 0, 1));
    FoldRemoval r = remove_folds(m.positions, normals, triangles, {});
    EXPECT_EQ(r.stats.pairs_before, 0u);
    return r;
}

// D-55: small pieces lying on a surface join it, every point kept. On a flat patch (normals
// up): a closed tetrahedron a twelfth of the spacing above it (a bubble) and a single triangle
// (a scrap) go in, their points splitting the patch's faces; a tetrahedron far above stays, and
// so does a triangle with one corner too high over the patch (a piece joins whole or not at
// all: its two low corners stay in it).
TEST(FoldRemoval, SmallPiecesOnASurfaceJoinIt) {
    TestMesh m = testing::square_patch(8);
    const std::vector<Triangle> tetrahedron{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
    add_piece(m,
              {{0.30, 0.33, 0.010}, {0.42, 0.36, 0.012}, {0.36, 0.45, 0.008}, {0.37, 0.38, 0.03}},
              tetrahedron);
    add_piece(m, {{0.62, 0.60, 0.005}, {0.70, 0.62, 0.004}, {0.66, 0.69, 0.006}}, {{0, 1, 2}});
    add_piece(m, {{0.30, 0.33, 1.0}, {0.42, 0.36, 1.0}, {0.36, 0.45, 1.0}, {0.37, 0.38, 1.02}},
              tetrahedron);
    add_piece(m, {{0.15, 0.80, 0.005}, {0.26, 0.81, 0.004}, {0.20, 0.88, 0.3}}, {{0, 1, 2}});
    std::vector<Triangle> triangles;
    const FoldRemoval r = removed_facing_up(m, triangles);
    EXPECT_EQ(r.stats.pieces_absorbed, 2u);
    EXPECT_EQ(r.stats.points_absorbed, 7u);
    const MeshStats s = kept_and_clean(m, r, triangles);
    ASSERT_EQ(s.components.size(), 3u); // the patch, the far tetrahedron, the high triangle
    EXPECT_EQ(s.boundary_edges, 32u + 3u);
    // The patch took the seven points: 128 faces, two more for each.
    std::size_t largest = 0;
    for (const ComponentTopology& c : s.components) largest = std::max(largest, c.faces);
    EXPECT_EQ(largest, 128u + 2u * 7u);
}

// D-62: in the last pass a face is against a point's normal only beyond 120° (θ's 60° short of
// opposed). A point 0.17 longest sides over a face (not flat on it: D-60 does not take it)
// whose normal is 100° off the face's goes in; one 150° off stays out (the other side of a
// sheet, D-41).
TEST(FoldRemoval, APointWhoseNormalSaysNothingOfItsSideGoesIn) {
    TestMesh m = testing::square_patch(8);
    const std::size_t patch_vertices = m.positions.size();
    std::vector<Vec3> normals(patch_vertices, Vec3(0, 0, 1));
    const auto off_the_patch = [](double degrees) {
        const double a = degrees * M_PI / 180.0;
        return Vec3(std::sin(a), 0, std::cos(a));
    };
    m.positions.emplace_back(0.30, 0.70, 0.03);
    normals.push_back(off_the_patch(100));
    m.positions.emplace_back(0.65, 0.55, 0.03);
    normals.push_back(off_the_patch(150));
    const Placed p = expect_placed(m, normals, patch_vertices, 1, 2);
    EXPECT_EQ(p.vertex_source.back(), patch_vertices);
    EXPECT_EQ(p.mesh.boundary_edges, 32u);
}

// D-63: a scrap's points join the surface under it by D-62's rule too. Two triangles 0.17 of the
// patch faces' longest side above a patch (too high for D-60's flat rule): one whose points'
// normals are 100° off the patch's (estimated in noise, they say nothing of the side) joins it,
// every point kept; one whose normals are 150° off (the other side of a sheet) stays.
TEST(FoldRemoval, AScrapWhoseNormalsSayNothingOfItsSideJoinsTheSurface) {
    TestMesh m = testing::square_patch(8);
    std::vector<Vec3> normals(m.positions.size(), Vec3(0, 0, 1));
    const auto add_scrap = [&](double x, double degrees) {
        add_piece(m, {{x, 0.40, 0.03}, {x + 0.16, 0.42, 0.03}, {x + 0.06, 0.56, 0.03}},
                  {{0, 1, 2}});
        const double a = degrees * M_PI / 180.0;
        normals.resize(m.positions.size(), Vec3(std::sin(a), 0, std::cos(a)));
    };
    add_scrap(0.15, 100);
    add_scrap(0.60, 150);
    std::vector<Triangle> triangles = m.triangles;
    const FoldRemoval r = remove_folds(m.positions, normals, triangles, {});
    EXPECT_EQ(r.stats.pieces_absorbed, 1u);
    EXPECT_EQ(r.stats.points_absorbed, 3u);
    const MeshStats s = kept_and_clean(m, r, triangles);
    ASSERT_EQ(s.components.size(), 2u); // the patch with the first scrap, the second scrap
    std::size_t largest = 0;
    for (const ComponentTopology& c : s.components) largest = std::max(largest, c.faces);
    EXPECT_EQ(largest, 128u + 2u * 3u);
    EXPECT_EQ(s.boundary_edges, 32u + 3u);
}

// D-60 comes last: a scrap lying on the surface (a triangle 0.17 of the patch faces' longest
// side above a patch) joins it (D-55) although a point turned against both lies flat on the
// scrap; had the point gone into the scrap first, the scrap would no longer be the piece it was,
// and would stay.
TEST(FoldRemoval, APointTurnedAgainstTheSurfaceKeepsNoScrapOut) {
    TestMesh m = testing::square_patch(8);
    add_piece(m, {{0.40, 0.40, 0.03}, {0.56, 0.42, 0.03}, {0.46, 0.56, 0.03}}, {{0, 1, 2}});
    std::vector<Vec3> normals(m.positions.size(), Vec3(0, 0, 1));
    m.positions.emplace_back(0.48, 0.46, 0.031);
    normals.emplace_back(0, 0, -1);
    std::vector<Triangle> triangles = m.triangles;
    const FoldRemoval r = remove_folds(m.positions, normals, triangles, {});
    EXPECT_EQ(r.stats.pieces_absorbed, 1u);
    EXPECT_EQ(r.stats.points_absorbed, 3u);
    // The point itself stays out: 0.17 longest sides over the patch, more than D-60 allows.
    EXPECT_EQ(r.stats.points_placed, 0u);
    EXPECT_EQ(r.vertex_source.size(), m.positions.size() - 1);
    std::vector<Vec3> positions;
    for (std::uint32_t v : r.vertex_source) positions.push_back(m.positions[v]);
    EXPECT_TRUE(self_intersecting_pairs(positions, triangles, {}).empty());
    const MeshStats s = measure_mesh(positions.size(), triangles);
    EXPECT_EQ(s.components.size(), 1u);
    EXPECT_EQ(s.boundary_edges, 32u);
    EXPECT_EQ(s.non_manifold_edges + s.non_manifold_vertices, 0u);
}

// D-55: a bubble pinched to the surface at one of its points (a copy of a patch vertex, as §5.8
// makes it) joins the surface with its three other points; the copy goes, its point stays in
// the patch.
TEST(FoldRemoval, APinchedBubbleJoinsWithoutItsCopy) {
    TestMesh m = testing::square_patch(8);
    const std::size_t patch_vertices = m.positions.size();
    const Vec3 pinch = m.positions[4 * 9 + 4];
    add_piece(m,
              {pinch, pinch + Vec3(0.05, 0.02, 0.010), pinch + Vec3(0.02, 0.06, 0.012),
               pinch + Vec3(0.04, 0.04, 0.03)},
              {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});
    std::vector<Triangle> triangles;
    const FoldRemoval r = removed_facing_up(m, triangles);
    EXPECT_EQ(r.stats.pieces_absorbed, 1u);
    EXPECT_EQ(r.stats.points_absorbed, 3u);
    ASSERT_EQ(r.vertex_source.size(), m.positions.size() - 1); // the copy
    std::vector<std::uint32_t> kept(r.vertex_source);
    std::sort(kept.begin(), kept.end());
    for (std::uint32_t v = 0; v < patch_vertices; ++v)
        EXPECT_TRUE(std::binary_search(kept.begin(), kept.end(), v)) << v;
    std::vector<Vec3> positions;
    for (std::uint32_t v : r.vertex_source) positions.push_back(m.positions[v]);
    EXPECT_TRUE(self_intersecting_pairs(positions, triangles, {}).empty());
    const MeshStats s = measure_mesh(positions.size(), triangles);
    EXPECT_EQ(s.components.size(), 1u);
    EXPECT_EQ(s.non_manifold_edges + s.non_manifold_vertices, 0u);
    EXPECT_EQ(s.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(s.boundary_edges, 32u);
    EXPECT_EQ(s.faces, 128u + 2u * 3u);
}

// D-55: a piece that points of an earlier one joined (here a scrap beside another triangle's
// border, both half a unit above the patch; as large, they go in the order of their points) is
// not the piece it was: it stays as it stands, and nothing reaches the patch.
TEST(FoldRemoval, APieceThatTookPointsStays) {
    TestMesh m = testing::square_patch(8);
    add_piece(m, {{0.46, 0.26, 0.5}, {0.52, 0.30, 0.5}, {0.46, 0.34, 0.5}}, {{0, 1, 2}});
    add_piece(m, {{0.2, 0.2, 0.5}, {0.4, 0.2, 0.5}, {0.4, 0.4, 0.5}}, {{0, 1, 2}});
    std::vector<Triangle> triangles;
    const FoldRemoval r = removed_facing_up(m, triangles);
    const MeshStats s = kept_and_clean(m, r, triangles);
    EXPECT_EQ(r.stats.pieces_absorbed, 1u); // the scrap, into the quad
    EXPECT_EQ(r.stats.points_absorbed, 3u);
    ASSERT_EQ(s.components.size(), 2u);
    std::size_t largest = 0;
    for (const ComponentTopology& c : s.components) largest = std::max(largest, c.faces);
    EXPECT_EQ(largest, 128u); // the patch took nothing
    for (std::uint32_t v : r.vertex_source) {
        if (v >= 81) {
            EXPECT_EQ(m.positions[v][2], 0.5);
        }
    }
}

// D-45 (D-59: both methods): a piece closed but for loops of at most `pinhole_edges` edges is
// closed, every vertex kept; a patch whose outer border is longer keeps its 8-edge inner hole
// too, and a tent with more border than interior vertices (8 against 1) keeps its border.
TEST(FoldRemoval, PinholesOfAClosedPieceCloseOtherBordersStay) {
    const TestMesh sphere = without_fan(testing::uv_sphere(8, 10), 0); // a 10-edge hole
    // Two neighbouring inner vertices (5, 5) and (5, 6) of the 11 × 11 grid go: an 8-edge hole
    // in a patch with a 40-edge border.
    const TestMesh holed_patch = without_fan(without_fan(testing::square_patch(10), 60), 60);
    TestMesh tent; // an octagonal pyramid: a cap under it would fit
    tent.positions.emplace_back(0, 0, 0.3);
    for (std::uint32_t k = 0; k < 8; ++k) {
        tent.positions.emplace_back(std::cos(k * M_PI / 4), std::sin(k * M_PI / 4), 0);
        tent.triangles.push_back({0, 1 + k, 1 + (k + 1) % 8});
    }
    const TestMesh m = joined(joined(sphere, testing::shifted(holed_patch, Vec3(3, 0, 0))),
                              testing::shifted(tent, Vec3(5, 0, 0)));
    for (const std::size_t pinhole_edges : {kMaxFilledLoop, std::size_t(20)}) {
        std::vector<Triangle> triangles = m.triangles;
        const FoldRemoval r =
            remove_folds(m.positions, face_normals_at_vertices(m), triangles, {}, pinhole_edges);
        const MeshStats s = kept_and_clean(m, r, triangles);
        ASSERT_EQ(s.components.size(), 3u);
        const bool closes = pinhole_edges >= 10;
        EXPECT_EQ(r.stats.small_holes_closed, closes ? 1u : 0u);
        EXPECT_EQ(s.boundary_edges, (closes ? 0u : 10u) + 40u + 8u + 8u);
        EXPECT_EQ(s.boundary_loops, closes ? 3u : 4u);
        EXPECT_EQ(genera(s), (std::vector<long>{0, 0, 0}));
    }
}

// `m` without the faces whose three corners all satisfy `gone`, and without the vertices that
// leaves without a face.
template <class Gone>
TestMesh without_faces(const TestMesh& m, Gone&& gone) {
    TestMesh out;
    std::vector<std::uint32_t> renumbered(m.positions.size(), ~0u);
    for (const Triangle& t : m.triangles) {
        if (gone(m.positions[t[0]]) && gone(m.positions[t[1]]) && gone(m.positions[t[2]])) continue;
        Triangle kept;
        for (int k = 0; k < 3; ++k) {
            if (renumbered[t[k]] == ~0u) {
                renumbered[t[k]] = std::uint32_t(out.positions.size());
                out.positions.push_back(m.positions[t[k]]);
            }
            kept[k] = renumbered[t[k]];
        }
        out.triangles.push_back(kept);
    }
    return out;
}

// D-48: a slit (a border loop whose sides are a spacing apart, long for its width) closes with
// every vertex kept; one two spacings wide, a round hole and the patch's own border stay.
TEST(FoldRemoval, SlitsCloseRoundHolesStay) {
    constexpr int n = 24;                    // spacing 1/24
    const auto on_slit = [](const Vec3& p) { // one row of cells, ten long
        return p[1] > 5.5 / n && p[1] < 7.5 / n && p[0] > 3.5 / n && p[0] < 14.5 / n;
    };
    const auto on_wide_slit = [](const Vec3& p) { // two rows of cells, ten long
        return p[1] > 10.5 / n && p[1] < 13.5 / n && p[0] > 3.5 / n && p[0] < 14.5 / n;
    };
    const auto in_hole = [](const Vec3& p) { // a block of 4 x 4 cells
        return p[0] > 15.5 / n && p[0] < 20.5 / n && p[1] > 14.5 / n && p[1] < 19.5 / n;
    };
    const TestMesh m = without_faces(
        without_faces(without_faces(testing::square_patch(n), on_slit), on_wide_slit), in_hole);
    ASSERT_EQ(measure_mesh(m.positions.size(), m.triangles).boundary_loops, 4u);
    std::vector<Triangle> triangles = m.triangles;
    const FoldRemoval r = remove_folds(m.positions, face_normals_at_vertices(m), triangles, {});
    const MeshStats s = kept_and_clean(m, r, triangles);
    EXPECT_EQ(r.stats.slits_closed, 1u);
    EXPECT_EQ(r.stats.small_holes_closed, 0u);
    EXPECT_EQ(s.boundary_loops, 3u);
    EXPECT_EQ(s.boundary_edges, 4u * n + 24u + 16u);
    EXPECT_EQ(genera(s), (std::vector<long>{0}));
}

// D-48 on a closed surface: a slit along a torus's tube closes it with its genus.
TEST(FoldRemoval, ASlitOfATorusClosesWithItsHandle) {
    const TestMesh torus = testing::torus(64, 24);
    // The row of cells just above the outer equator, over a quarter of the ring: 15 long.
    const TestMesh m = without_faces(torus, [](const Vec3& p) {
        return p[2] > -1e-9 && p[2] < 0.1 && p[0] > 0 && p[1] > 0 && std::hypot(p[0], p[1]) > 1.2;
    });
    const MeshStats before = measure_mesh(m.positions.size(), m.triangles);
    ASSERT_EQ(before.boundary_loops, 1u);
    ASSERT_EQ(before.boundary_edges, 32u);
    std::vector<Triangle> triangles = m.triangles;
    const FoldRemoval r = remove_folds(m.positions, face_normals_at_vertices(m), triangles, {});
    const MeshStats s = kept_and_clean(m, r, triangles);
    EXPECT_EQ(r.stats.slits_closed, 1u);
    EXPECT_EQ(s.boundary_edges, 0u);
    EXPECT_EQ(genera(s), (std::vector<long>{1}));
}

// D-38: a gap of up to six edges is closed after the folds, every vertex kept; seven edges is
// beyond it (and beyond D-45, which is off here: pinhole_edges at D-28's five).
TEST(FoldRemoval, GapsOfUpToSixEdgesClose) {
    for (const int edges : {5, 6, 7}) {
        const TestMesh m = without_fan(testing::uv_sphere(8, edges), 0);
        std::vector<Triangle> triangles = m.triangles;
        const FoldRemoval r = remove_folds(m.positions, face_normals_at_vertices(m), triangles, {});
        const MeshStats s = kept_and_clean(m, r, triangles);
        const bool closes = edges <= 6;
        EXPECT_EQ(r.stats.small_holes_closed, closes ? 1u : 0u) << edges;
        EXPECT_EQ(s.boundary_edges, closes ? 0u : std::size_t(edges)) << edges;
    }
}

// A patch of n × n cells (spacing 1/n) with the square hole where x and y are between the given
// cell numbers (its border corners kept).
TestMesh patch_with_hole(int n, int first, int last) {
    return without_faces(testing::square_patch(n), [&](const Vec3& p) {
        return p[0] > (first - 0.5) / n && p[0] < (last + 0.5) / n && p[1] > (first - 0.5) / n &&
               p[1] < (last + 0.5) / n;
    });
}

// A grid piece of `side` × `side` points inside patch_with_hole(n, first, last)'s hole, a
// spacing clear of its border (by default as large as that leaves), at `height` above the patch.
void add_piece_in_hole(TestMesh& m, int n, int first, int last, double height, int side = 0) {
    if (side == 0) side = last - first - 1;
    add_grid_piece(m, side, [&](int i, int j) { // a little off the patch's grid: not a copy
        return Vec3((first + 1 + i + 0.1) / n, (first + 1 + j + 0.05) / n, height);
    });
}

// patch_with_hole() with add_piece_in_hole().
TestMesh patch_with_piece_in_hole(int n, int first, int last, double height, int side = 0) {
    TestMesh m = patch_with_hole(n, first, last);
    add_piece_in_hole(m, n, first, last, height, side);
    return m;
}

// D-56: a piece lying in a hole of the surface (RsR on noise leaves a disc so, its border and
// the hole's two faces of the rotation system) joins it: the hole closes and every point of the
// piece goes into its fill. A piece far above the hole stays.
TEST(FoldRemoval, APieceInAHoleClosesIt) {
    constexpr int n = 24;
    for (const double height : {0.002, 0.5}) {
        const TestMesh m = patch_with_piece_in_hole(n, 8, 14, height); // a 24-edge hole, 5 × 5
        std::vector<Triangle> triangles;
        const FoldRemoval r = removed_facing_up(m, triangles);
        const MeshStats s = kept_and_clean(m, r, triangles);
        const bool joins = height < 0.1;
        EXPECT_EQ(r.stats.pieces_absorbed, joins ? 1u : 0u) << height;
        EXPECT_EQ(r.stats.piece_holes_closed, joins ? 1u : 0u) << height;
        EXPECT_EQ(r.stats.points_absorbed, joins ? 25u : 0u) << height;
        EXPECT_EQ(s.components.size(), joins ? 1u : 2u) << height;
        EXPECT_EQ(s.boundary_edges, 4u * n + (joins ? 0u : 24u + 16u)) << height;
        EXPECT_EQ(genera(s), (std::vector<long>(s.components.size(), 0))) << height;
    }
}

// D-58: a scrap lying over a piece in a hole (the noise of the 1M graded triple torus stacks
// them so), its points numbered before the piece's, takes none of the piece's points, and the
// piece goes first: the hole closes under the piece, every point goes into the fill, and the
// scrap then joins the fill too, one piece. Were the large scrap's faces open to the piece's
// points, it would grow by them and stand beside the fill; were the small scrap (too far from the
// hole's border to join it) tried first, it would join the piece and the piece would stand.
TEST(FoldRemoval, AScrapOverAPieceInAHoleJoinsTheFill) {
    constexpr int n = 24;
    const std::vector<std::vector<Vec3>> scraps{
        {{9.3 / n, 9.4 / n, 0.006}, {12.8 / n, 9.6 / n, 0.006}, {11.0 / n, 12.7 / n, 0.006}},
        {{10.6 / n, 10.6 / n, 0.006}, {11.4 / n, 10.7 / n, 0.006}, {11.0 / n, 11.4 / n, 0.006}}};
    for (const std::vector<Vec3>& scrap : scraps) {
        TestMesh m = patch_with_hole(n, 8, 14);
        add_piece(m, scrap, {{0, 1, 2}});
        add_piece_in_hole(m, n, 8, 14, 0.002);
        std::vector<Triangle> triangles;
        const FoldRemoval r = removed_facing_up(m, triangles);
        const MeshStats s = kept_and_clean(m, r, triangles);
        EXPECT_EQ(r.stats.piece_holes_closed, 1u) << scrap[0][0];
        EXPECT_EQ(r.stats.pieces_absorbed, 2u) << scrap[0][0];
        EXPECT_EQ(r.stats.points_absorbed, 25u + 3u) << scrap[0][0];
        EXPECT_EQ(s.components.size(), 1u) << scrap[0][0];
        EXPECT_EQ(s.boundary_edges, 4u * n) << scrap[0][0];
        EXPECT_EQ(genera(s), std::vector<long>{0}) << scrap[0][0];
    }
}

// D-58: where no surface is under a scrap, it may still join another small piece it lies on
// (scraps of noise become one): a triangle just over a 4 × 4 grid of points far above the patch
// goes into the grid's faces; the grid stays where it is.
TEST(FoldRemoval, AScrapOnlyOverAnotherJoinsIt) {
    TestMesh m = testing::square_patch(8);
    constexpr int side = 4;
    add_grid_piece(m, side, [](int i, int j) { return Vec3(0.3 + i / 8.0, 0.3 + j / 8.0, 1.0); });
    add_piece(m, {{0.36, 0.35, 1.004}, {0.52, 0.37, 1.004}, {0.44, 0.51, 1.004}}, {{0, 1, 2}});
    std::vector<Triangle> triangles;
    const FoldRemoval r = removed_facing_up(m, triangles);
    const MeshStats s = kept_and_clean(m, r, triangles);
    EXPECT_EQ(r.stats.pieces_absorbed, 1u);
    EXPECT_EQ(r.stats.points_absorbed, 3u);
    EXPECT_EQ(s.components.size(), 2u);
    EXPECT_EQ(s.boundary_edges, 4u * 8 + 4u * (side - 1));
}

// D-56 keeps a hole in the data with a scrap in it (D-30): 3 × 3 points in a hole of 6 × 6
// spacings, where a surface would have about 42, do not close it. The scrap joins the hole's
// border by D-55 instead (its points across the border edges, D-41), every point kept.
TEST(FoldRemoval, AScrapInAHoleLeavesItOpen) {
    constexpr int n = 24;
    const TestMesh m = patch_with_piece_in_hole(n, 8, 14, 0.002, 3);
    std::vector<Triangle> triangles;
    const FoldRemoval r = removed_facing_up(m, triangles);
    const MeshStats s = kept_and_clean(m, r, triangles);
    EXPECT_EQ(r.stats.piece_holes_closed, 0u);
    EXPECT_EQ(s.boundary_loops, 2u);
    EXPECT_GT(s.boundary_edges, 4u * n + 20u);
}

// D-56 closes holes, not rims: a piece lying in a bowl (a 7 × 7 grid of points just above an
// 8 × 8-cell bowl, more than the bowl's 32-edge rim would need) does not cap the bowl (a fill
// across the rim would face away from the normals); it joins the bowl's faces (D-55).
TEST(FoldRemoval, APieceInABowlLeavesItsRimOpen) {
    const auto bowl = [](double x, double y) {
        return 0.5 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5));
    };
    TestMesh m = testing::height_patch(8, bowl);
    add_grid_piece(m, 7, [&](int i, int j) {
        const double x = (i + 1.1) / 8, y = (j + 1.05) / 8;
        return Vec3(x, y, bowl(x, y) + 0.004);
    });
    std::vector<Triangle> triangles;
    const FoldRemoval r = removed_facing_up(m, triangles);
    const MeshStats s = kept_and_clean(m, r, triangles);
    EXPECT_EQ(r.stats.piece_holes_closed, 0u);
    EXPECT_EQ(r.stats.pieces_absorbed, 1u); // onto the bowl's faces (D-55)
    EXPECT_EQ(s.boundary_edges, 32u);
}

// D-56 stops at holes of kMaxOptimisedHole (48) edges: a piece in a 52-edge hole stays, and so
// does the hole.
TEST(FoldRemoval, APieceInALargeHoleStays) {
    constexpr int n = 24;
    const TestMesh m = patch_with_piece_in_hole(n, 4, 17, 0.002); // 52 edges
    std::vector<Triangle> triangles;
    const FoldRemoval r = removed_facing_up(m, triangles);
    const MeshStats s = kept_and_clean(m, r, triangles);
    EXPECT_EQ(r.stats.piece_holes_closed, 0u);
    EXPECT_EQ(s.components.size(), 2u);
    EXPECT_EQ(s.boundary_edges, 4u * n + 52u + 4u * 11u);
}

// The edges of each border loop of a manifold triangle list (a border edge a → b has no b → a).
std::vector<std::size_t> border_loop_edges(const std::vector<Triangle>& triangles) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const Triangle& t : triangles)
        for (int k = 0; k < 3; ++k) edges.emplace(t[k], t[(k + 1) % 3]);
    std::map<std::uint32_t, std::uint32_t> next; // along the border
    for (const auto& [a, b] : edges)
        if (!edges.count({b, a})) next.emplace(a, b);
    std::vector<std::size_t> loops;
    while (!next.empty()) {
        std::size_t length = 0;
        auto at = next.begin();
        while (at != next.end()) { // along the loop until back at its first edge (erased)
            const std::uint32_t to = at->second;
            next.erase(at);
            ++length;
            at = next.find(to);
        }
        loops.push_back(length);
    }
    return loops;
}

// The shipped sample at the defaults, both methods: the written coordinates (float) have no
// intersecting pair, every point taken out is reported as dropped in a fold, and r_v stays. No
// gap of up to six edges stays open (D-38); D-61: RsR's mesh kept one of six edges, whose fill
// took out a point that only a split turning as its face does (D-57) puts back.
TEST(FoldRemoval, OwlAtDefaultsHasNoIntersectingPairNorShortGap) {
    const PointSet cloud = io::read_point_set(HRSR_SAMPLE);
    for (const Method method : {Method::Hrsr, Method::Rsr}) {
        ReconstructionOptions options;
        options.method = method;
        ReconstructionReport report;
        const Reconstruction mesh = reconstruct(cloud, options, {}, report);
        std::vector<Vec3> written;
        for (std::uint32_t i : mesh.vertex_input_index) {
            const Vec3& p = cloud.positions[i];
            written.emplace_back(float(p[0]), float(p[1]), float(p[2]));
        }
        EXPECT_TRUE(self_intersecting_pairs(written, mesh.triangles, {}).empty());
        const std::vector<Triangle> welded =
            welded_triangles(mesh.triangles, same_position_representatives(written));
        EXPECT_EQ(face_quality(written, mesh.triangles, welded).duplicate_faces, 0u);
        EXPECT_EQ(report.fold_removal.pairs_after, 0u);
        const std::set<std::uint32_t> vertices(mesh.vertex_input_index.begin(),
                                               mesh.vertex_input_index.end());
        for (std::uint32_t i : report.dropped_fold) EXPECT_EQ(vertices.count(i), 0u);
        EXPECT_LE(report.dropped_fold.size(), report.fold_removal.vertices_removed);
        EXPECT_GE(report.vertex_reference_ratio, 0.999);
        EXPECT_EQ(report.mesh.non_manifold_edges, 0u);
        EXPECT_EQ(report.mesh.non_manifold_vertices, 0u);
        EXPECT_EQ(report.mesh.inconsistently_oriented_edges, 0u);
        EXPECT_EQ(report.mesh.unreferenced_vertices, 0u);
        const std::vector<std::size_t> loops = border_loop_edges(mesh.triangles);
        EXPECT_EQ(loops.size(), report.mesh.boundary_loops);
        for (std::size_t edges : loops) EXPECT_GT(edges, 6u) << int(method);
    }
}

} // namespace
} // namespace hrsr
