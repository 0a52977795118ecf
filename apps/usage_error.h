#pragma once

#include <stdexcept>

namespace hrsr::app {

/// A mistake in how the command was called (exit code 2).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace hrsr::app
