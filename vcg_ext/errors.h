// The error types the core throws. Each message is meant for a user: it names what is wrong
// and, where it can, what to change.
#pragma once

#include <stdexcept>
#include <string>

namespace hrsr {

/// Base of every error the library throws on purpose.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The data cannot be processed (e.g. no usable point left).
struct InvalidInput : Error {
    using Error::Error;
};

/// An option is out of range; the message names the option.
struct InvalidOption : Error {
    using Error::Error;
};

/// A file cannot be read or written; the message names the file and the problem.
struct IoError : Error {
    using Error::Error;
};

/// The progress callback asked to stop.
struct Cancelled : Error {
    Cancelled() : Error("cancelled by the caller") {}
};

} // namespace hrsr
