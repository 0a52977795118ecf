#include "graph/concurrent_sets.h"

namespace hrsr {

ConcurrentSets::ConcurrentSets(std::size_t n, const Execution& exec) : parent_(n) {
    parallel_for_blocks(exec, n, kCheapBlock, [&](std::size_t, std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i)
            parent_[i].store(std::uint32_t(i), std::memory_order_relaxed);
    });
}

std::vector<std::uint32_t> ConcurrentSets::labels(const Execution& exec, std::size_t& count) {
    const std::size_t n = parent_.size();
    std::vector<std::uint32_t> label(n);
    parallel_for_blocks(exec, n, kCheapBlock, [&](std::size_t, std::size_t first, std::size_t end) {
        for (std::size_t i = first; i < end; ++i) label[i] = find(std::uint32_t(i));
    });
    // A root is its set's smallest member, so it is numbered before any other member reads it.
    count = 0;
    for (std::size_t i = 0; i < n; ++i)
        label[i] = label[i] == i ? std::uint32_t(count++) : label[label[i]];
    return label;
}

} // namespace hrsr
