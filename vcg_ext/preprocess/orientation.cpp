#include "preprocess/orientation.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>

namespace hrsr {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// Cost of joining a vertex to the tree through an edge, totally ordered (D-10).
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
        move(heap_.back(), 0);
        heap_.pop_back();
        slot_[top] = kNone;
        if (!heap_.empty()) sift_down(0);
        return top;
    }

private:
    void move(std::uint32_t v, std::size_t s) {
        heap_[s] = v;
        slot_[v] = std::uint32_t(s);
    }
    void sift_up(std::size_t s) {
        const std::uint32_t v = heap_[s];
        while (s > 0 && key_[v] < key_[heap_[(s - 1) / 2]]) {
            move(heap_[(s - 1) / 2], s);
            s = (s - 1) / 2;
        }
        move(v, s);
    }
    void sift_down(std::size_t s) {
        const std::uint32_t v = heap_[s];
        for (;;) {
            std::size_t child = 2 * s + 1;
            if (child >= heap_.size()) break;
            if (child + 1 < heap_.size() && key_[heap_[child + 1]] < key_[heap_[child]]) ++child;
            if (!(key_[heap_[child]] < key_[v])) break;
            move(heap_[child], s);
            s = child;
        }
        move(v, s);
    }
    std::vector<std::uint32_t> heap_;
    std::vector<std::uint32_t> slot_;
    std::vector<EdgeKey> key_;
};

} // namespace

OrientationResult orient_normals(const CsrGraph& graph, std::vector<Vec3>& normals) {
    OrientationResult result;
    const std::size_t n = graph.size();
    std::vector<std::uint8_t> in_tree(n, 0);
    std::vector<std::uint32_t> parent(n, kNone);
    VertexHeap heap(n);
    for (std::uint32_t root = 0; root < n; ++root) {
        if (in_tree[root]) continue;
        ++result.components;
        heap.push_or_decrease(root, {0.0, root, root});
        while (!heap.empty()) {
            const std::uint32_t v = heap.pop();
            in_tree[v] = 1;
            // The parent joined the tree earlier, so its normal is final: propagating in Prim's
            // order equals the breadth-first traversal of the finished tree.
            if (parent[v] != kNone && normals[v].dot(normals[parent[v]]) < 0) {
                normals[v] = -normals[v];
                ++result.flips;
            }
            for (const std::uint32_t* w = graph.begin(v); w != graph.end(v); ++w) {
                if (in_tree[*w]) continue;
                const double cost = 1.0 - std::abs(normals[v].dot(normals[*w]));
                const EdgeKey key{cost, std::min(v, *w), std::max(v, *w)};
                if (!heap.contains(*w) || key < heap.key(*w)) {
                    heap.push_or_decrease(*w, key);
                    parent[*w] = v;
                }
            }
        }
    }
    return result;
}

} // namespace hrsr
