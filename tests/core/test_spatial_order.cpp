// D-40: the cloud in Morton order inside reconstruct(), the result in input indices.
#include "input_order.h"
#include "reconstruction.h"
#include "samplers.h"
#include "spatial_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <set>

namespace hrsr {
namespace {

TEST(SpatialOrder, CornersOfACubeComeInZOrder) {
    // The eight corners given in reverse Z order: x is the lowest bit, then y, then z.
    std::vector<Vec3> corners;
    for (int k = 7; k >= 0; --k) corners.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    const SpatialOrder order = spatial_order(corners, Execution{});
    EXPECT_EQ(order.input_index, (std::vector<std::uint32_t>{7, 6, 5, 4, 3, 2, 1, 0}));
}

TEST(SpatialOrder, DuplicatesKeepInputOrderAndNonFinitePointsComeLast) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<Vec3> points{{1, 1, 1}, {nan, 0, 0},
                                   {0, 0, 0}, {1, 1, 1},
                                   {0, 0, 0}, {0, std::numeric_limits<double>::infinity(), 0}};
    const SpatialOrder order = spatial_order(points, Execution{});
    EXPECT_EQ(order.input_index, (std::vector<std::uint32_t>{2, 4, 0, 3, 1, 5}));
}

// The mean distance between consecutive points of `order` (those of the first `count` points).
double mean_step(const PointSet& s, const std::vector<std::uint32_t>& order, std::size_t count) {
    double sum = 0;
    std::size_t steps = 0, previous = order.size();
    for (std::size_t i = 0; i < order.size(); ++i) {
        if (order[i] >= count) continue;
        if (previous < order.size()) {
            sum += (s.positions[order[i]] - s.positions[order[previous]]).Norm();
            ++steps;
        }
        previous = i;
    }
    return sum / double(steps);
}

TEST(SpatialOrder, NeighboursInTheOrderAreNearInSpace) {
    // Sphere samples come in random order: consecutive points are a radius apart on average.
    const PointSet s = testing::sample_sphere(20000);
    std::vector<std::uint32_t> input(s.size());
    std::iota(input.begin(), input.end(), 0u);
    const SpatialOrder order = spatial_order(s.positions, Execution{});
    std::vector<std::uint32_t> sorted = order.input_index;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, input); // a permutation
    const double spacing = std::sqrt(4 * M_PI / double(s.size()));
    EXPECT_GT(mean_step(s, input, s.size()), 50 * spacing);
    EXPECT_LT(mean_step(s, order.input_index, s.size()), 4 * spacing);
}

// The radix sort counts and scatters by blocks of points in parallel: the order is the same for
// any thread count (here over 12 blocks, with exact duplicates spread across them).
TEST(SpatialOrder, SameOrderForAnyThreadCount) {
    PointSet s = testing::sample_sphere(180000);
    for (std::size_t i = 0; i < 20000; ++i) s.positions.push_back(s.positions[i * 7]);
    const SpatialOrder one = spatial_order(s.positions, Execution{1});
    std::vector<std::uint32_t> sorted = one.input_index;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::uint32_t> input(s.size());
    std::iota(input.begin(), input.end(), 0u);
    ASSERT_EQ(sorted, input); // a permutation
    for (int threads : {2, 8})
        EXPECT_EQ(spatial_order(s.positions, Execution{threads}).input_index, one.input_index)
            << threads << " threads";
}

// A far outlier is clamped into the outermost cells instead of stretching the grid (a cell would
// be a quarter of the sphere): the sphere's points stay in spatial order.
TEST(SpatialOrder, AFarOutlierDoesNotCoarsenTheCells) {
    PointSet s = testing::sample_sphere(20000);
    s.positions.emplace_back(1e6, -1e6, 1e6);
    const SpatialOrder order = spatial_order(s.positions, Execution{});
    EXPECT_LT(mean_step(s, order.input_index, 20000), 4 * std::sqrt(4 * M_PI / 20000.0));
}

