// A binary min-heap of vertices keyed by an edge each (Prim's best connection, the collapse's
// smallest admissible edge): O(vertices) memory, unlike a lazy heap holding every edge.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

namespace hrsr {

/// An edge with its cost, totally ordered by (cost, lo, hi) (D-10).
struct EdgeKey {
    double cost;
    std::uint32_t lo, hi;
    bool operator<(const EdgeKey& o) const {
        return std::tie(cost, lo, hi) < std::tie(o.cost, o.lo, o.hi);
    }
    bool touches(std::uint32_t v) const { return lo == v || hi == v; }
};

class VertexHeap {
public:
    explicit VertexHeap(std::size_t n) : slot_(n, kNone), key_(n) {}

    /// All at once: vertex v is queued with keys[v] where present[v] (linear time).
    void assign(std::vector<EdgeKey> keys, const std::vector<std::uint8_t>& present) {
        key_ = std::move(keys);
        heap_.clear();
        slot_.assign(key_.size(), kNone);
        for (std::uint32_t v = 0; v < key_.size(); ++v) {
            if (!present[v]) continue;
            slot_[v] = std::uint32_t(heap_.size());
            heap_.push_back(v);
        }
        for (std::size_t s = heap_.size() / 2; s-- > 0;) sift_down(s);
    }

    bool empty() const { return heap_.empty(); }
    bool contains(std::uint32_t v) const { return slot_[v] != kNone; }
    const EdgeKey& key(std::uint32_t v) const { return key_[v]; }
    std::uint32_t top() const { return heap_.front(); }

    /// Queues v with key k, or moves it to k (up or down) if it is queued.
    void set(std::uint32_t v, const EdgeKey& k) {
        if (!contains(v)) {
            slot_[v] = std::uint32_t(heap_.size());
            heap_.push_back(v);
        }
        key_[v] = k;
        sift_up(slot_[v]);
        sift_down(slot_[v]);
    }
    void erase(std::uint32_t v) {
        const std::uint32_t s = slot_[v];
        if (s == kNone) return;
        slot_[v] = kNone;
        const std::uint32_t last = heap_.back();
        heap_.pop_back();
        if (last == v) return;
        place(last, s);
        sift_up(s);
        sift_down(slot_[last]);
    }
    std::uint32_t pop() {
        const std::uint32_t v = top();
        erase(v);
        return v;
    }

private:
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

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
    std::vector<std::uint32_t> slot_; ///< per vertex: its index in heap_, or kNone
    std::vector<EdgeKey> key_;
};

} // namespace hrsr
