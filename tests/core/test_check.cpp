// hrsr check's measures on meshes with known properties.
#include "errors.h"
#include "mesh/check.h"
#include "mesh/self_intersections.h"
#include "mesh/surface_distance.h"
#include "mesh/triangle_grid.h"

#include "fold_fixtures.h"
#include "mesh_fixtures.h"
#include "vcg_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>

namespace hrsr {
namespace {

using testing::TestMesh;

MeshCheck check(const TestMesh& m, const CheckOptions& o = {}) {
    return check_mesh({m.positions, m.triangles}, nullptr, nullptr, o, {});
}

std::uint32_t add_vertex(TestMesh& m, const Vec3& p) {
    m.positions.push_back(p);
    return std::uint32_t(m.positions.size() - 1);
}

/// Adds `other` to `m` as a separate piece.
void append(TestMesh& m, const TestMesh& other) {
    const auto offset = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
    for (Triangle f : other.triangles) {
        for (std::uint32_t& v : f) v += offset;
        m.triangles.push_back(f);
    }
}

TEST(Check, ClosedSphereIsGenusZeroWithoutBoundary) {
    const MeshCheck c = check(testing::uv_sphere());
    EXPECT_EQ(c.topology.vertices, 2u + 15u * 32u);
    EXPECT_EQ(c.topology.faces, 2u * 32u * 15u);
    EXPECT_EQ(c.topology.boundary_edges, 0u);
    EXPECT_EQ(c.topology.boundary_loops, 0u);
    EXPECT_EQ(c.topology.non_manifold_edges, 0u);
    EXPECT_EQ(c.topology.non_manifold_vertices, 0u);
    ASSERT_EQ(c.topology.components.size(), 1u);
    EXPECT_TRUE(c.topology.components[0].closed());
    EXPECT_EQ(c.topology.components[0].genus(), 0);
    EXPECT_TRUE(c.coherently_oriented());
    EXPECT_EQ(c.faces.degenerate_faces, 0u);
    EXPECT_EQ(c.faces.duplicate_faces, 0u);
    ASSERT_TRUE(c.self_intersecting_pairs.has_value());
    EXPECT_EQ(*c.self_intersecting_pairs, 0u);
    // The angle of a pole triangle at the pole, cos = ((1 + c) cos(2π/32) + 1 − c) / 2 with
    // c = cos(π/16), is an upper bound of the smallest angle (the narrow quads next to the
    // poles have smaller ones); no triangle is thinner than 10°.
    const double c16 = std::cos(M_PI / 16);
    const double pole = std::acos(((1 + c16) * std::cos(M_PI / 16) + 1 - c16) / 2) * 180 / M_PI;
    EXPECT_LE(c.faces.min_angle.min, pole + 1e-9);
    EXPECT_GE(c.faces.min_angle.min, 10.0);
    EXPECT_EQ(c.faces.min_angle.faces, c.topology.faces);
    EXPECT_EQ(c.faces.min_angle.below_10_degrees, 0u);
}

TEST(Check, TorusHasGenusOne) {
    const MeshCheck c = check(testing::torus());
    ASSERT_EQ(c.topology.components.size(), 1u);
    EXPECT_TRUE(c.topology.components[0].closed());
    EXPECT_EQ(c.topology.components[0].genus(), 1);
    EXPECT_EQ(c.topology.boundary_edges, 0u);
    EXPECT_TRUE(c.coherently_oriented());
    EXPECT_EQ(*c.self_intersecting_pairs, 0u);
}

TEST(Check, PatchHasOneBoundaryLoop) {
    const MeshCheck c = check(testing::square_patch(8));
    EXPECT_EQ(c.topology.boundary_edges, 32u);
    EXPECT_EQ(c.topology.boundary_loops, 1u);
    ASSERT_EQ(c.topology.components.size(), 1u);
    EXPECT_FALSE(c.topology.components[0].closed());
    EXPECT_EQ(c.topology.components[0].genus(), 0);
    EXPECT_NEAR(c.faces.min_angle.min, 45.0, 1e-9);
    EXPECT_NEAR(c.faces.min_angle.median, 45.0, 1e-9);
    EXPECT_EQ(*c.self_intersecting_pairs, 0u);
}

TEST(Check, TwoComponentsAreCountedSeparately) {
    TestMesh m = testing::uv_sphere();
    append(m, testing::shifted(testing::torus(), Vec3(5, 0, 0)));
    const MeshCheck c = check(m);
    ASSERT_EQ(c.topology.components.size(), 2u);
    EXPECT_EQ(c.topology.components[0].genus(), 0);
    EXPECT_EQ(c.topology.components[1].genus(), 1);
}

TEST(Check, LargestComponentIsTheOneWithMostTriangles) {
    TestMesh m = testing::shifted(testing::torus(), Vec3(5, 0, 0));
    const TestMesh sphere = testing::uv_sphere();
    ASSERT_LT(sphere.triangles.size(), m.triangles.size());
    append(m, sphere);
    const MeshCheck c = check(m);
    const ComponentTopology* largest = largest_component(c.topology);
    ASSERT_NE(largest, nullptr);
    EXPECT_EQ(largest->faces, testing::torus().triangles.size());
    EXPECT_EQ(largest->genus(), 1);
    EXPECT_EQ(largest_component(MeshStats{}), nullptr);
}

// Holes are boundary loops, not lost handles: a torus with two separate triangles removed is
// still of genus 1 (χ = −2, b = 2), which is how an open reconstruction is judged.
TEST(Check, TorusWithHolesKeepsGenusOne) {
    TestMesh m = testing::torus();
    const long middle = long(m.triangles.size() / 2);
    const Triangle first = m.triangles.front(), far = m.triangles[std::size_t(middle)];
    for (std::uint32_t v : first)
        ASSERT_EQ(std::count(far.begin(), far.end(), v), 0) << "the two holes must not touch";
    m.triangles.erase(m.triangles.begin() + middle);
    m.triangles.erase(m.triangles.begin());
    const MeshCheck c = check(m);
    EXPECT_EQ(c.topology.boundary_loops, 2u);
    ASSERT_EQ(c.topology.components.size(), 1u);
    EXPECT_FALSE(c.topology.components[0].closed());
    EXPECT_EQ(c.topology.components[0].euler(), -2);
    EXPECT_EQ(largest_component(c.topology)->genus(), 1);
}

// Two faces on one place cover each other: a pair, as CGAL reports one wound the other way.
TEST(Check, DuplicatedFaceIsFoundAndIsAnIntersectingPair) {
    TestMesh m = testing::square_patch(4);
    m.triangles.push_back(m.triangles[5]);
    const Triangle& f = m.triangles[9];
    m.triangles.push_back({f[0], f[2], f[1]}); // the other winding is a duplicate too
    const MeshCheck c = check(m);
    EXPECT_EQ(c.faces.duplicate_faces, 2u);
    EXPECT_EQ(c.faces.degenerate_faces, 0u);
    EXPECT_GT(c.topology.non_manifold_edges, 0u); // three triangles on its edges
    EXPECT_EQ(*c.self_intersecting_pairs, 2u);
}

TEST(Check, DuplicateThroughCoincidentVerticesIsFound) {
    TestMesh m = testing::square_patch(2);
    const Triangle f = m.triangles[0];
    const std::uint32_t a = add_vertex(m, m.positions[f[0]]), b = add_vertex(m, m.positions[f[1]]),
                        c = add_vertex(m, m.positions[f[2]]);
    m.triangles.push_back({a, b, c});
    const MeshCheck r = check(m);
    EXPECT_EQ(r.coincident_vertices, 3u);
    EXPECT_EQ(r.faces.duplicate_faces, 1u);
    EXPECT_EQ(*r.self_intersecting_pairs, 1u);
    EXPECT_EQ(r.topology.components.size(), 2u); // by index, the copy is a separate piece
}

TEST(Check, DegenerateFacesAreFound) {
    TestMesh m = testing::square_patch(2);
    const std::uint32_t v0 = m.triangles[0][0], v1 = m.triangles[0][1];
    m.triangles.push_back({v0, v0, v1}); // repeated index
    const std::uint32_t a = add_vertex(m, Vec3(3, 0, 0)), b = add_vertex(m, Vec3(4, 0, 0)),
                        c = add_vertex(m, Vec3(5, 0, 0));
    m.triangles.push_back({a, b, c}); // collinear
    const std::uint32_t d = add_vertex(m, Vec3(3, 3, 0)), e = add_vertex(m, Vec3(3, 3, 0)),
                        g = add_vertex(m, Vec3(4, 3, 0));
    m.triangles.push_back({d, e, g}); // two corners at one position
    const MeshCheck r = check(m);
    EXPECT_EQ(r.faces.degenerate_faces, 3u);
    EXPECT_EQ(r.faces.repeated_vertex_faces, 1u);
    EXPECT_EQ(r.faces.min_angle.faces, m.triangles.size() - 3);
    EXPECT_EQ(*r.self_intersecting_pairs, 0u);
}

TEST(Check, ThinButValidTriangleIsNotDegenerate) {
    EXPECT_FALSE(is_degenerate(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1e-6, 0)));
    EXPECT_TRUE(is_degenerate(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, 0)));
    EXPECT_TRUE(is_degenerate(Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3)));
}

