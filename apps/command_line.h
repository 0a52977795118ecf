// Options shared by the subcommands, and file-path checks.
#pragma once

#include "errors.h"
#include "options.h"
#include "preprocess/report.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace hrsr::app {

/// --k, --r, --theta, --distance, --reestimate-normals, --k-normals, --min-component-size.
void add_preprocess_options(CLI::App& command, PreprocessOptions& options);

/// The flag that sets `option` ("--collapse-ratio"; "-o" for the output).
const char* flag_of(OptionId option);

/// The core's complaint about an option, worded with its flag: "--k must be between 3 and 1000
/// (got 1)".
std::string worded(const InvalidOption& error);

/// Prints the reader's and the pre-processing's warnings on stderr, with the flag that helps
/// where there is one.
void print_warnings(const std::vector<std::string>& reader, const PreprocessReport& report);

/// --threads (0 = all cores, the default).
void add_threads_option(CLI::App& command, int& threads);

/// --no-attributes: sets `attributes` to false.
void add_no_attributes_flag(CLI::App& command, bool& attributes);

/// The input files as a report shows them: a string for one file, an array for several.
nlohmann::json inputs_json(const std::vector<std::string>& inputs);

/// The input files as an error message names them ("a.ply" or "a.laz, b.laz").
std::string inputs_label(const std::vector<std::string>& inputs);

/// Throws UsageError when `output` names the input file (we never overwrite the input).
void check_output_is_not_input(const std::string& input, const std::string& output);

/// The same for a command's output and (if not empty) its report.
void check_outputs(const std::string& input, const std::string& output, const std::string& report);

/// Runs `work`; an InvalidInput it throws is rethrown with the input file's name in front, as
/// every input error names its file.
template <class Work>
auto naming_input(const std::string& input, Work&& work) -> decltype(work()) {
    try {
        return work();
    } catch (const InvalidInput& e) {
        throw InvalidInput(input + ": " + e.what());
    }
}

} // namespace hrsr::app
