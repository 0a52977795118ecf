// Fans at a vertex (§5.8): the whole-mesh count and the count restricted to flagged vertices,
// which D-32 uses for the corners of the faces it cut or added.
#include "mesh/fans.h"
#include "mesh/triangle_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace hrsr {
namespace {

// Two discs of two triangles each, touching at vertex 0 only (a bow tie), and a separate
// triangle.
std::vector<Triangle> bow_tie() {
    return {{0, 1, 2}, {0, 2, 3}, {0, 4, 5}, {0, 5, 6}, {7, 8, 9}};
}

TEST(Fans, ABowTieVertexHasTwoFansInTheOrderOfTheirFirstTriangle) {
    const Fans fans = compute_fans(10, bow_tie());
    EXPECT_EQ(fans.fan_count[0], 2u);
    EXPECT_EQ(fans.fan_count[2], 1u);
    EXPECT_EQ(fans.corner_fan[0], 0u); // triangle 0, corner 0
    EXPECT_EQ(fans.corner_fan[3], 0u); // triangle 1
    EXPECT_EQ(fans.corner_fan[6], 1u); // triangle 2
    EXPECT_EQ(fans.corner_fan[9], 1u); // triangle 3
}

TEST(Fans, FlaggedVerticesGetTheWholeMeshNumbering) {
    const std::vector<Triangle> triangles = bow_tie();
    const Fans all = compute_fans(10, triangles);
    std::vector<std::uint8_t> only(10, 0);
    only[0] = only[5] = 1;
    const Fans some = compute_fans(10, triangles, only);
    EXPECT_EQ(some.fan_count, all.fan_count); // every vertex here has one fan but vertex 0
    EXPECT_EQ(some.corner_fan, all.corner_fan);
}

TEST(Fans, SplittingOnlyFlaggedVerticesGivesTheSameMesh) {
    std::vector<Triangle> whole = bow_tie(), flagged = bow_tie();
    std::vector<std::uint8_t> only(10, 0);
    only[0] = 1;
    const std::vector<std::uint32_t> source_whole = compact_and_split_vertices(10, whole);
    const std::vector<std::uint32_t> source_flagged =
        compact_and_split_vertices(10, flagged, &only);
    EXPECT_EQ(source_flagged, source_whole);
    EXPECT_EQ(flagged, whole);
    ASSERT_EQ(source_whole.size(), 11u); // vertex 0 copied once
    EXPECT_EQ(source_whole[10], 0u);
    EXPECT_EQ(whole[2][0], 10u); // the second fan uses the copy
}

TEST(Fans, AnyThreadCountNumbersTheSameFans) {
    // 5,000 bow ties (vertices over several blocks of the parallel numbering), their triangles
    // listed back to front so that a vertex's corners come in no particular order.
    std::vector<Triangle> triangles;
    for (std::uint32_t b = 5000; b-- > 0;)
        for (const Triangle& t : bow_tie())
            triangles.push_back({t[0] + 10 * b, t[1] + 10 * b, t[2] + 10 * b});
    const Fans one = compute_fans(50000, triangles);
    for (int threads : {2, 8}) {
        const Fans many = compute_fans(50000, triangles, {threads, nullptr});
        EXPECT_EQ(many.fan_count, one.fan_count);
        EXPECT_EQ(many.corner_fan, one.corner_fan);
        std::vector<Triangle> split_one = triangles, split_many = triangles;
        EXPECT_EQ(compact_and_split_vertices(50000, split_many, nullptr, {threads, nullptr}),
                  compact_and_split_vertices(50000, split_one));
        EXPECT_EQ(split_many, split_one);
    }
    std::size_t bow_ties = 0;
    for (std::uint32_t b = 0; b < 5000; ++b) bow_ties += one.fan_count[10 * b] == 2;
    EXPECT_EQ(bow_ties, 5000u);
}

// The corners around each vertex built by one task per range of vertices are the sequential
// lists exactly (each vertex's corners in increasing order), for any thread count.
TEST(CornersByVertex, RangesOfVerticesGiveTheSequentialLists) {
    std::mt19937 random(7);
    const std::uint32_t n = 50000;
    std::uniform_int_distribution<std::uint32_t> vertex(0, n - 1);
    std::vector<Triangle> triangles(200000); // over the parallel threshold
    for (Triangle& t : triangles) t = {vertex(random), vertex(random), vertex(random)};
    const VertexCorners sequential = corners_by_vertex(n, triangles);
    for (int threads : {2, 3, 8}) {
        const VertexCorners ranges = corners_by_vertex(n, triangles, Execution{threads});
        EXPECT_EQ(ranges.start, sequential.start) << threads << " threads";
        EXPECT_EQ(ranges.corner, sequential.corner) << threads << " threads";
    }
    for (std::uint32_t v = 0; v < n; ++v)
        for (std::uint32_t e = sequential.begin(v); e < sequential.end(v); ++e)
            ASSERT_EQ(triangles[sequential.corner[e] / 3][sequential.corner[e] % 3], v);
}

// D-46: faces ordered by their smallest vertex, stably (faces sharing it keep their order), the
// same order for any thread count; each face keeps its corners as they were.
TEST(SortBySmallestVertex, StableAndTheSameForAnyThreadCount) {
    std::mt19937 random(11);
    // Vertex ids over all four bytes, with many faces sharing a smallest vertex.
    std::uniform_int_distribution<std::uint32_t> vertex(0, 0xfffffff0u), small(0, 999);
    std::vector<Triangle> triangles(200000); // several blocks of the parallel passes
    for (std::uint32_t k = 0; k < triangles.size(); ++k)
        triangles[k] = k % 2 ? Triangle{vertex(random), vertex(random), vertex(random)}
                             : Triangle{vertex(random), small(random), vertex(random)};
    auto smallest = [](const Triangle& t) { return std::min({t[0], t[1], t[2]}); };
    std::vector<Triangle> expected = triangles;
    std::stable_sort(expected.begin(), expected.end(), [&](const Triangle& a, const Triangle& b) {
        return smallest(a) < smallest(b);
    });
    for (int threads : {1, 2, 8}) {
        std::vector<Triangle> sorted = triangles;
        sort_by_smallest_vertex(sorted, Execution{threads});
        EXPECT_EQ(sorted, expected) << threads << " threads";
    }
}

} // namespace
} // namespace hrsr
