// Options shared by the subcommands, and file-path checks.
#pragma once

#include "options.h"

#include <CLI/CLI.hpp>

#include <string>

namespace hrsr::app {

/// --k, --r, --theta, --distance, --reestimate-normals, --k-normals, --min-component-size.
void add_preprocess_options(CLI::App& command, PreprocessOptions& options);

/// Throws UsageError when `output` names the input file (we never overwrite the input).
void check_output_is_not_input(const std::string& input, const std::string& output);

} // namespace hrsr::app
