// The minimum spanning forest (graph/spanning_forest.h) against an independent Prim with a lazy
// queue: the same forest with ties broken by the vertices (D-10), rooted at each piece's
// smallest vertex, parents first.
#include "graph/spanning_forest.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <queue>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace hrsr {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;
using Key = std::tuple<double, std::uint32_t, std::uint32_t>;

// The undirected graph of `edges`, as the code builds its graphs (neighbour_graph.h).
CsrGraph graph_of(std::size_t n, const std::set<Edge>& edges) {
    CsrGraph directed;
    auto edge = edges.begin();
    for (std::uint32_t v = 0; v < n; ++v) {
        for (; edge != edges.end() && edge->first == v; ++edge)
            directed.adjacency.push_back(edge->second);
        directed.offsets.push_back(directed.adjacency.size());
    }
    return symmetric_union(std::move(directed), {});
}

// The oracle: Prim's algorithm with a lazy queue of keyed edges, grown from the smallest vertex
// of each piece. Returns the forest's edges as (lo, hi), sorted.
std::vector<Edge> prim_edges(const CsrGraph& g, const std::vector<std::vector<double>>& cost) {
    const std::size_t n = g.size();
    std::vector<std::uint8_t> in(n, 0);
    std::vector<Edge> edges;
    std::priority_queue<std::pair<Key, std::uint32_t>, std::vector<std::pair<Key, std::uint32_t>>,
                        std::greater<>>
        queue;
    for (std::uint32_t root = 0; root < n; ++root) {
        if (in[root]) continue;
        queue.push({{0.0, root, root}, root});
        while (!queue.empty()) {
            const auto [key, v] = queue.top();
            queue.pop();
            if (in[v]) continue;
            in[v] = 1;
            if (std::get<1>(key) != std::get<2>(key))
                edges.emplace_back(std::get<1>(key), std::get<2>(key));
            for (const std::uint32_t* w = g.begin(v); w != g.end(v); ++w)
                if (!in[*w]) queue.push({{cost[v][*w], std::min(v, *w), std::max(v, *w)}, *w});
        }
    }
    std::sort(edges.begin(), edges.end());
    return edges;
}

struct RandomGraph {
    std::size_t n;
    std::set<Edge> edges;
    std::vector<std::vector<double>> cost; ///< symmetric; few distinct values: many ties
};

RandomGraph random_graph(std::size_t n, std::size_t edge_count, int distinct_costs, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_int_distribution<std::uint32_t> vertex(0, std::uint32_t(n - 1));
    std::uniform_int_distribution<int> value(0, distinct_costs - 1);
    RandomGraph r{n, {}, std::vector<std::vector<double>>(n, std::vector<double>(n, 0.0))};
    while (r.edges.size() < edge_count) {
        const std::uint32_t a = vertex(random), b = vertex(random);
        if (a == b) continue;
        if (!r.edges.insert({std::min(a, b), std::max(a, b)}).second) continue;
        r.cost[a][b] = r.cost[b][a] = double(value(random));
    }
    return r;
}

// Every vertex's parent comes before it, each tree starts at its piece's smallest vertex, and
// the parent edges are the forest's.
void expect_rooted_forest(const SpanningForest& f, const std::vector<Edge>& expected_edges,
                          std::size_t n) {
    ASSERT_EQ(f.parent.size(), n);
    ASSERT_EQ(f.order.size(), n);
    std::vector<std::size_t> position(n, n);
    for (std::size_t i = 0; i < n; ++i) position[f.order[i]] = i;
    std::vector<Edge> edges;
    std::size_t roots = 0;
    std::uint32_t last_root = 0;
    for (std::uint32_t v : f.order) {
        const std::uint32_t p = f.parent[v];
        if (p == SpanningForest::kRoot) {
            EXPECT_TRUE(roots == 0 || v > last_root) << "trees start at increasing vertices";
            last_root = v;
            ++roots;
            continue;
        }
        EXPECT_LT(position[p], position[v]) << "parents first";
        EXPECT_GT(v, last_root) << "a tree's root is its smallest vertex";
        edges.emplace_back(std::min(p, v), std::max(p, v));
    }
    EXPECT_EQ(roots, f.trees);
    std::sort(edges.begin(), edges.end());
    EXPECT_EQ(edges, expected_edges);
}

TEST(SpanningForest, TheForestOfTheKeysWithManyTies) {
    for (unsigned seed = 1; seed <= 12; ++seed) {
        // Sparse graphs fall into pieces; two or three cost values make most keys tie on cost.
        const std::size_t n = 300 + 40 * seed;
        const RandomGraph r = random_graph(n, n * (seed % 3 == 0 ? 1 : 3), 2 + int(seed % 2), seed);
        const CsrGraph g = graph_of(n, r.edges);
        const auto cost = [&](std::uint32_t i, std::uint32_t j) { return r.cost[i][j]; };
        const std::vector<Edge> expected = prim_edges(g, r.cost);
        expect_rooted_forest(minimum_spanning_forest(g, cost), expected, n);
    }
}

TEST(SpanningForest, IsolatedVerticesAreTreesOfTheirOwn) {
    const CsrGraph g = graph_of(5, {{1, 3}});
    const SpanningForest f =
        minimum_spanning_forest(g, [](std::uint32_t, std::uint32_t) { return 1.0; });
    EXPECT_EQ(f.trees, 4u);
    EXPECT_EQ(f.order, (std::vector<std::uint32_t>{0, 1, 3, 2, 4}));
    EXPECT_EQ(f.parent[3], 1u);
    for (std::uint32_t v : {0u, 1u, 2u, 4u}) EXPECT_EQ(f.parent[v], SpanningForest::kRoot);
}

TEST(SpanningForest, EmptyGraph) {
    const SpanningForest f =
        minimum_spanning_forest(CsrGraph{}, [](std::uint32_t, std::uint32_t) { return 0.0; });
    EXPECT_EQ(f.trees, 0u);
    EXPECT_TRUE(f.order.empty());
}

} // namespace
} // namespace hrsr
