// hrsr: surface reconstruction from point clouds (command-line tool).
// Exit codes: 0 success, 1 unreadable or invalid input / failed output, 2 usage error.
#include "check_command.h"
#include "command_line.h"
#include "errors.h"
#include "malloc_policy.h"
#include "normals_command.h"
#include "reconstruct_command.h"
#include "usage_error.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <new>

namespace {

int fail(int code, const char* what) {
    std::fprintf(stderr, "hrsr: %s\n", what);
    return code;
}

} // namespace

int main(int argc, char** argv) {
    hrsr::app::ask_for_huge_pages(argv);
    hrsr::app::release_large_blocks_eagerly();
    CLI::App app{"hrsr " HRSR_VERSION
                 " - Hierarchical Rotation System Reconstruction of point clouds",
                 "hrsr"};
    app.set_version_flag("--version", "hrsr " HRSR_VERSION);
    app.require_subcommand(1);
    hrsr::app::NormalsArguments normals;
    CLI::App* normals_command = hrsr::app::add_normals_command(app, normals);
    hrsr::app::ReconstructArguments reconstruct;
    CLI::App* reconstruct_command = hrsr::app::add_reconstruct_command(app, reconstruct);
    hrsr::app::CheckArguments check;
    CLI::App* check_command = hrsr::app::add_check_command(app, check);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line: what is wrong, and where to look.
        std::fprintf(stderr, "hrsr: %s (see hrsr --help)\n", e.what());
        return 2;
    }

    try {
        if (normals_command->parsed()) hrsr::app::run_normals(normals);
        if (reconstruct_command->parsed()) hrsr::app::run_reconstruct(reconstruct);
        if (check_command->parsed()) hrsr::app::run_check(check);
        return 0;
    } catch (const hrsr::app::UsageError& e) {
        return fail(2, e.what());
    } catch (const hrsr::InvalidOption& e) {
        return fail(2, hrsr::app::worded(e).c_str());
    } catch (const hrsr::Error& e) { // IoError, InvalidInput, Cancelled
        return fail(1, e.what());
    } catch (const std::bad_alloc&) {
        return fail(1, "out of memory");
    } catch (const std::exception& e) {
        return fail(1, (std::string("internal error: ") + e.what()).c_str());
    }
}
