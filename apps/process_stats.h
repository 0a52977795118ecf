// Resource use of this process, for reports.
#pragma once

#include <cstddef>

namespace hrsr::app {

/// Peak resident set size so far, in bytes (0 if unknown).
std::size_t peak_memory_bytes();

} // namespace hrsr::app
