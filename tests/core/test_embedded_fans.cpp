// The vertices whose faces provably meet only where they join (embedded_fans.h), and the pair
// search that skips such faces' pairs.
#include "mesh/embedded_fans.h"
#include "mesh/triangle_grid.h"
#include "mesh/triangle_intersection.h"

#include "fold_fixtures.h"
#include "mesh_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace hrsr {
namespace {

using testing::TestMesh;

std::vector<std::uint8_t> fans_of(const TestMesh& m, int threads = 1) {
    const TriangleGeometry g(m.positions, m.triangles);
    return embedded_fans(g, {threads, nullptr});
}

std::size_t count(const std::vector<std::uint8_t>& flags) {
    std::size_t n = 0;
    for (std::uint8_t f : flags) n += f;
    return n;
}

// No two faces around a flagged vertex intersect (the claim the search relies on), checked by
// the exact pair test; and the search finds the same pairs with and without the flags.
void expect_sound(const TestMesh& m, const std::string& what) {
    const TriangleGeometry g(m.positions, m.triangles);
    const std::vector<std::uint8_t> embedded = embedded_fans(g, {1, nullptr});
    std::vector<std::vector<std::uint32_t>> faces_at(m.positions.size());
    for (std::uint32_t f = 0; f < m.triangles.size(); ++f)
        for (std::uint32_t v : m.triangles[f]) faces_at[v].push_back(f);
    for (std::uint32_t v = 0; v < embedded.size(); ++v) {
        if (!embedded[v]) continue;
        for (std::size_t i = 0; i < faces_at[v].size(); ++i)
            for (std::size_t j = i + 1; j < faces_at[v].size(); ++j)
                ASSERT_FALSE(g.intersect(g.triangle(faces_at[v][i]), g.triangle(faces_at[v][j])))
                    << what << ": faces " << faces_at[v][i] << ", " << faces_at[v][j]
                    << " at embedded vertex " << v;
    }
    const TriangleGrid grid(g, {1, nullptr});
    EXPECT_EQ(grid.all_pairs(g, embedded, {1, nullptr}), grid.all_pairs(g, {}, {1, nullptr}))
        << what;
}

/// A vertex at the origin whose `m` neighbours lie on a circle at angles `turns` · 2π i / m,
/// joined in that order into a closed fan of flat faces: it winds around the vertex `turns`
/// times.
TestMesh winding_fan(int m, int turns) {
    TestMesh fan;
    fan.positions.emplace_back(0, 0, 0);
    for (int i = 0; i < m; ++i) {
        const double a = 2 * M_PI * turns * i / m;
        fan.positions.emplace_back(std::cos(a), std::sin(a), 0);
    }
    for (int i = 0; i < m; ++i)
        fan.triangles.push_back({0, std::uint32_t(1 + i), std::uint32_t(1 + (i + 1) % m)});
    return fan;
}

/// `m` turned about the axis (1, 2, 3) by 0.7 radians: no coordinate or height is exactly 0.
TestMesh turned(TestMesh m) {
    const Vec3 axis = Vec3(1, 2, 3) / std::sqrt(14.0);
    const double c = std::cos(0.7), s = std::sin(0.7);
    for (Vec3& p : m.positions) // Rodrigues' formula
        p = p * c + (axis ^ p) * s + axis * (axis.dot(p) * (1 - c));
    return m;
}

TEST(EmbeddedFans, EveryVertexOfClosedSmoothSurfacesQualifies) {
    // Vertices facing every way: the projection axis and both turning senses are used.
    const TestMesh sphere = testing::uv_sphere(16, 16);
    EXPECT_EQ(count(fans_of(sphere)), sphere.positions.size());
    const TestMesh torus = testing::torus();
    EXPECT_EQ(count(fans_of(torus)), torus.positions.size());
    expect_sound(sphere, "sphere");
    expect_sound(torus, "torus");
}

TEST(EmbeddedFans, BorderVerticesDoNotQualifyInnerOnesDo) {
    // On a grid in the plane z = 0: neighbours at the vertex's own height on the ray's line
    // decide the half-open count.
    const int n = 6;
    const TestMesh patch = testing::square_patch(n);
    const std::vector<std::uint8_t> embedded = fans_of(patch);
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x) {
            const bool border = x == 0 || y == 0 || x == n || y == n;
            EXPECT_EQ(embedded[std::size_t(y * (n + 1) + x)], border ? 0 : 1) << x << ", " << y;
        }
    expect_sound(patch, "patch");
}

TEST(EmbeddedFans, AFanWindingTwiceDoesNotQualify) {
    const TestMesh once = winding_fan(7, 1), twice = winding_fan(7, 2);
    EXPECT_EQ(fans_of(once)[0], 1);
    EXPECT_EQ(fans_of(twice)[0], 0);
    // Seen along its normal rather than an axis.
    EXPECT_EQ(fans_of(turned(once))[0], 1);
    EXPECT_EQ(fans_of(turned(twice))[0], 0);
    expect_sound(turned(twice), "twice, turned");
    // Its faces do overlap: the search, told nothing, finds them.
    const TriangleGeometry g(twice.positions, twice.triangles);
    EXPECT_FALSE(TriangleGrid(g, {1, nullptr}).all_pairs(g, {}, {1, nullptr}).empty());
    expect_sound(twice, "twice");
}

