#include "reconstruct_command.h"

#include "command_line.h"
#include "errors.h"
#include "io/ply_writer.h"
#include "io/point_set_reader.h"
#include "process_stats.h"
#include "reconstruction.h"
#include "report_json.h"
#include "terminal_progress.h"

#include <cstdio>

namespace hrsr::app {

CLI::App* add_reconstruct_command(CLI::App& app, ReconstructArguments& a) {
    CLI::App* c = app.add_subcommand(
        "reconstruct", "Reconstruct a triangle mesh whose vertices are the input points.\n"
                       "Cleans and orients the cloud as `hrsr normals` does, then runs Rotation\n"
                       "System Reconstruction per connected piece, and writes a binary PLY mesh.");
    c->add_option("input", a.input, "Point cloud: .ply (ascii/binary), .xyz/.txt, .obj")
        ->required();
    c->add_option("-o,--output", a.output, "Output mesh (binary PLY with vertex normals)")
        ->required();
    c->add_option("--method", a.method, "Reconstruction method")
        ->transform(CLI::IsMember({"rsr"}, CLI::ignore_case).description(""))
        ->type_name("rsr")
        ->capture_default_str();
    add_preprocess_options(*c, a.options.preprocess);
    c->add_option("--n", a.options.max_handle_hops,
                  "Handles only join points more than n graph hops apart")
        ->capture_default_str();
    c->add_option("--handles", a.options.handles,
                  "Handles: -1 = as many as found, 0 = none (genus 0), g = at most g")
        ->capture_default_str();
    c->add_flag_function(
        "--keep-winding", [&a](std::int64_t) { a.options.orient_outward = false; },
        "Do not turn closed components outwards (face winding follows the point normals)");
    c->add_option("--threads", a.threads, "Worker threads; 0 = all cores")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    c->add_option("--report", a.report,
                  "Write a JSON report (counts, topology, dropped points, timings)");
    c->add_flag("-q,--quiet", a.quiet, "No progress bar or summary");
    return c;
}

namespace {

nlohmann::json genus_of_closed_components(const MeshStats& m) {
    nlohmann::json genus = nlohmann::json::array();
    for (const ComponentTopology& c : m.components)
        if (c.closed()) genus.push_back(c.genus());
    return genus;
}

nlohmann::json report_json(const ReconstructArguments& a, const ReconstructionReport& r) {
    const MeshStats& m = r.mesh;
    nlohmann::json timings = nlohmann::json::array();
    for (const auto& [phase, seconds] : r.timings)
        timings.push_back({{"phase", phase}, {"seconds", seconds}});
    const PreprocessOptions& p = a.options.preprocess;
    return {{"tool", "hrsr"},
            {"version", HRSR_VERSION},
            {"command", "reconstruct"},
            {"method", a.method},
            {"input", a.input},
            {"output", a.output},
            {"options",
             {{"k", p.k},
              {"r", p.r},
              {"theta", p.theta_degrees},
              {"distance", p.distance == DistanceMode::Tangent ? "tangent" : "euclidean"},
              {"normals", p.normals == NormalSource::Input ? "input" : "reestimate"},
              {"k_normals", p.k_normals},
              {"min_component_size", p.min_component_size},
              {"n", a.options.max_handle_hops},
              {"handles", a.options.handles},
              {"orient_outward", a.options.orient_outward},
              {"threads", a.threads}}},
            {"points",
             {{"input", r.preprocess.input_points},
              {"used", r.points_used},
              {"dropped",
               {{"non_finite", r.preprocess.count(PointFate::NonFinite)},
                {"no_normal", r.preprocess.count(PointFate::NoNormal)},
                {"small_component", r.preprocess.count(PointFate::SmallComponent)},
                {"not_in_any_triangle", r.not_in_triangle.size()}}},
              {"merged_duplicates", r.preprocess.count(PointFate::Duplicate)},
              {"not_in_any_triangle_indices", r.not_in_triangle},
              {"referenced", r.referenced_input_points},
              {"vertex_reference_ratio", r.vertex_reference_ratio}}},
            {"mesh",
             {{"vertices", m.vertices},
              {"faces", m.faces},
              {"edges", m.edges},
              {"boundary_edges", m.boundary_edges},
              {"boundary_loops", m.boundary_loops},
              {"non_manifold_edges", m.non_manifold_edges},
              {"non_manifold_vertices", m.non_manifold_vertices},
              {"inconsistently_oriented_edges", m.inconsistently_oriented_edges},
              {"components", m.components.size()},
              {"genus_of_closed_components", genus_of_closed_components(m)},
              {"vertex_copies_for_non_manifold_points", r.vertex_copies},
              {"components_turned_outwards", r.flipped_components}}},
            {"rsr",
             {{"candidate_edges", r.candidates},
              {"tree_edges", r.tree_edges},
              {"face_split_edges", r.face_split_edges},
              {"handle_edges", r.handle_edges},
              {"handles", r.handles},
              {"ear_edges", r.ear_edges}}},
            {"preprocess", to_json(r.preprocess)},
            {"timings", timings},
            {"peak_memory_bytes", peak_memory_bytes()}};
}

void print_summary(const ReconstructArguments& a, const ReconstructionReport& r) {
    const MeshStats& m = r.mesh;
    std::printf("hrsr reconstruct (%s): %zu input points -> %zu vertices, %zu triangles in %s\n",
                a.method.c_str(), r.preprocess.input_points, m.vertices, m.faces, a.output.c_str());
    std::printf("  r_v %.4f %% of input points are vertices; dropped: %zu non-finite, %zu in small "
                "components, %zu not in any triangle; merged: %zu duplicates\n",
                100.0 * r.vertex_reference_ratio, r.preprocess.count(PointFate::NonFinite),
                r.preprocess.count(PointFate::SmallComponent), r.not_in_triangle.size(),
                r.preprocess.count(PointFate::Duplicate));
    std::string genus;
    for (const ComponentTopology& c : m.components)
        if (c.closed()) genus += (genus.empty() ? "" : ", ") + std::to_string(c.genus());
    std::printf(
        "  %zu components (genus of closed ones: %s), %zu handles; boundary: %zu edges in %zu "
        "loops; non-manifold: %zu edges, %zu vertices\n",
        m.components.size(), genus.empty() ? "none" : genus.c_str(), r.handles, m.boundary_edges,
        m.boundary_loops, m.non_manifold_edges, m.non_manifold_vertices);
    double total = 0;
    for (const auto& t : r.timings) total += t.second;
    std::printf("  %.2f s, peak memory %.0f MB\n", total, double(peak_memory_bytes()) / 1e6);
    if (!a.report.empty()) std::printf("  report: %s\n", a.report.c_str());
}

} // namespace

void run_reconstruct(const ReconstructArguments& a) {
    check_output_is_not_input(a.input, a.output);
    if (!a.report.empty()) check_output_is_not_input(a.input, a.report);
    validate(a.options);
    const PointSet input = io::read_point_set(a.input);

    TerminalProgress bar(!a.quiet);
    Progress progress(bar.callback());
    const Execution exec{a.threads, &progress};
    ReconstructionReport report;
    Reconstruction mesh;
    try {
        mesh = reconstruct_rsr(input, a.options, exec, report);
    } catch (const InvalidInput& e) {
        throw InvalidInput(a.input + ": " + e.what());
    }
    bar.finish();

    std::vector<Vec3> positions;
    positions.reserve(mesh.vertex_input_index.size());
    for (std::uint32_t i : mesh.vertex_input_index) positions.push_back(input.positions[i]);
    io::write_ply(a.output, positions, mesh.vertex_normals, mesh.triangles, input.precision);

    for (const std::string& w : report.preprocess.warnings)
        std::fprintf(stderr, "hrsr: warning: %s\n", w.c_str());
    if (!a.report.empty()) write_json(a.report, report_json(a, report));
    if (!a.quiet) print_summary(a, report);
}

} // namespace hrsr::app
