// D-34: notches of HRsR's border (a border vertex whose faces leave less than 90° open) get an
// ear; wider gaps and small loops (holes in the data) are left as they are.
#include "hrsr/border_notches.h"
#include "mesh/mesh_stats.h"
#include "options.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

namespace hrsr {
namespace {

struct Fan {
    std::vector<Vec3> positions;
    std::vector<Triangle> triangles;
    IndexVector<VertexIndex, PointIndex> vertex_point;
};

// Vertex 0 at the origin, its border neighbours 1 and 2 at 90° ∓ gap/2 on the unit circle, and
// `rim` more vertices round the far side: faces (0, r_k, r_k+1) counter-clockwise from 2 to 1 the
// long way. The border loop has rim + 3 vertices and the gap at 0 is `gap_degrees`.
Fan notch(double gap_degrees, std::uint32_t rim) {
    Fan f;
    f.positions.emplace_back(0, 0, 0);
    const double first = M_PI / 2 + gap_degrees * M_PI / 360; // vertex 1, then round to vertex 2
    const double sweep = 2 * M_PI - gap_degrees * M_PI / 180;
    std::vector<std::uint32_t> ring;
    for (std::uint32_t k = 0; k <= rim + 1; ++k) {
        const double a = first + sweep * double(k) / double(rim + 1);
        f.positions.emplace_back(std::cos(a), std::sin(a), 0);
        ring.push_back(std::uint32_t(f.positions.size() - 1));
    }
    std::swap(f.positions[2], f.positions[ring.back()]); // vertex 2: the far end of the sweep
    std::swap(ring[1], ring.back());
    for (std::size_t k = 0; k + 1 < ring.size(); ++k)
        f.triangles.push_back({0, ring[k], ring[k + 1]});
    for (std::uint32_t v = 0; v < f.positions.size(); ++v) f.vertex_point.push_back(PointIndex(v));
    return f;
}

MeshStats stats(const Fan& f) {
    return measure_mesh(f.positions.size(), f.triangles);
}

// The directed edges no triangle runs the other way.
std::vector<BorderEdge> border_of(const std::vector<Triangle>& triangles) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
    for (const Triangle& t : triangles)
        for (std::size_t k = 0; k < 3; ++k) directed.insert({t[k], t[(k + 1) % 3]});
    std::vector<BorderEdge> border;
    for (const auto& [a, b] : directed)
        if (!directed.count({b, a})) border.push_back({a, b});
    return border;
}

std::size_t close(Fan& f) {
    return close_border_notches(f.triangles, border_of(f.triangles), f.positions, f.vertex_point,
                                constants::kBorderNotchDegrees * M_PI / 180.0);
}

TEST(BorderNotches, ANotchGetsAnEarAndItsVertexTurnsInterior) {
    Fan f = notch(60, 10);
    const MeshStats before = stats(f);
    ASSERT_EQ(before.boundary_loops, 1u);
    ASSERT_EQ(before.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(close(f), 1u);
    const MeshStats after = stats(f);
    EXPECT_EQ(after.faces, before.faces + 1);
    EXPECT_EQ(after.boundary_loops, 1u);
    EXPECT_EQ(after.boundary_edges, before.boundary_edges - 1);
    EXPECT_EQ(after.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(after.non_manifold_edges, 0u);
    EXPECT_EQ(after.non_manifold_vertices, 0u);
    EXPECT_EQ(f.triangles.back(), (Triangle{0, 2, 1})); // over the gap, facing as the fan
}

TEST(BorderNotches, AWideGapStaysOpen) {
    Fan f = notch(100, 10);
    EXPECT_EQ(close(f), 0u);
}

// A loop of at most kMinNotchedLoop vertices may be a hole in the data: no ear shrinks it.
TEST(BorderNotches, ASmallLoopStaysOpen) {
    Fan f = notch(60, constants::kMinNotchedLoop - 3); // kMinNotchedLoop vertices round
    EXPECT_EQ(close(f), 0u);
    Fan g = notch(60, constants::kMinNotchedLoop - 2);
    EXPECT_EQ(close(g), 1u);
}

} // namespace
} // namespace hrsr