TEST(Check, FlippedFaceBreaksCoherentOrientation) {
    TestMesh m = testing::square_patch(4);
    EXPECT_TRUE(check(m).coherently_oriented());
    std::swap(m.triangles[10][1], m.triangles[10][2]); // an interior triangle
    const MeshCheck c = check(m);
    EXPECT_FALSE(c.coherently_oriented());
    EXPECT_EQ(c.topology.inconsistently_oriented_edges, 3u);
    EXPECT_EQ(c.topology.boundary_edges, 16u);
}

// Two pieces touching at a vertex (as ball pivoting often leaves them): each is a disc of its own.
// Counted by vertex, the shared vertex went to one piece only and the loops through it were one,
// so the other piece came out closed with genus 1.
TEST(Check, PiecesSharingAVertexKeepTheirOwnTopology) {
    TestMesh m = testing::square_patch(2);
    TestMesh other = testing::shifted(testing::square_patch(2), Vec3(1, 1, 0));
    append(m, other);
    // Weld the second patch's corner at (1, 1) onto the first's.
    const auto corner = std::uint32_t(
        std::find(m.positions.begin(), m.positions.end(), Vec3(1, 1, 0)) - m.positions.begin());
    for (std::size_t t = testing::square_patch(2).triangles.size(); t < m.triangles.size(); ++t)
        for (std::uint32_t& v : m.triangles[t])
            if (m.positions[v] == Vec3(1, 1, 0)) v = corner;
    const MeshCheck c = check(m);
    EXPECT_EQ(c.topology.non_manifold_vertices, 1u);
    ASSERT_EQ(c.topology.components.size(), 2u);
    for (const ComponentTopology& piece : c.topology.components) {
        EXPECT_EQ(piece.vertices, 9u);
        EXPECT_EQ(piece.boundary_loops, 1u);
        EXPECT_EQ(piece.genus(), 0);
    }
    EXPECT_EQ(c.topology.boundary_loops, 2u);
}

