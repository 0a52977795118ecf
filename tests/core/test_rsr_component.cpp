#include "mesh/mesh_stats.h"
#include "preprocess/preprocess.h"
#include "rsr/reconstruct_component.h"
#include "rsr_invariants.h"
#include "samplers.h"

#include <gtest/gtest.h>

namespace hrsr {
namespace {

rsr::ComponentCloud as_component(const PreparedCloud& c) {
    return {c.positions, c.smoothed, c.normals};
}

MeshStats reconstruct(const PointSet& s, const RsrOptions& o, rsr::ComponentStats& stats,
                      testing::InvariantChecker* checker, std::size_t& vertices) {
    PreprocessReport report;
    const PreparedCloud c = preprocess(s, o.preprocess, {}, report);
    EXPECT_EQ(report.components_kept, 1u);
    const auto local = rsr::reconstruct_component(as_component(c), o, {}, stats, checker);
    std::vector<Triangle> triangles(local.begin(), local.end());
    vertices = c.size();
    return measure_mesh(c.size(), triangles);
}

TEST(RsrComponent, SphereIsAClosedGenusZeroManifold) {
    RsrOptions o;
    testing::InvariantChecker checker(50);
    rsr::ComponentStats stats;
    std::size_t n = 0;
    const MeshStats m = reconstruct(testing::sample_sphere(3000), o, stats, &checker, n);
    EXPECT_EQ(m.non_manifold_edges, 0u);
    EXPECT_EQ(m.inconsistently_oriented_edges, 0u);
    EXPECT_EQ(m.degenerate_faces, 0u);
    EXPECT_EQ(m.boundary_edges, 0u);
    ASSERT_EQ(m.components.size(), 1u);
    EXPECT_EQ(m.components[0].genus(), 0);
    EXPECT_EQ(m.vertices, n);
    EXPECT_EQ(checker.euler(), 2);
}

} // namespace
} // namespace hrsr