// Distinct points in one cell (a near-duplicate pair) come in the order of their coordinates,
// whatever their order in the input.
TEST(SpatialOrder, PointsInOneCellFollowTheirCoordinates) {
    const Vec3 a(0.5, 0.5, 0.5), b(0.5 + 1e-12, 0.5, 0.5);
    const std::vector<Vec3> ab{{0, 0, 0}, a, b, {1, 1, 1}}, ba{{0, 0, 0}, b, a, {1, 1, 1}};
    EXPECT_EQ(spatial_order(ab, Execution{}).input_index, (std::vector<std::uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(spatial_order(ba, Execution{}).input_index, (std::vector<std::uint32_t>{0, 2, 1, 3}));
}

TEST(SpatialOrder, ReorderedCloudKeepsPointsWithTheirNormals) {
    PointSet s = testing::sample_sphere(100);
    const SpatialOrder order = spatial_order(s.positions, Execution{});
    const PointSet r = reordered(s, order);
    ASSERT_EQ(r.size(), s.size());
    for (std::size_t i = 0; i < r.size(); ++i) {
        EXPECT_EQ(r.positions[i], s.positions[order.input_index[i]]);
        EXPECT_EQ(r.normals[i], s.normals[order.input_index[i]]);
    }
    s.normals.pop_back(); // a file that lies: sanitising must see the same mismatch
    EXPECT_EQ(reordered(s, order).normals.size(), s.size() - 1);
}

// The triangles as input-point triples, each from its smallest corner (winding kept).
std::set<std::array<std::uint32_t, 3>> triangles_over_points(const Reconstruction& m,
                                                             const std::vector<std::uint32_t>& to) {
    std::set<std::array<std::uint32_t, 3>> out;
    for (const Triangle& t : m.triangles) {
        std::array<std::uint32_t, 3> p{to[m.vertex_input_index[t[0]]],
                                       to[m.vertex_input_index[t[1]]],
                                       to[m.vertex_input_index[t[2]]]};
        std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
        out.insert(p);
    }
    return out;
}

// Vertices in input order: each point's first vertex by input index, then the copies (§5.8).
bool in_input_order(const std::vector<std::uint32_t>& vertex_input_index) {
    std::set<std::uint32_t> seen;
    std::size_t firsts = 0;
    while (firsts < vertex_input_index.size() && seen.insert(vertex_input_index[firsts]).second)
        ++firsts;
    const auto copies = vertex_input_index.begin() + std::ptrdiff_t(firsts);
    return std::is_sorted(vertex_input_index.begin(), copies) &&
           std::is_sorted(copies, vertex_input_index.end()) &&
           std::all_of(copies, vertex_input_index.end(),
                       [&](std::uint32_t i) { return seen.count(i) == 1; });
}

// The mesh handed back in input numbers: each point's first vertex by input index, then the
// copies of non-manifold points by input index (each point's in vertex order), the triangles over
// the new numbers; the same for any thread count. Checked against sorting every vertex by
// (copy, input index), on 200,000 vertices over a shuffled order with 3,000 copies.
TEST(SpatialOrder, VerticesComeBackNumberedInInputOrder) {
    const std::uint32_t points = 250000;
    SpatialOrder order;
    order.input_index.resize(points);
    std::iota(order.input_index.begin(), order.input_index.end(), 0U);
    std::mt19937 rng(11);
    std::shuffle(order.input_index.begin(), order.input_index.end(), rng);
    Reconstruction spatial;
    for (std::uint32_t p = 0; p < points; p += 5)
        for (int k = 0; k < 4; ++k) spatial.vertex_input_index.push_back(p + std::uint32_t(k));
    std::uniform_int_distribution<std::uint32_t> any_vertex(
        0, std::uint32_t(spatial.vertex_input_index.size() - 1));
    for (int c = 0; c < 3000; ++c) // copies: another vertex of a point that has one
        spatial.vertex_input_index.push_back(spatial.vertex_input_index[any_vertex(rng)]);
    const std::size_t n = spatial.vertex_input_index.size();
    for (std::uint32_t v = 0; v < n; ++v) spatial.vertex_normals.emplace_back(v, 0, 1);
    std::uniform_int_distribution<std::uint32_t> any(0, std::uint32_t(n - 1));
    for (int t = 0; t < 100000; ++t) spatial.triangles.push_back({any(rng), any(rng), any(rng)});

    // The expected numbering: a stable sort of (is a copy, input index).
    std::vector<std::pair<bool, std::uint32_t>> key(n);
    std::vector<std::uint8_t> seen(points, 0);
    for (std::uint32_t v = 0; v < n; ++v) {
        const std::uint32_t i = order.input_index[spatial.vertex_input_index[v]];
        key[v] = {seen[i] != 0, i};
        seen[i] = 1;
    }
    std::vector<std::uint32_t> by_key(n);
    std::iota(by_key.begin(), by_key.end(), 0U);
    std::stable_sort(by_key.begin(), by_key.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    std::vector<std::uint32_t> new_index(n);
    for (std::uint32_t k = 0; k < n; ++k) new_index[by_key[k]] = k;

    for (int threads : {1, 2, 8}) {
        Reconstruction mesh = spatial;
        ReconstructionReport report;
        restore_input_order(order, mesh, report, {threads, nullptr});
        ASSERT_EQ(mesh.vertex_input_index.size(), n);
        for (std::uint32_t v = 0; v < n; ++v) {
            ASSERT_EQ(mesh.vertex_input_index[new_index[v]], key[v].second) << v;
            ASSERT_EQ(mesh.vertex_normals[new_index[v]], spatial.vertex_normals[v]) << v;
        }
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                ASSERT_EQ(mesh.triangles[t][k], new_index[spatial.triangles[t][k]]) << t;
    }
}

class InputOrder : public ::testing::TestWithParam<Method> {};

// Shuffling the input changes nothing but the numbers: the same triangles over the same points,
// vertices in input order, the same points dropped.
TEST_P(InputOrder, ShuffledInputGivesTheSameMeshOverTheSamePoints) {
    PointSet s = testing::sample_torus(6000, 1.0, 0.35, testing::Density::Graded);
    testing::add_noise(s, 0.002);
    std::vector<std::uint32_t> shuffle(s.size()); // shuffled point -> original point
    std::iota(shuffle.begin(), shuffle.end(), 0u);
    std::shuffle(shuffle.begin(), shuffle.end(), std::mt19937(7));
    PointSet t = s;
    for (std::size_t i = 0; i < s.size(); ++i) {
        t.positions[i] = s.positions[shuffle[i]];
        t.normals[i] = s.normals[shuffle[i]];
    }
    ReconstructionOptions options;
    options.method = GetParam();
    ReconstructionReport a_report, b_report;
    const Reconstruction a = reconstruct(s, options, Execution{}, a_report);
    const Reconstruction b = reconstruct(t, options, Execution{}, b_report);
    std::vector<std::uint32_t> identity(s.size());
    std::iota(identity.begin(), identity.end(), 0u);
    EXPECT_EQ(triangles_over_points(a, identity), triangles_over_points(b, shuffle));
    EXPECT_TRUE(in_input_order(a.vertex_input_index));
    EXPECT_TRUE(in_input_order(b.vertex_input_index));
    const auto original = [&](std::vector<std::uint32_t> v) {
        for (std::uint32_t& i : v) i = shuffle[i];
        std::sort(v.begin(), v.end());
        return v;
    };
    EXPECT_EQ(a_report.not_in_triangle, original(b_report.not_in_triangle));
    EXPECT_EQ(a_report.dropped_fold, original(b_report.dropped_fold));
    EXPECT_EQ(a_report.mesh.boundary_edges, b_report.mesh.boundary_edges);
    EXPECT_EQ(a_report.vertex_reference_ratio, b_report.vertex_reference_ratio);
}

INSTANTIATE_TEST_SUITE_P(Methods, InputOrder, ::testing::Values(Method::Rsr, Method::Hrsr),
                         [](const auto& param_info) {
                             return std::string(param_info.param == Method::Rsr ? "Rsr" : "Hrsr");
                         });

} // namespace
} // namespace hrsr