// D-64's measure: a face wound against its corners' normals, as a fold lying flat would be.
TEST(Check, FacesAgainstVertexNormalsAreCounted) {
    TestMesh m = testing::square_patch(4);
    const std::vector<Vec3> up(m.positions.size(), Vec3(0, 0, 1));
    const std::vector<Vec3> down(m.positions.size(), Vec3(0, 0, -1));
    EXPECT_FALSE(check(m).faces_against_vertex_normals.has_value()); // no normals, no count
    const auto against = [&](const std::vector<Vec3>& normals) {
        const MeshCheck c =
            check_mesh({m.positions, m.triangles, &normals}, nullptr, nullptr, {}, {});
        return c.faces_against_vertex_normals.value();
    };
    const std::size_t facing_up = m.triangles.size() - against(up);
    EXPECT_TRUE(facing_up == 0 || facing_up == m.triangles.size()); // one winding throughout
    const std::vector<Vec3>& with = facing_up > 0 ? up : down;
    EXPECT_EQ(against(with), 0u);
    std::swap(m.triangles[10][1], m.triangles[10][2]); // an interior triangle turned over
    EXPECT_EQ(against(with), 1u);
    m.triangles.push_back({0, 0, 1}); // no area: degenerate, not against
    EXPECT_EQ(against(with), 1u);
    const std::vector<Vec3> too_few(m.positions.size() - 1, Vec3(0, 0, 1));
    EXPECT_THROW(check_mesh({m.positions, m.triangles, &too_few}, nullptr, nullptr, {}, {}),
                 InvalidInput);
}

