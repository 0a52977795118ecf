#include "mesh/mesh_stats.h"
#include "mesh/split_mesh.h"

#include <vcg/complex/algorithms/clean.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <tuple>

namespace hrsr::reexpand {
namespace {

struct Fixture {
    std::vector<Vec3> positions;
    std::vector<Triangle> triangles;
};

Fixture octahedron() {
    return {
        {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}},
        {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}};
}

// Vertex 0 at the centre of six triangles (counter-clockwise seen from +z).
Fixture hexagon() {
    Fixture f;
    f.positions.emplace_back(0, 0, 0);
    for (int k = 0; k < 6; ++k)
        f.positions.emplace_back(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0);
    for (std::uint32_t k = 0; k < 6; ++k) f.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
    return f;
}

struct Counts {
    std::size_t v, e, f, loops;
    long euler;
};

Counts check(const SplitMesh& m) {
    const std::vector<Triangle> t = m.triangles();
    const MeshStats s = measure_mesh(m.vertex_count(), t);
    EXPECT_EQ(s.non_manifold_edges, 0u);
    EXPECT_EQ(s.non_manifold_vertices, 0u);
    EXPECT_EQ(s.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(s.degenerate_faces, 0u);
    EXPECT_TRUE(vcg::tri::Clean<SMesh>::IsFFAdjacencyConsistent(const_cast<SMesh&>(m.vcg_mesh())));
    return {s.vertices, s.edges, s.faces, s.boundary_loops, s.euler()};
}

// Every ordered pair (a, b) of c's neighbours, each on a fresh copy of the mesh.
void split_every_pair(const Fixture& fixture, std::uint32_t c) {
    const SplitMesh probe(fixture.positions, fixture.triangles, 64, 64);
    const Star star = probe.star(c);
    ASSERT_GE(star.neighbours.size(), 2u);
    for (std::uint32_t a : star.neighbours)
        for (std::uint32_t b : star.neighbours) {
            if (a == b) continue;
            SplitMesh m(fixture.positions, fixture.triangles, 64, 64);
            const Counts before = check(m);
            const std::uint32_t c2 = m.split(c, a, b, m.position(c) + Vec3(0.01, 0.02, 0.03));
            const Counts after = check(m);
            EXPECT_EQ(after.v, before.v + 1) << a << " " << b;
            EXPECT_EQ(after.e, before.e + 3) << a << " " << b;
            EXPECT_EQ(after.f, before.f + 2) << a << " " << b;
            EXPECT_EQ(after.euler, before.euler);
            EXPECT_EQ(after.loops, before.loops);
            // c' is adjacent to c, a and b; c keeps a and b.
            const Star s2 = m.star(c2), s1 = m.star(c);
            for (std::uint32_t x : {c, a, b})
                EXPECT_NE(std::find(s2.neighbours.begin(), s2.neighbours.end(), x),
                          s2.neighbours.end());
            for (std::uint32_t x : {c2, a, b})
                EXPECT_NE(std::find(s1.neighbours.begin(), s1.neighbours.end(), x),
                          s1.neighbours.end());
        }
}

TEST(SplitMesh, StarIsCounterClockwiseFromTheSmallestNeighbour) {
    const Fixture h = hexagon();
    const SplitMesh m(h.positions, h.triangles, 16, 16);
    const Star s = m.star(0);
    EXPECT_EQ(s.neighbours, (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6}));
    EXPECT_FALSE(s.boundary);
    // Rim vertex 1 at (1, 0): 2 lies at 120°, 0 at 180°, 6 at 240°; counter-clockwise from the
    // smallest id: 0, 6, 2, and the boundary gap is the wedge from 6 round to 2.
    const Star rim = m.star(1);
    EXPECT_TRUE(rim.boundary);
    EXPECT_EQ(rim.neighbours, (std::vector<std::uint32_t>{0, 6, 2}));
    EXPECT_EQ(rim.wedges[1], nullptr);
}

// A border vertex's star runs from the face after its gap, wherever the walk around it starts:
// the hexagon's centre with each of its six triangles taken out in turn.
TEST(SplitMesh, StarOfABorderVertexWhereverItsGapLies) {
    for (std::size_t gap = 0; gap < 6; ++gap) {
        Fixture h = hexagon();
        h.triangles.erase(h.triangles.begin() + std::ptrdiff_t(gap));
        const SplitMesh m(h.positions, h.triangles, 16, 16);
        const Star s = m.star(0);
        EXPECT_TRUE(s.boundary) << gap;
        EXPECT_EQ(s.neighbours, (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6})) << gap;
        for (std::size_t w = 0; w < 6; ++w)
            EXPECT_EQ(s.wedges[w] == nullptr, w == gap) << gap << " " << w;
    }
}

