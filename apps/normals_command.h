// `hrsr normals`: clean and orient a point cloud, write it with unit normals.
#pragma once

#include "options.h"

#include <CLI/CLI.hpp>

#include <string>

namespace hrsr::app {

struct NormalsArguments {
    std::string input;
    std::string output;
    std::string report; ///< JSON report path; empty = none
    PreprocessOptions options;
    int threads = 0;
    bool quiet = false;
    bool attributes = true; ///< carry the points' colour and other values to the output
};

/// Registers the subcommand and its options (defaults from the options header).
CLI::App* add_normals_command(CLI::App& app, NormalsArguments& args);

/// Runs it. Throws hrsr::Error subclasses (mapped to exit codes by main) or UsageError.
void run_normals(const NormalsArguments& args);

} // namespace hrsr::app
