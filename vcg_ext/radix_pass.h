// One pass of a stable least-significant-digit radix sort, by blocks in parallel.
#pragma once

#include "parallel.h"

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace hrsr {

/// Orders `items` stably by the byte digit(item) (0 … 255), using `buffer` (resized to match).
/// Each block of items counts its digits in parallel, and each block scatters its items after
/// those of every earlier block with the same digit: the order of the sequential pass for any
/// thread count. A pass in which every item has the same digit moves nothing.
template <class Item, class Digit>
void stable_radix_pass(std::vector<Item>& items, std::vector<Item>& buffer, const Digit& digit,
                       const Execution& exec) {
    const std::size_t n = items.size();
    std::vector<std::array<std::size_t, 256>> next(block_count(n, kCheapBlock)); // per block
    parallel_for_blocks(exec, n, kCheapBlock,
                        [&](std::size_t b, std::size_t first, std::size_t end) {
                            next[b].fill(0);
                            for (std::size_t i = first; i < end; ++i) ++next[b][digit(items[i])];
                        });
    std::size_t slot = 0;
    for (std::size_t d = 0; d < 256; ++d) {
        const std::size_t before = slot;
        for (std::array<std::size_t, 256>& count : next) slot += std::exchange(count[d], slot);
        if (slot - before == n) return; // one digit value: already in order
    }
    buffer.resize(n);
    parallel_for_blocks(exec, n, kCheapBlock,
                        [&](std::size_t b, std::size_t first, std::size_t end) {
                            for (std::size_t i = first; i < end; ++i)
                                buffer[next[b][digit(items[i])]++] = items[i];
                        });
    items.swap(buffer);
}

} // namespace hrsr
