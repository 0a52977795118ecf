// Union-find that threads may update at once: the sets (a partition, hence what the caller
// derives from them) are the same for any thread count and any order of the unions.
#pragma once

#include "parallel.h"

#include <atomic>
#include <cstdint>
#include <vector>

namespace hrsr {

/// Lock-free union-find: a root is linked under a smaller root with a compare-and-swap, so
/// parents only decrease and every set's root is its smallest member once the unions are done.
class ConcurrentSets {
public:
    ConcurrentSets(std::size_t n, const Execution& exec);

    /// The root of x's set; may be called while other threads unite (path halving).
    std::uint32_t find(std::uint32_t x) {
        for (;;) {
            std::uint32_t p = parent_[x].load(std::memory_order_relaxed);
            if (p == x) return x;
            const std::uint32_t g = parent_[p].load(std::memory_order_relaxed);
            if (g != p) parent_[x].compare_exchange_weak(p, g, std::memory_order_relaxed);
            x = g;
        }
    }

    void unite(std::uint32_t a, std::uint32_t b) {
        for (;;) {
            a = find(a);
            b = find(b);
            if (a == b) return;
            if (a < b) std::swap(a, b);
            // a is the larger root: link it under b unless another thread linked it meanwhile.
            std::uint32_t expected = a;
            if (parent_[a].compare_exchange_strong(expected, b, std::memory_order_relaxed)) return;
        }
    }

    /// Each element's set as the 0-based rank of its smallest member among the sets' smallest
    /// members: sets numbered in order of their first element. `count` receives their number.
    std::vector<std::uint32_t> labels(const Execution& exec, std::size_t& count);

private:
    std::vector<std::atomic<std::uint32_t>> parent_;
};

} // namespace hrsr
