#include "process_stats.h"

#include <sys/resource.h>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace hrsr::app {

std::size_t peak_memory_bytes() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
    return std::size_t(usage.ru_maxrss) * 1024; // Linux reports kilobytes
}

void release_large_blocks_eagerly() {
#ifdef __GLIBC__
    mallopt(M_MMAP_THRESHOLD, 1 << 20); // a fixed threshold: no more dynamic raising
#endif
}

} // namespace hrsr::app