TEST(SplitMesh, InteriorSplitsPreserveEulerCharacteristic) {
    split_every_pair(octahedron(), 4);
}

TEST(SplitMesh, InteriorVertexOfADisc) {
    split_every_pair(hexagon(), 0);
}

TEST(SplitMesh, BoundaryVertexInEveryGapPosition) {
    Fixture h = hexagon();
    split_every_pair(h, 1);                     // rim vertex: valence 3, one gap
    h.triangles.erase(h.triangles.begin() + 2); // now the centre is a boundary vertex too
    split_every_pair(h, 0);
}

// D-34: a border split leaves out the new triangle next to the gap: (V, E, F) change by
// (+1, +2, +1), the border gains an edge, c' lies on it between c and the spoke next to the gap.
TEST(SplitMesh, BorderSplitPutsTheNewVertexOnTheBorder) {
    const Fixture h = hexagon();
    const SplitMesh probe(h.positions, h.triangles, 64, 64);
    const Star rim = probe.star(1); // 0, 6, 2 with the gap from 6 round to 2
    ASSERT_EQ(rim.wedges[1], nullptr);
    using B = SplitMesh::BorderSplit;
    // Out: the wedge before b (= 2) is the gap; In: the wedge after a (= 6) is.
    for (const auto& [a, b, omit, beside] :
         {std::tuple{6u, 2u, B::Out, 2u}, std::tuple{0u, 2u, B::Out, 2u},
          std::tuple{6u, 0u, B::In, 6u}, std::tuple{6u, 2u, B::In, 6u}}) {
        SplitMesh m(h.positions, h.triangles, 64, 64);
        const Counts before = check(m);
        const std::uint32_t c2 = m.split(1, m.star(1), a, b, Vec3(1.2, 0.1, 0), omit);
        const Counts after = check(m);
        EXPECT_EQ(after.v, before.v + 1);
        EXPECT_EQ(after.e, before.e + 2);
        EXPECT_EQ(after.f, before.f + 1);
        EXPECT_EQ(after.loops, before.loops);
        EXPECT_EQ(after.euler, before.euler);
        EXPECT_EQ(m.border_loop_edges(1, 16), 7u); // the hexagon's six rim edges and one more
        const Star s2 = m.star(c2), s1 = m.star(1);
        EXPECT_TRUE(s2.boundary);
        EXPECT_TRUE(s1.boundary);
        EXPECT_NE(std::find(s2.neighbours.begin(), s2.neighbours.end(), beside),
                  s2.neighbours.end());
    }
    // The triangle next to the gap must be the one left out.
    SplitMesh m(h.positions, h.triangles, 64, 64);
    EXPECT_THROW(m.split(1, m.star(1), 6, 0, Vec3(1.2, 0.1, 0), B::Out), std::logic_error);
}

TEST(SplitMesh, BorderLoopEdgesCountsUpToTheLimit) {
    Fixture h = hexagon();
    const SplitMesh disc(h.positions, h.triangles, 16, 16);
    EXPECT_EQ(disc.border_loop_edges(1, 6), 6u);
    EXPECT_EQ(disc.border_loop_edges(1, 5), 6u); // more than the limit: limit + 1
    h.triangles.erase(h.triangles.begin() + 2);  // the centre now has a gap too: the loop runs
    const SplitMesh notched(h.positions, h.triangles, 16, 16); // 1 2 3 0 4 5 6: seven edges
    EXPECT_EQ(notched.border_loop_edges(0, 10), 7u);
}

TEST(SplitMesh, CapacityIsNeverExceeded) {
    const Fixture o = octahedron();
    SplitMesh m(o.positions, o.triangles, 7, 10);
    m.split(4, 0, 1, Vec3(0, 0, 0.9));
    EXPECT_THROW(m.split(5, 0, 1, Vec3(0, 0, -0.9)), std::logic_error);
}

