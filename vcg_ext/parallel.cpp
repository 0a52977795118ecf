#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hrsr {

int thread_count(const Execution& exec) {
#ifdef _OPENMP
    return exec.threads > 0 ? exec.threads : omp_get_max_threads();
#else
    (void)exec;
    return 1;
#endif
}

void parallel_for(const Execution& exec, std::size_t n,
                  const std::function<void(std::size_t)>& body, std::size_t chunk) {
    if (n == 0) return;
    // Fixed-size chunks handed out dynamically: the split changes nothing in the results
    // (they are written by index), it only balances uneven per-point work.
    if (chunk == 0) chunk = std::clamp<std::size_t>(n / 256, 64, 4096);
    const std::size_t chunks = (n + chunk - 1) / chunk;
    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> stop{false};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    auto fail = [&](std::exception_ptr e) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = e;
        stop = true;
    };
    const int threads = thread_count(exec);

#pragma omp parallel num_threads(threads)
    {
#ifdef _OPENMP
        const bool is_caller = omp_get_thread_num() == 0;
#else
        const bool is_caller = true;
#endif
        for (std::size_t c = next++; c < chunks && !stop; c = next++) {
            try {
                const std::size_t end = std::min(n, (c + 1) * chunk);
                for (std::size_t i = c * chunk; i < end; ++i) body(i);
            } catch (...) {
                fail(std::current_exception());
            }
            const std::size_t finished = ++done;
            if (is_caller && exec.progress && !stop) {
                try {
                    exec.progress->update(double(finished) / double(chunks));
                } catch (...) {
                    fail(std::current_exception());
                }
            }
        }
    }
    if (failure) std::rethrow_exception(failure);
}

} // namespace hrsr