TEST(Check, TwoCrossingTrianglesAreOnePair) {
    TestMesh m;
    m.positions = {Vec3(0, 0, 0),  Vec3(2, 0, 0), Vec3(1, 2, 0),
                   Vec3(1, 1, -1), Vec3(1, 1, 1), Vec3(1, 3, 0)};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    const MeshCheck c = check(m);
    ASSERT_TRUE(c.self_intersecting_pairs.has_value());
    EXPECT_EQ(*c.self_intersecting_pairs, 1u);
    ASSERT_EQ(c.first_intersecting_pairs.size(), 1u);
    EXPECT_EQ(c.first_intersecting_pairs[0], TrianglePair(0, 1));

    m.positions[3][0] = m.positions[4][0] = m.positions[5][0] = 3; // moved apart
    EXPECT_EQ(*check(m).self_intersecting_pairs, 0u);
}

TEST(Check, PiercingTriangleIsFoundInALargeMesh) {
    TestMesh m = testing::uv_sphere(40, 80);
    const std::uint32_t a = add_vertex(m, Vec3(0.2, 0.1, 0)), b = add_vertex(m, Vec3(2, 0.1, 0)),
                        c = add_vertex(m, Vec3(2, 0.1, 0.05));
    m.triangles.push_back({a, b, c});
    const std::vector<TrianglePair> pairs = self_intersecting_pairs(m.positions, m.triangles, {});
    ASSERT_FALSE(pairs.empty());
    for (const TrianglePair& p : pairs) EXPECT_EQ(p.second, m.triangles.size() - 1);
    // The same pairs whatever the thread count.
    EXPECT_EQ(self_intersecting_pairs(m.positions, m.triangles, {1, nullptr}), pairs);
}

// Two overlapping spheres with degenerate faces, their triangles shuffled so that each cell
// holds faces of many blocks of the grid's parallel loops: the grid files the same faces in the
// same order, and the search finds the same pairs, for 1, 2 and 8 threads.
TEST(Check, AnyThreadCountBuildsTheSameGridAndPairs) {
    TestMesh m = testing::uv_sphere(120, 240);
    append(m, testing::shifted(testing::uv_sphere(100, 200, 0.8), Vec3(0.9, 0.1, 0.05)));
    std::uint64_t state = 1; // a fixed shuffle (Knuth's MMIX generator)
    for (std::size_t i = m.triangles.size(); i > 1; --i) {
        state = state * 6364136223846793005u + 1442695040888963407u;
        std::swap(m.triangles[i - 1], m.triangles[(state >> 33) % i]);
    }
    const std::uint32_t a = add_vertex(m, Vec3(0, 0, 0)), b = add_vertex(m, Vec3(1, 1, 1)),
                        c = add_vertex(m, Vec3(2, 2, 2));
    m.triangles.insert(m.triangles.begin() + 1000, {a, b, c});  // collinear corners
    m.triangles.insert(m.triangles.begin() + 30000, {a, a, b}); // a repeated corner
    ASSERT_GT(m.triangles.size(), 80000u);
    const TriangleGeometry g(m.positions, m.triangles);
    const TriangleGrid one(g, {1, nullptr});
    const std::vector<TrianglePair> pairs = one.all_pairs(g, {1, nullptr});
    EXPECT_GT(pairs.size(), 100u);
    // A cell lists its faces in increasing order (the sort is by cell, then face).
    for (std::uint32_t f = 0; f < g.size(); f += 7) {
        const Vec3& corner = g.position(g.triangle(f)[0]);
        std::vector<std::uint32_t> in_cell;
        one.query({corner, corner}, in_cell);
        EXPECT_TRUE(std::adjacent_find(in_cell.begin(), in_cell.end(), std::greater_equal<>()) ==
                    in_cell.end());
        if (!g.degenerate(g.triangle(f))) {
            EXPECT_TRUE(std::binary_search(in_cell.begin(), in_cell.end(), f));
        }
    }
    for (int threads : {2, 8}) {
        const Execution exec{threads, nullptr};
        const TriangleGrid many(g, exec);
        EXPECT_EQ(many.cell_size(), one.cell_size());
        EXPECT_EQ(many.all_pairs(g, exec), pairs) << threads << " threads";
        for (std::uint32_t f = 0; f < g.size(); f += 7) {
            std::vector<std::uint32_t> filed_one, filed_many;
            one.query(g.box(g.triangle(f)), filed_one);
            many.query(g.box(g.triangle(f)), filed_many);
            ASSERT_EQ(filed_many, filed_one) << "near face " << f << ", " << threads << " threads";
        }
    }
    EXPECT_EQ(self_intersecting_pairs(m.positions, m.triangles, {8, nullptr}),
              self_intersecting_pairs(m.positions, m.triangles, {1, nullptr}));
}