TEST(SplitMesh, FlipsKeepCountsAndRespectValence) {
    const Fixture h = hexagon();
    SplitMesh m(h.positions, h.triangles, 16, 16);
    // Spoke {0, 1} of the centre: 0 has valence 6, 1 is on the boundary: flippable.
    SFace* f = nullptr;
    int z = -1;
    for (const SFace& face : m.vcg_mesh().face)
        for (int k = 0; k < 3; ++k)
            if (m.vertex_of(&face, k) == 0 && m.vertex_of(&face, (k + 1) % 3) == 1) {
                f = const_cast<SFace*>(&face);
                z = k;
            }
    ASSERT_NE(f, nullptr);
    ASSERT_TRUE(m.can_flip(f, z));
    const Counts before = check(m);
    m.flip(f, z);
    const Counts after = check(m);
    EXPECT_EQ(after.e, before.e);
    EXPECT_EQ(after.f, before.f);
    // The octahedron's vertices have valence 4: after one flip two have 3, and their spokes
    // may not be flipped again.
    const Fixture o = octahedron();
    SplitMesh oct(o.positions, o.triangles, 16, 16);
    SFace* g = &const_cast<SMesh&>(oct.vcg_mesh()).face[0];
    ASSERT_TRUE(oct.can_flip(g, 0));
    oct.flip(g, 0);
    check(oct);
    std::size_t flippable_spokes_of_valence_three = 0;
    for (const SFace& face : oct.vcg_mesh().face)
        for (int k = 0; k < 3; ++k)
            if (oct.star(oct.vertex_of(&face, k)).neighbours.size() == 3 &&
                oct.can_flip(const_cast<SFace*>(&face), k))
                ++flippable_spokes_of_valence_three;
    EXPECT_EQ(flippable_spokes_of_valence_three, 0u);
}

// The face holding the directed edge u→w (its index z), or null.
SFace* face_with_edge(const SplitMesh& m, std::uint32_t u, std::uint32_t w, int& z) {
    for (const SFace& face : m.vcg_mesh().face)
        if (!face.IsD())
            for (int k = 0; k < 3; ++k)
                if (m.vertex_of(&face, k) == u && m.vertex_of(&face, (k + 1) % 3) == w) {
                    z = k;
                    return const_cast<SFace*>(&face);
                }
    return nullptr;
}

TEST(SplitMesh, GuardStopsAtAnotherTilesVertexBeforeAnyChange) {
    // D-43: the hexagon's centre and spokes 1-3 in tile 0, spokes 4-6 in tile 1; one slot for a
    // split (vertex 7, faces 6 and 7), owned by tile 0.
    const Fixture h = hexagon();
    SplitMesh m(h.positions, h.triangles, 8, 8);
    m.add_slots(1, 2);
    ASSERT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.face_count(), 6u);
    EXPECT_TRUE(m.isolated(7));
    m.set_owners({0, 0, 0, 0, 1, 1, 1, 0});
    const std::vector<Triangle> before = m.triangles();
    m.guard(true);
    SplitMesh::work_for(0);
    const Star star = m.star(0);
    EXPECT_THROW(m.claim(star), TileConflict);
    int z = -1;
    SFace* own = face_with_edge(m, 0, 2, z); // spoke {0, 2}: the quad 0, 1, 2, 3 is tile 0's
    ASSERT_NE(own, nullptr);
    EXPECT_TRUE(m.can_flip(own, z));
    SFace* shared = face_with_edge(m, 0, 4, z); // spoke {0, 4}: the quad holds 3, 4 and 5
    ASSERT_NE(shared, nullptr);
    EXPECT_THROW(m.can_flip(shared, z), TileConflict);
    EXPECT_THROW(m.flip(shared, z), TileConflict);
    EXPECT_THROW(m.remove_face(shared), TileConflict);
    EXPECT_THROW(m.split(0, star, 1, 4, Vec3(0.1, 0, 0), SplitMesh::BorderSplit::None, {7, {6, 7}}),
                 TileConflict);
    EXPECT_EQ(m.triangles(), before);
    EXPECT_TRUE(m.isolated(7));
    SplitMesh::work_for(1);
    EXPECT_NO_THROW(m.position(5));
    EXPECT_THROW(m.position(1), TileConflict);
    EXPECT_THROW(m.move(0, Vec3(0, 0, 0)), TileConflict);
    m.guard(false);
    // Unguarded, the same split goes into its slots.
    EXPECT_EQ(
        m.split(0, m.star(0), 1, 4, Vec3(0.1, 0, 0), SplitMesh::BorderSplit::None, {7, {6, 7}}),
        7u);
    const Counts after = check(m);
    EXPECT_EQ(after.v, 8u);
    EXPECT_EQ(after.f, 8u);
    EXPECT_EQ(m.face_count(), 8u);
    EXPECT_EQ(after.euler, 1);
}

