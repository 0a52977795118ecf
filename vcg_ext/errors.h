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

/// The options a caller can set, named without any front end's spelling: the CLI words them as
/// flags, the MeshLab filter as its fields.
enum class OptionId {
    K,
    R,
    Theta,
    KNormals,
    KSmoothing,
    MinComponentSize,
    MinHandleLoop, ///< n
    Handles,
    FoldRepairRounds,
    CollapseRatio, ///< p
    CollapseK,
    LMin,
    RefinementIterations,
    Output, ///< the output file (its format)
};

/// The option's name in the library's own terms (the field of the options structs: "k",
/// "collapse_ratio", ...).
const char* option_name(OptionId option);

/// An option is out of range. `problem` says what is wrong without naming the option ("must be
/// between 3 and 1000 (got 2)"), so that each front end can put its own name for it in front;
/// what() uses option_name().
struct InvalidOption : Error {
    InvalidOption(OptionId option_id, const std::string& problem_text)
        : Error(std::string(option_name(option_id)) + " " + problem_text), option(option_id),
          problem(problem_text) {}
    OptionId option;
    std::string problem;
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