TEST(Check, TrianglesOfThePairsAreThoseVcglibFinds) {
    // On this mesh vcglib's rule and the exact one find the same triangles (not pairs).
    const TestMesh m = testing::overlapping_spheres();
    std::vector<std::uint32_t> ours;
    for (const TrianglePair& p : self_intersecting_pairs(m.positions, m.triangles, {})) {
        ours.push_back(p.first);
        ours.push_back(p.second);
    }
    std::sort(ours.begin(), ours.end());
    ours.erase(std::unique(ours.begin(), ours.end()), ours.end());

    testing::VcgMesh v;
    vcg::tri::Allocator<testing::VcgMesh>::AddVertices(v, m.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i) v.vert[i].P() = m.positions[i];
    vcg::tri::Allocator<testing::VcgMesh>::AddFaces(v, m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) v.face[t].V(k) = &v.vert[m.triangles[t][k]];
    std::vector<std::uint32_t> theirs;
    for (testing::VcgFace* f : testing::self_intersecting_faces(v))
        theirs.push_back(std::uint32_t(vcg::tri::Index(v, f)));
    std::sort(theirs.begin(), theirs.end());
    EXPECT_GT(ours.size(), 40u);
    EXPECT_EQ(ours, theirs);
}

TEST(Check, TouchingThroughVertexCopiesIsNotAnIntersection) {
    // Two fans sharing one point through two vertex copies (as HRsR writes non-manifold points).
    TestMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0),    Vec3(0, 1, 0),
                   Vec3(0, 0, 0), Vec3(-1, 0, 0.5), Vec3(0, -1, 0.5)};
    m.triangles = {{0, 1, 2}, {3, 4, 5}};
    EXPECT_EQ(*check(m).self_intersecting_pairs, 0u);
}

TEST(Check, SelfIntersectionTestCanBeSkipped) {
    CheckOptions o;
    o.self_intersections = false;
    EXPECT_FALSE(check(testing::torus(), o).self_intersecting_pairs.has_value());
}

TEST(Check, DistanceToItselfIsZero) {
    const TestMesh m = testing::uv_sphere();
    CheckOptions o;
    o.distance.area_samples = 20000;
    const MeshView self{m.positions, m.triangles};
    const MeshCheck c = check_mesh(self, nullptr, &self, o, {});
    ASSERT_TRUE(c.reference.has_value());
    EXPECT_NEAR(c.reference->diagonal, std::sqrt(12.0), 1e-9);
    EXPECT_LT(c.reference->distance.chamfer(), 1e-12);
    EXPECT_LT(c.reference->distance.hausdorff(), 1e-12);
    EXPECT_EQ(c.reference->distance.a_to_b.area_samples, 20000u);
    EXPECT_EQ(c.reference->distance.a_to_b.vertices, m.positions.size());
}

