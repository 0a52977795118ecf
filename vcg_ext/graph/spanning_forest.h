// Minimum spanning forest of an undirected graph (Prim), deterministic under ties.
#pragma once

#include "graph/neighbour_graph.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

namespace hrsr {

struct SpanningForest {
    static constexpr std::uint32_t kRoot = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> parent; ///< per vertex: its tree parent, or kRoot
    std::vector<std::uint32_t> order;  ///< vertices in the order they joined (parents first)
    std::size_t trees = 0;
};

/// Prim's algorithm grown from the smallest index of each connected piece. Edge keys are
/// (cost(i, j), smaller endpoint, larger endpoint), so the forest is unique (D-10). `cost` must
/// be symmetric.
SpanningForest
minimum_spanning_forest(const CsrGraph& graph,
                        const std::function<double(std::uint32_t, std::uint32_t)>& cost);

} // namespace hrsr