// D-49: grouped by two tiles, a thread working for group 0 may touch tiles 0 and 1, not tile 2.
TEST(SplitMesh, GuardByGroupsOfTilesLetsAThreadWorkOnEveryTileOfItsGroup) {
    const Fixture h = hexagon();
    SplitMesh m(h.positions, h.triangles, 8, 8);
    m.add_slots(1, 2);
    m.set_owners({0, 0, 0, 1, 1, 2, 2, 0}); // spokes 5 and 6 in tile 2, the others in 0 and 1
    const std::vector<Triangle> before = m.triangles();
    m.group_tiles(1);
    m.guard(true);
    SplitMesh::work_for(0);
    EXPECT_NO_THROW(m.position(3));
    EXPECT_THROW(m.position(5), TileConflict);
    try { // the conflict names the tile reached, not its group
        m.position(6);
        ADD_FAILURE() << "vertex 6 is tile 2's";
    } catch (const TileConflict& conflict) {
        EXPECT_EQ(conflict.tile, 2u);
    }
    const Star star = m.star(0);
    EXPECT_THROW(m.claim(star), TileConflict);
    EXPECT_THROW(m.split(0, star, 1, 4, Vec3(0.1, 0, 0), SplitMesh::BorderSplit::None, {7, {6, 7}}),
                 TileConflict);
    EXPECT_EQ(m.triangles(), before);
    SplitMesh::work_for(1); // group 1: tiles 2 and 3
    EXPECT_NO_THROW(m.position(6));
    EXPECT_THROW(m.position(4), TileConflict);
    m.guard(false);
    m.group_tiles(0);
    m.guard(true);
    SplitMesh::work_for(0);
    EXPECT_THROW(m.position(3), TileConflict); // by tiles again
    m.guard(false);
}

// A torus of rows × columns quads, two triangles each.
Fixture torus_grid(std::uint32_t rows, std::uint32_t columns) {
    Fixture f;
    for (std::uint32_t i = 0; i < rows; ++i)
        for (std::uint32_t j = 0; j < columns; ++j) {
            const double u = 2 * M_PI * i / rows, v = 2 * M_PI * j / columns;
            f.positions.emplace_back((2 + std::cos(v)) * std::cos(u),
                                     (2 + std::cos(v)) * std::sin(u), std::sin(v));
        }
    const auto at = [&](std::uint32_t i, std::uint32_t j) {
        return (i % rows) * columns + j % columns;
    };
    for (std::uint32_t i = 0; i < rows; ++i)
        for (std::uint32_t j = 0; j < columns; ++j) {
            f.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            f.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return f;
}

// The links are built by blocks of faces in parallel: the same stars for one and two threads,
// and a face repeated far from the first block is refused on any thread.
TEST(SplitMesh, BuiltOnSeveralThreadsTheSameAsOnOne) {
    Fixture t = torus_grid(300, 200); // 120,000 faces: several blocks
    const std::size_t n = t.positions.size();
    SplitMesh one(t.positions, t.triangles, n, t.triangles.size(), Execution{1});
    SplitMesh two(t.positions, t.triangles, n, t.triangles.size(), Execution{2});
    const Counts c = check(two);
    EXPECT_EQ(c.euler, 0);
    EXPECT_EQ(c.loops, 0u);
    for (std::uint32_t v = 0; v < n; ++v) {
        const Star a = one.star(v), b = two.star(v);
        ASSERT_EQ(a.neighbours, b.neighbours) << v;
        ASSERT_EQ(a.wedges.size(), b.wedges.size());
        for (std::size_t k = 0; k < a.wedges.size(); ++k) // the same face slot each
            ASSERT_EQ(a.wedges[k] - &one.vcg_mesh().face[0], b.wedges[k] - &two.vcg_mesh().face[0]);
    }
    t.triangles.push_back(t.triangles[100000]);
    EXPECT_THROW(SplitMesh(t.positions, t.triangles, n, t.triangles.size(), Execution{2}),
                 std::logic_error);
}

TEST(SplitMesh, SplitsInGuardedTilesCountTheirFacesWhenTheGuardEnds) {
    const Fixture h = hexagon();
    SplitMesh m(h.positions, h.triangles, 8, 8);
    m.add_slots(1, 2);
    m.set_owners(std::vector<std::uint32_t>(8, 3));
    m.guard(true);
    SplitMesh::work_for(3);
    m.split(0, m.star(0), 2, 5, Vec3(0.1, 0.1, 0), SplitMesh::BorderSplit::None, {7, {6, 7}});
    m.guard(false);
    EXPECT_EQ(m.face_count(), 8u);
    EXPECT_EQ(check(m).f, 8u);
}

TEST(SplitMesh, RemovingAFaceOpensTheBoundary) {
    const Fixture o = octahedron();
    SplitMesh m(o.positions, o.triangles, 16, 16);
    m.remove_face(&const_cast<SMesh&>(m.vcg_mesh()).face[0]);
    const Counts c = check(m);
    EXPECT_EQ(c.f, 7u);
    EXPECT_EQ(c.loops, 1u);
    for (std::uint32_t v = 0; v < 6; ++v) EXPECT_FALSE(m.isolated(v));
    EXPECT_TRUE(m.star(0).boundary);
}

} // namespace
} // namespace hrsr::reexpand
