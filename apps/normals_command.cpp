#include "normals_command.h"

#include "command_line.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"
#include "normals.h"
#include "process_stats.h"
#include "report_json.h"
#include "terminal_progress.h"

#include "errors.h"

#include <cstdio>

namespace hrsr::app {

CLI::App* add_normals_command(CLI::App& app, NormalsArguments& a) {
    CLI::App* c = app.add_subcommand(
        "normals", "Clean a point cloud and give every point an oriented unit normal.\n"
                   "Drops non-finite points, merges exact duplicates, estimates normals where the\n"
                   "input has none (PCA + MST orientation), removes small far-away clusters, and\n"
                   "writes the kept points at their input coordinates as binary PLY.");
    c->add_option("input", a.input,
                  "Point cloud: .ply (ascii/binary), .xyz/.txt, .obj, .pts, .pcd, .las/.laz")
        ->required(); // existence is checked by the reader: a missing file is bad input (exit 1)
    c->add_option("-o,--output", a.output,
                  "Output PLY (binary, with normals and the points' attributes)")
        ->required();
    add_no_attributes_flag(*c, a.attributes);
    add_preprocess_options(*c, a.options);
    add_threads_option(*c, a.threads);
    c->add_option("--report", a.report, "Write a JSON report (what was dropped, merged and why)");
    c->add_flag("-q,--quiet", a.quiet, "No progress bar or summary");
    return c;
}

namespace {

void print_summary(const NormalsArguments& a, const PreprocessReport& r, std::size_t written) {
    std::printf("hrsr normals: %zu input points, %zu written to %s\n", r.input_points, written,
                a.output.c_str());
    std::printf("  dropped: %zu non-finite, %zu without a normal, %zu in small components; "
                "merged: %zu duplicates\n",
                r.count(PointFate::NonFinite), r.count(PointFate::NoNormal),
                r.count(PointFate::SmallComponent), r.count(PointFate::Duplicate));
    if (r.normal_origin == NormalOrigin::Input)
        std::printf("  normals: from the input (%zu renormalised)\n", r.normals_renormalised);
    else
        std::printf(
            "  normals: estimated (PCA, %d neighbours), %zu flipped, %zu oriented piece(s)\n",
            r.pca_neighbours, r.orientation_flips, r.orientation_components);
    std::printf("  components: %zu kept, %zu dropped\n", r.components_kept, r.components_dropped);
    if (!a.report.empty()) std::printf("  report: %s\n", a.report.c_str());
}

} // namespace

void run_normals(const NormalsArguments& a) {
    check_outputs(a.input, a.output, a.report);
    validate(a.options);
    const PointSet input = io::read_point_sets({a.input}, {a.attributes});

    TerminalProgress bar(!a.quiet);
    Progress progress(bar.callback());
    Execution exec{a.threads, &progress};
    PreprocessReport report;
    const OrientedPoints cloud =
        naming_input(a.input, [&] { return estimate_normals(input, a.options, exec, report); });
    bar.finish();

    // Kept points at their input coordinates (never the normalised or smoothed ones).
    std::vector<Vec3> positions;
    positions.reserve(cloud.size());
    for (std::uint32_t i : cloud.input_index) positions.push_back(input.positions[i]);
    io::write_ply(a.output, positions, cloud.normals, {}, input.precision,
                  gather(input.attributes, cloud.input_index));

    print_warnings(input.warnings, report);
    if (!a.report.empty()) {
        nlohmann::json doc = {
            {"tool", "hrsr"},
            {"version", HRSR_VERSION},
            {"command", "normals"},
            {"input", a.input},
            {"output", a.output},
            {"options",
             {{"k", a.options.k},
              {"r", a.options.r},
              {"theta", a.options.theta_degrees},
              {"distance", a.options.distance == DistanceMode::Tangent ? "tangent" : "euclidean"},
              {"normals", a.options.normals == NormalSource::Input ? "input" : "reestimate"},
              {"k_normals", a.options.k_normals},
              {"min_component_size", a.options.min_component_size},
              {"threads", a.threads}}},
            {"preprocess", to_json(report)},
            {"peak_memory_bytes", peak_memory_bytes()}};
        write_json(a.report, doc);
    }
    if (!a.quiet) print_summary(a, report, positions.size());
}

} // namespace hrsr::app
