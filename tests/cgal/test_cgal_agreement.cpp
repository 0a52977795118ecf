// The exact pair test (mesh/self_intersections.h) finds exactly CGAL's self-intersecting pairs:
// on folded fixtures, on reconstructions of the sample and, when present, of the shared scans.
#include "io/point_set_reader.h"
#include "mesh/self_intersections.h"
#include "mesh/triangle_intersection.h"
#include "reconstruction.h"

#include "cgal_self_intersections.h"
#include "fold_fixtures.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

namespace hrsr {
namespace {

using testing::TestMesh;

std::string shared(const std::string& relative) {
    const std::filesystem::path p = std::filesystem::path(HRSR_SHARED_DATA) / relative;
    return std::filesystem::exists(p) ? p.string() : std::string();
}

bool share_a_position(const TestMesh& m, const TrianglePair& p) {
    for (std::uint32_t u : m.triangles[p.first])
        for (std::uint32_t v : m.triangles[p.second])
            if (m.positions[u] == m.positions[v]) return true;
    return false;
}

// CGAL's pairs are ours by index; welded, ours lose exactly pairs that share a position (the
// two meet there through vertex copies). Returns the number of pairs CGAL found.
std::size_t expect_agreement(const TestMesh& m, const std::string& what) {
    const auto cgal = testing::cgal_self_intersections(m.positions, m.triangles);
    EXPECT_TRUE(cgal.has_value()) << what << ": CGAL's Surface_mesh refused a face";
    if (!cgal) return 0;
    EXPECT_EQ(cgal->degenerate, 0u) << what;
    const std::vector<TrianglePair> by_index =
        intersecting_pairs_by_index(m.positions, m.triangles, {});
    EXPECT_EQ(by_index, cgal->pairs) << what;
    const std::vector<TrianglePair> welded = self_intersecting_pairs(m.positions, m.triangles, {});
    EXPECT_TRUE(std::includes(by_index.begin(), by_index.end(), welded.begin(), welded.end()))
        << what;
    std::size_t through_copies = 0;
    for (const TrianglePair& p : by_index)
        if (!std::binary_search(welded.begin(), welded.end(), p)) {
            EXPECT_TRUE(share_a_position(m, p)) << what;
            ++through_copies;
        }
    ::testing::Test::RecordProperty(what + "_pairs", std::to_string(welded.size()));
    ::testing::Test::RecordProperty(what + "_cgal_pairs", std::to_string(cgal->pairs.size()));
    ::testing::Test::RecordProperty(what + "_through_copies", std::to_string(through_copies));
    return cgal->pairs.size();
}

// At the defaults, or with the fold repair off (`fold_repair_rounds` 0) to leave pairs to find.
TestMesh reconstruction(const std::string& file, Method method, bool repaired = true) {
    const PointSet input = io::read_point_set(file);
    ReconstructionOptions o;
    o.method = method;
    if (!repaired) o.rsr.fold_repair_rounds = 0;
    ReconstructionReport report;
    const Reconstruction r = reconstruct(input, o, {}, report);
    TestMesh m;
    for (std::uint32_t i : r.vertex_input_index) m.positions.push_back(input.positions[i]);
    m.triangles = r.triangles;
    return m;
}

// Random triangle pairs sharing 0, 1 or 2 corners, on a coarse lattice (touching, coplanar and
// collinear cases, corners at one position through distinct vertices) and in general position.
TEST(CgalAgreement, RandomTrianglePairs) {
    std::mt19937 random(7);
    std::size_t intersecting[3] = {0, 0, 0}, tested[3] = {0, 0, 0};
    for (int trial = 0; trial < 20000; ++trial) {
        std::uniform_int_distribution<int> cell(0, 2);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        TestMesh m;
        for (int k = 0; k < 6; ++k)
            m.positions.push_back(trial % 2 == 0 ? Vec3(cell(random), cell(random), cell(random))
                                                 : Vec3(unit(random), unit(random), unit(random)));
        const int shared = trial % 3;
        Triangle b{3, 4, 5};
        if (shared == 1) b[0] = 0;
        if (shared == 2) b = {1, 0, 5}; // the shared edge the other way round, as in a mesh
        std::rotate(b.begin(), b.begin() + trial % 3, b.end());
        m.triangles = {{0, 1, 2}, b};
        const auto cgal = testing::cgal_self_intersections(m.positions, m.triangles);
        ASSERT_TRUE(cgal.has_value());
        if (cgal->degenerate > 0) continue; // not tested by us either
        const auto corners = [&](const Triangle& t) {
            return Corners{m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]};
        };
        const bool ours = mesh_triangles_intersect(corners(m.triangles[0]), m.triangles[0],
                                                   corners(m.triangles[1]), m.triangles[1]);
        ASSERT_EQ(ours, !cgal->pairs.empty()) << "trial " << trial;
        ++tested[shared];
        intersecting[shared] += ours;
    }
    for (int shared = 0; shared < 3; ++shared) { // both outcomes occur
        EXPECT_GT(intersecting[shared], 0u) << shared;
        EXPECT_LT(intersecting[shared], tested[shared]) << shared;
    }
}

TEST(CgalAgreement, FoldedFixtures) {
    EXPECT_GT(expect_agreement(testing::pushed_vertex(), "pushed_vertex"), 0u);
    EXPECT_GT(expect_agreement(testing::crossing_sheets(), "crossing_sheets"), 0u);
    EXPECT_GT(expect_agreement(testing::boundary_fold(), "boundary_fold"), 0u);
    EXPECT_EQ(expect_agreement(testing::flat_fold_on_floats(), "flat_fold_on_floats"), 1u);
    EXPECT_EQ(expect_agreement(testing::touching_on_floats(), "touching_on_floats"), 1u);
}

TEST(CgalAgreement, OverlappingSpheresAndAPiercingTriangle) {
    EXPECT_GT(expect_agreement(testing::as_floats(testing::overlapping_spheres()), "spheres"), 40u);
}

TEST(CgalAgreement, SampleReconstructions) {
    for (Method method : {Method::Hrsr, Method::Rsr}) {
        const TestMesh m = reconstruction(HRSR_SAMPLE, method);
        const std::string name = method == Method::Hrsr ? "owl_hrsr" : "owl_rsr";
        expect_agreement(m, name);
        expect_agreement(testing::as_floats(m), name + "_floats");
    }
}

// Folds as reconstructions make them (the pair search skips the pairs around vertices whose fans
// it proves embedded, mesh/embedded_fans.h): every pair is found all the same.
TEST(CgalAgreement, UnrepairedReconstructions) {
    for (Method method : {Method::Hrsr, Method::Rsr}) {
        const std::string name = method == Method::Hrsr ? "hrsr" : "rsr";
        expect_agreement(testing::as_floats(reconstruction(HRSR_SAMPLE, method, false)),
                         "owl_unrepaired_" + name);
        const std::string feline = shared("topology/feline_genus2.ply");
        if (feline.empty()) continue;
        EXPECT_GT(expect_agreement(testing::as_floats(reconstruction(feline, method, false)),
                                   "feline_unrepaired_" + name),
                  100u);
    }
}

TEST(CgalAgreement, ScanReconstructions) {
    const std::string kitten = shared("topology/kitten_points_genus1_normals.ply");
    const std::string bunny = shared("scans/bunny_rangescans_merged_normals.ply");
    if (kitten.empty() || bunny.empty()) GTEST_SKIP() << "shared data not available";
    expect_agreement(testing::as_floats(reconstruction(kitten, Method::Rsr)), "kitten_rsr");
    expect_agreement(testing::as_floats(reconstruction(kitten, Method::Hrsr)), "kitten_hrsr");
    expect_agreement(testing::as_floats(reconstruction(bunny, Method::Hrsr)), "bunny_hrsr");
}

} // namespace
} // namespace hrsr
