// Deterministic parallel loops over indices (OpenMP). Results must be written by index so that
// they do not depend on the thread count; reductions are done by the caller, sequentially.
#pragma once

#include "progress.h"

#include <cstddef>
#include <functional>

namespace hrsr {

/// How a stage runs: thread count (0 = OpenMP's default) and where progress goes.
struct Execution {
    int threads = 0;
    Progress* progress = nullptr;
};

/// Calls body(i) for every i in [0, n), in parallel. Progress is reported from the calling
/// thread only. An exception thrown by `body` or by the progress callback (including
/// Cancelled) stops the loop promptly and is rethrown here, on the calling thread. Indices are
/// handed out in chunks of `chunk` (0: sized from n, for cheap bodies; 1: for a few long tasks).
void parallel_for(const Execution& exec, std::size_t n,
                  const std::function<void(std::size_t)>& body, std::size_t chunk = 0);

/// Number of threads parallel_for would use.
int thread_count(const Execution& exec);

} // namespace hrsr