TEST(Check, DistanceToAShiftedPatchIsTheShift) {
    const TestMesh m = testing::square_patch(8);
    const TestMesh r = testing::shifted(m, Vec3(0, 0, 0.01));
    SurfaceDistanceOptions o;
    o.area_samples = 5000;
    const SurfaceDistance d =
        surface_distance({m.positions, m.triangles}, {r.positions, r.triangles}, o, {});
    EXPECT_NEAR(d.chamfer(), 0.01, 1e-12);
    EXPECT_NEAR(d.hausdorff(), 0.01, 1e-12);
    EXPECT_NEAR(d.a_to_b.mean, 0.01, 1e-12);
    EXPECT_NEAR(d.b_to_a.max, 0.01, 1e-12);
}

TEST(Check, HausdorffToAShiftedSphereIsTheShift) {
    const TestMesh m = testing::uv_sphere(32, 64);
    const TestMesh r = testing::shifted(m, Vec3(0, 0, 0.05));
    SurfaceDistanceOptions o;
    o.area_samples = 20000;
    const SurfaceDistance d =
        surface_distance({m.positions, m.triangles}, {r.positions, r.triangles}, o, {});
    // The poles are vertices and lie exactly 0.05 from the other sphere's pole, the farthest.
    EXPECT_NEAR(d.hausdorff(), 0.05, 1e-3);
    // Mean of |z| · 0.05 over the sphere ≈ 0.025 (point-to-sphere distance ≈ shift · |cos θ|).
    EXPECT_NEAR(d.chamfer(), 0.025, 1e-3);
    // Deterministic for a seed.
    EXPECT_EQ(
        surface_distance({m.positions, m.triangles}, {r.positions, r.triangles}, o, {}).chamfer(),
        d.chamfer());
}

TEST(Check, VertexReferenceRatioCountsInputPointsOnVertices) {
    const TestMesh m = testing::square_patch(4); // 25 vertices, diagonal sqrt(2)
    PointSet input;
    input.positions = m.positions;
    input.positions[3] += Vec3(1e-8, 0, 0);         // within 1e-6 of the diagonal
    input.positions.push_back(Vec3(0.5, 0.5, 0.1)); // not a vertex
    input.positions.push_back(Vec3(0.1, 0.1, 0));   // on the surface but not a vertex
    const MeshCheck c = check_mesh({m.positions, m.triangles}, &input, nullptr, {}, {});
    ASSERT_TRUE(c.vertex_reference.has_value());
    EXPECT_EQ(c.vertex_reference->input_points, 27u);
    EXPECT_EQ(c.vertex_reference->present, 25u);
    EXPECT_NEAR(c.vertex_reference->ratio(), 25.0 / 27.0, 1e-12);
}

TEST(Check, UnreferencedVerticesDoNotCountForRv) {
    TestMesh m = testing::square_patch(1);
    add_vertex(m, Vec3(7, 7, 7));
    PointSet input;
    input.positions = m.positions;
    const MeshCheck c = check_mesh({m.positions, m.triangles}, &input, nullptr, {}, {});
    EXPECT_EQ(c.topology.unreferenced_vertices, 1u);
    EXPECT_EQ(c.vertex_reference->present, 4u);
}

TEST(Check, InvalidMeshesAreRejected) {
    TestMesh m = testing::square_patch(1);
    m.positions[0][1] = std::nan("");
    EXPECT_THROW(check(m), InvalidInput);
    TestMesh n = testing::square_patch(1);
    n.triangles.push_back({0, 1, 99});
    EXPECT_THROW(check(n), InvalidInput);
    const TestMesh empty;
    const TestMesh s = testing::square_patch(1);
    const MeshView no_triangles{empty.positions, empty.triangles};
    EXPECT_THROW(check_mesh({s.positions, s.triangles}, nullptr, &no_triangles, {}, {}),
                 InvalidInput);
}

} // namespace
} // namespace hrsr
