#include "process_stats.h"

#include <sys/resource.h>

namespace hrsr::app {

std::size_t peak_memory_bytes() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
    return std::size_t(usage.ru_maxrss) * 1024; // Linux reports kilobytes
}

} // namespace hrsr::app
