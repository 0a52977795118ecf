#include "graph/spanning_forest.h"

#include <tuple>

namespace hrsr {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

struct EdgeKey {
    double cost;
    std::uint32_t lo, hi;
    bool operator<(const EdgeKey& o) const {
        return std::tie(cost, lo, hi) < std::tie(o.cost, o.lo, o.hi);
    }
};

// Binary min-heap of vertices keyed by their best connection, with decrease-key. Memory is
// O(vertices), unlike a lazy heap holding every edge.
class VertexHeap {
public:
    explicit VertexHeap(std::size_t n) : slot_(n, kNone), key_(n) {}
    bool empty() const { return heap_.empty(); }
    bool contains(std::uint32_t v) const { return slot_[v] != kNone; }
    const EdgeKey& key(std::uint32_t v) const { return key_[v]; }

    void push_or_decrease(std::uint32_t v, const EdgeKey& k) {
        if (!contains(v)) {
            slot_[v] = std::uint32_t(heap_.size());
            heap_.push_back(v);
        } else if (!(k < key_[v])) {
            return;
        }
        key_[v] = k;
        sift_up(slot_[v]);
    }
    std::uint32_t pop() {
        const std::uint32_t top = heap_.front();
        place(heap_.back(), 0);
        heap_.pop_back();
        slot_[top] = kNone;
        if (!heap_.empty()) sift_down(0);
        return top;
    }

private:
    void place(std::uint32_t v, std::size_t s) {
        heap_[s] = v;
        slot_[v] = std::uint32_t(s);
    }
    void sift_up(std::size_t s) {
        const std::uint32_t v = heap_[s];
        while (s > 0 && key_[v] < key_[heap_[(s - 1) / 2]]) {
            place(heap_[(s - 1) / 2], s);
            s = (s - 1) / 2;
        }
        place(v, s);
    }
    void sift_down(std::size_t s) {
        const std::uint32_t v = heap_[s];
        for (;;) {
            std::size_t child = 2 * s + 1;
            if (child >= heap_.size()) break;
            if (child + 1 < heap_.size() && key_[heap_[child + 1]] < key_[heap_[child]]) ++child;
            if (!(key_[heap_[child]] < key_[v])) break;
            place(heap_[child], s);
            s = child;
        }
        place(v, s);
    }
    std::vector<std::uint32_t> heap_;
    std::vector<std::uint32_t> slot_;
    std::vector<EdgeKey> key_;
};

} // namespace

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
        heap.push_or_decrease(root, {0.0, root, root});
        while (!heap.empty()) {
            const std::uint32_t v = heap.pop();
            in_tree[v] = 1;
            forest.order.push_back(v);
            for (const std::uint32_t* w = graph.begin(v); w != graph.end(v); ++w) {
                if (in_tree[*w]) continue;
                const EdgeKey key{cost(v, *w), std::min(v, *w), std::max(v, *w)};
                if (!heap.contains(*w) || key < heap.key(*w)) {
                    heap.push_or_decrease(*w, key);
                    forest.parent[*w] = v;
                }
            }
        }
    }
    return forest;
}

} // namespace hrsr
