#include "graph/spanning_forest.h"

#include "graph/vertex_heap.h"

namespace hrsr {

SpanningForest
minimum_spanning_forest(const CsrGraph& graph,
                        const std::function<double(std::uint32_t, std::uint32_t)>& cost) {
    const std::size_t n = graph.size();
    SpanningForest forest;
    forest.parent.assign(n, SpanningForest::kRoot);
    forest.order.reserve(n);
    std::vector<std::uint8_t> in_tree(n, 0);
    VertexHeap heap(n);
    for (std::uint32_t root = 0; root < n; ++root) {
        if (in_tree[root]) continue;
        ++forest.trees;
        heap.set(root, {0.0, root, root});
        while (!heap.empty()) {
            const std::uint32_t v = heap.pop();
            in_tree[v] = 1;
            forest.order.push_back(v);
            for (const std::uint32_t* w = graph.begin(v); w != graph.end(v); ++w) {
                if (in_tree[*w]) continue;
                const EdgeKey key{cost(v, *w), std::min(v, *w), std::max(v, *w)};
                if (!heap.contains(*w) || key < heap.key(*w)) {
                    heap.set(*w, key);
                    forest.parent[*w] = v;
                }
            }
        }
    }
    return forest;
}

} // namespace hrsr
