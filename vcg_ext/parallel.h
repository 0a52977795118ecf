// Deterministic parallel loops over indices (OpenMP). Results must be written by index so that
// they do not depend on the thread count; reductions are done by the caller, sequentially.
#pragma once

#include "progress.h"

#include <algorithm>
#include <cstddef>
#include <functional>

namespace hrsr {

/// How a stage runs: thread count (0 = OpenMP's default) and where progress goes.
struct Execution {
    int threads = 0;
    Progress* progress = nullptr;
};

/// The same threads, reporting no progress: for the inner loops of a phase that reports its own
/// fraction, or of one that reports none.
inline Execution without_progress(const Execution& exec) {
    return {exec.threads, nullptr};
}

/// Calls body(i) for every i in [0, n), in parallel. Progress is reported from the calling
/// thread only. An exception thrown by `body` or by the progress callback (including
/// Cancelled) stops the loop promptly and is rethrown here, on the calling thread. Indices are
/// handed out in chunks of `chunk` (0: sized from n, for cheap bodies; 1: for a few long tasks).
void parallel_for(const Execution& exec, std::size_t n,
                  const std::function<void(std::size_t)>& body, std::size_t chunk = 0);

/// Number of threads parallel_for would use.
int thread_count(const Execution& exec);

/// Indices per task for loops whose body is cheap (a few memory reads per index).
inline constexpr std::size_t kCheapBlock = 16384;

/// How many blocks of `block` consecutive indices [0, n) makes (the last may be shorter).
inline std::size_t block_count(std::size_t n, std::size_t block) {
    return (n + block - 1) / block;
}

/// Calls body(b, first, end) for every block b of [0, n), [first, end) its indices, one block per
/// task, in parallel. Results gathered per block and joined in block order are the same for any
/// thread count.
template <class Body>
void parallel_for_blocks(const Execution& exec, std::size_t n, std::size_t block,
                         const Body& body) {
    parallel_for(
        exec, block_count(n, block),
        [&](std::size_t b) { body(b, b * block, std::min(n, (b + 1) * block)); }, 1);
}

} // namespace hrsr
