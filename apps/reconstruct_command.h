// `hrsr reconstruct`: point cloud in, triangle mesh out.
#pragma once

#include "options.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace hrsr::app {

struct ReconstructArguments {
    std::vector<std::string> inputs; ///< read as one cloud, in this order
    std::string output;
    std::string report; ///< JSON report path; empty = none
    std::string method = "hrsr";
    std::string l_min; ///< "0.5" (input units) or "1%" (of the bounding-box diagonal)
    ReconstructionOptions options;
    int threads = 0;
    bool quiet = false;
    bool attributes = true; ///< carry the points' colour and other values to the vertices
    bool ascii = false;     ///< ascii PLY output
};

CLI::App* add_reconstruct_command(CLI::App& app, ReconstructArguments& args);

void run_reconstruct(const ReconstructArguments& args);

} // namespace hrsr::app
