// `hrsr check`: measures a triangle mesh (topology, orientation, face quality, intersections),
// optionally against its input cloud (r_v) and a reference surface (Chamfer, Hausdorff).
#pragma once

#include "mesh/check.h"

#include <CLI/CLI.hpp>

#include <string>

namespace hrsr::app {

struct CheckArguments {
    std::string mesh;
    std::string input;     ///< point cloud the mesh was made from; empty = none
    std::string reference; ///< reference mesh; empty = none
    std::string report;    ///< JSON file; empty = none
    bool json = false;     ///< print the JSON document instead of the summary
    CheckOptions options;
    int threads = 0;
};

CLI::App* add_check_command(CLI::App& app, CheckArguments& args);

void run_check(const CheckArguments& args);

} // namespace hrsr::app
