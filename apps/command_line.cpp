#include "command_line.h"

#include "usage_error.h"

#include <cstdio>
#include <filesystem>

namespace hrsr::app {

void add_preprocess_options(CLI::App& c, PreprocessOptions& o) {
    c.add_option(
         "--k", o.k,
         "Neighbourhood size (true neighbours) of the orientation graph and component split")
        ->capture_default_str();
    c.add_option("--r", o.r,
                 "Component split: cut neighbour edges longer than r x the mean neighbour distance")
        ->capture_default_str();
    c.add_option("--theta", o.theta_degrees,
                 "Normal filter angle in degrees (tangent distance mode)")
        ->capture_default_str();
    c.add_option_function<std::string>(
         "--distance",
         [&o](const std::string& v) {
             o.distance = v == "euclidean" ? DistanceMode::Euclidean : DistanceMode::Tangent;
         },
         "Edge length: tangent (smooths positions along normals) or euclidean")
        ->transform(CLI::IsMember({"tangent", "euclidean"}, CLI::ignore_case).description(""))
        ->type_name("tangent|euclidean")
        ->default_str("tangent");
    c.add_flag_function(
        "--reestimate-normals", [&o](std::int64_t) { o.normals = NormalSource::Reestimate; },
        "Ignore the input's normals and estimate new ones (PCA + orientation)");
    c.add_option("--k-normals", o.k_normals,
                 "PCA neighbours for normal estimation; 0 = automatic, clamp(N/2000, 16, 192)")
        ->capture_default_str();
    c.add_option("--k-smoothing", o.k_smoothing,
                 "Neighbours of the tangent-mode smoothing; 0 = automatic, clamp(N/2000, 16, 192), "
                 "on HRsR's coarse cloud the same share of the surface")
        ->capture_default_str();
    c.add_option("--min-component-size", o.min_component_size,
                 "Drop connected pieces with fewer points than this (or than the whole cloud)")
        ->capture_default_str();
}

const char* flag_of(OptionId option) {
    switch (option) {
    case OptionId::K:
        return "--k";
    case OptionId::R:
        return "--r";
    case OptionId::Theta:
        return "--theta";
    case OptionId::KNormals:
        return "--k-normals";
    case OptionId::KSmoothing:
        return "--k-smoothing";
    case OptionId::MinComponentSize:
        return "--min-component-size";
    case OptionId::MinHandleLoop:
        return "--n";
    case OptionId::Handles:
        return "--handles";
    case OptionId::FoldRepairRounds:
        return "--fold-repair-rounds";
    case OptionId::CollapseRatio:
        return "--collapse-ratio";
    case OptionId::CollapseK:
        return "--collapse-k";
    case OptionId::LMin:
        return "--l-min";
    case OptionId::RefinementIterations:
        return "--refinement-iterations";
    case OptionId::Output:
        return "-o";
    }
    return option_name(option);
}

std::string worded(const InvalidOption& error) {
    return std::string(flag_of(error.option)) + " " + error.problem;
}

void print_warnings(const std::vector<std::string>& reader, const PreprocessReport& report) {
    for (const std::string& w : reader) std::fprintf(stderr, "hrsr: warning: %s\n", w.c_str());
    for (const std::string& w : report.warnings)
        std::fprintf(stderr, "hrsr: warning: %s\n", w.c_str());
    if (report.input_normals_look_inconsistent)
        std::fprintf(stderr, "hrsr: hint: --reestimate-normals ignores the input's normals\n");
}

void add_threads_option(CLI::App& c, int& threads) {
    c.add_option("--threads", threads, "Worker threads; 0 = all cores")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
}

void add_no_attributes_flag(CLI::App& c, bool& attributes) {
    c.add_flag_function(
        "--no-attributes", [&attributes](std::int64_t) { attributes = false; },
        "Do not carry the points' colour, intensity and other per-point values to the output");
}

nlohmann::json inputs_json(const std::vector<std::string>& inputs) {
    if (inputs.size() == 1) return inputs[0];
    return inputs;
}

std::string inputs_label(const std::vector<std::string>& inputs) {
    std::string label;
    for (const std::string& in : inputs) label += (label.empty() ? "" : ", ") + in;
    return label;
}

void check_output_is_not_input(const std::string& input, const std::string& output) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool same = fs::exists(output, ec)
                          ? fs::equivalent(input, output, ec)
                          : fs::weakly_canonical(input, ec) == fs::weakly_canonical(output, ec);
    if (same)
        throw UsageError("the output " + output + " is the input file; refusing to overwrite it");
}

void check_outputs(const std::string& input, const std::string& output, const std::string& report) {
    check_output_is_not_input(input, output);
    if (!report.empty()) check_output_is_not_input(input, report);
}

} // namespace hrsr::app