TEST(EmbeddedFans, ASteepFanQualifiesSeenAlongItsNormal) {
    // Eight neighbours around the normal (1, 1, 1), alternately 1.5 above and below its plane:
    // faces 56° steep, folded over seen along any coordinate axis, but a star seen along the
    // normal.
    const Vec3 n = Vec3(1, 1, 1) / std::sqrt(3.0), u = Vec3(1, -1, 0) / std::sqrt(2.0), w = n ^ u;
    TestMesh fan;
    fan.positions.emplace_back(0, 0, 0);
    for (int i = 0; i < 8; ++i) {
        const double a = 2 * M_PI * (i + 0.3) / 8; // no neighbour on the ray's line
        fan.positions.push_back(u * std::cos(a) + w * std::sin(a) + n * (i % 2 ? 1.5 : -1.5));
    }
    for (std::uint32_t i = 0; i < 8; ++i) fan.triangles.push_back({0, 1 + i, 1 + (i + 1) % 8});
    EXPECT_EQ(fans_of(fan)[0], 1);
    expect_sound(fan, "steep fan");
}

TEST(EmbeddedFans, ProductsThatUnderflowDecideNoTurn) {
    // Found by a review: in the plane z = 0, a vertex with two tiny neighbours whose sector
    // turns clockwise (by about 5e-5 of the smallest subnormal) among four huge ones turning
    // counter-clockwise. The products of the tiny differences underflow; multiplied by the
    // fan's huge normal, their error once passed for a counter-clockwise turn, the fan was
    // flagged and three overlapping pairs were missed.
    TestMesh fan;
    fan.positions = {Vec3(-0x1.030f9bc3e7a08p-527, -0x1.6deb840d53a59p-528, 0),
                     Vec3(0x1.b35ea43c185f8p-527, 0x1.00249003c916ap-526, 0),
                     Vec3(0x1.98911cf0643c2p-511, 0x1.990c290a3df95p-511, 0)};
    for (const double degrees : {10.0, 100.0, 190.0, 280.0}) {
        const double a = degrees * M_PI / 180;
        fan.positions.push_back(Vec3(std::cos(a), std::sin(a), 0) * std::ldexp(1.0, 110));
    }
    const std::uint32_t ring[] = {3, 1, 2, 4, 5, 6};
    for (std::uint32_t k = 0; k < 6; ++k) fan.triangles.push_back({0, ring[k], ring[(k + 1) % 6]});
    EXPECT_EQ(fans_of(fan)[0], 0);
    const TriangleGeometry g(fan.positions, fan.triangles);
    EXPECT_EQ(TriangleGrid(g, {1, nullptr}).all_pairs(g, {1, nullptr}).size(), 3u);
    expect_sound(fan, "underflow");
}

TEST(EmbeddedFans, PinchedDegenerateAndFoldedFansDoNotQualify) {
    // Two cones sharing their apex: two fans at one vertex.
    TestMesh cones = winding_fan(6, 1);
    for (Vec3& p : cones.positions) p[2] = p == Vec3(0, 0, 0) ? 0.0 : 1.0;
    const auto offset = std::uint32_t(cones.positions.size());
    for (int i = 1; i <= 6; ++i) {
        Vec3 p = cones.positions[std::size_t(i)];
        p[2] = -1;
        cones.positions.push_back(p);
    }
    for (std::uint32_t i = 0; i < 6; ++i)
        cones.triangles.push_back({0, offset + (i + 1) % 6, offset + i});
    EXPECT_EQ(fans_of(cones)[0], 0);
    expect_sound(cones, "cones");

    // A face whose corners lie on one line.
    TestMesh degenerate = winding_fan(6, 1);
    degenerate.positions[1] = degenerate.positions[2] * 0.5;
    EXPECT_EQ(fans_of(degenerate)[0], 0);
    expect_sound(degenerate, "degenerate");

    // The fold fixtures: whatever qualifies is sound, and the pushed vertex does not qualify.
    const TestMesh pushed = testing::pushed_vertex();
    EXPECT_LT(count(fans_of(pushed)), pushed.positions.size());
    expect_sound(pushed, "pushed vertex");
    expect_sound(testing::crossing_sheets(), "crossing sheets");
    expect_sound(testing::boundary_fold(), "boundary fold");
    expect_sound(testing::fin_through_a_copy(), "fin");
    expect_sound(testing::overlapping_spheres(), "overlapping spheres");
    expect_sound(testing::flat_fold_on_floats(), "flat fold");
    expect_sound(testing::touching_on_floats(), "touching");
}

TEST(EmbeddedFans, RandomlyCrumpledSurfacesAreSoundForAnyThreadCount) {
    std::uint64_t state = 7; // Knuth's MMIX generator
    const auto uniform = [&] {
        state = state * 6364136223846793005u + 1442695040888963407u;
        return double(state >> 11) / double(1ull << 53) - 0.5;
    };
    for (const double amplitude : {0.01, 0.05, 0.2}) {
        TestMesh m = testing::torus(40, 20);
        for (Vec3& p : m.positions) p += Vec3(uniform(), uniform(), uniform()) * amplitude;
        const std::vector<std::uint8_t> one = fans_of(m, 1);
        EXPECT_GT(count(one), 0u);
        EXPECT_EQ(fans_of(m, 8), one);
        expect_sound(m, "torus crumpled by " + std::to_string(amplitude));
        // On a grid of float coordinates: exact ties everywhere.
        for (Vec3& p : m.positions)
            for (int k = 0; k < 3; ++k) p[k] = std::round(p[k] * 16) / 16;
        expect_sound(m, "the same on a grid, " + std::to_string(amplitude));
    }
}

} // namespace
} // namespace hrsr
