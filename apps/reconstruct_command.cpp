#include "reconstruct_command.h"

#include "command_line.h"
#include "errors.h"
#include "io/mesh_writer.h"
#include "io/point_set_reader.h"
#include "mesh_summary.h"
#include "process_stats.h"
#include "reconstruction.h"
#include "report_json.h"
#include "terminal_progress.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace hrsr::app {

CLI::App* add_reconstruct_command(CLI::App& app, ReconstructArguments& a) {
    CLI::App* c = app.add_subcommand(
        "reconstruct",
        "Reconstruct a triangle mesh whose vertices are the input points.\n"
        "Cleans and orients the cloud as `hrsr normals` does; HRsR (default) collapses\n"
        "it to a fraction of its points, runs Rotation System Reconstruction on them and\n"
        "replays the collapses as vertex splits; RsR runs on the full cloud.");
    c->add_option("input", a.inputs,
                  "Point cloud(s): .ply (ascii/binary), .xyz/.txt, .obj, .pts, .pcd, .las/.laz;\n"
                  "several files are read as one cloud (tiles) and must have the same fields")
        ->required();
    c->add_option("-o,--output", a.output,
                  "Output mesh, format by extension: .ply (binary; every attribute), .obj, .off\n"
                  "(positions, normals in .obj, colour)")
        ->required();
    c->add_flag("--ascii", a.ascii, "Write the .ply output as ascii text");
    add_no_attributes_flag(*c, a.attributes);
    c->add_option("--method", a.method,
                  "hrsr (collapse, RsR, re-expansion) or rsr (RsR on all points)")
        ->transform(CLI::IsMember({"hrsr", "rsr"}, CLI::ignore_case).description(""))
        ->type_name("hrsr|rsr")
        ->capture_default_str();
    add_preprocess_options(*c, a.options.rsr.preprocess);
    c->add_option("--n", a.options.rsr.min_handle_loop,
                  "Shortest loop around a handle that is kept, in point spacings of the input;\n"
                  "shorter gaps are slits, not handles (both methods close them on otherwise\n"
                  "closed pieces)")
        ->capture_default_str();
    c->add_option("--handles", a.options.rsr.handles,
                  "Handles: -1 = as many as found, 0 = none (genus 0), g = at most g")
        ->capture_default_str();
    c->add_flag_function(
        "--keep-winding", [&a](std::int64_t) { a.options.rsr.orient_outward = false; },
        "Do not turn closed components outwards (face winding follows the point normals)");
    c->add_option("--collapse-ratio", a.options.collapse.collapse_ratio,
                  "HRsR: fraction p of the points RsR runs on (1 = no collapse)")
        ->capture_default_str();
    c->add_option("--collapse-k", a.options.collapse.collapse_k,
                  "HRsR: neighbours of the collapse graph")
        ->capture_default_str();
    c->add_option(
         "--l-min", a.l_min,
         "HRsR: do not re-expand collapses shorter than this: a length in input units, or\n"
         "a percentage of the bounding-box diagonal (e.g. 1%); 0 = full detail")
        ->default_str("0");
    c->add_option_function<std::string>(
         "--l-min-mode",
         [&a](const std::string& v) {
             a.options.reexpand.l_min_mode = v == "filter" ? LMinMode::Filter : LMinMode::Stop;
         },
         "HRsR: stop at the first shorter collapse (coarser level of detail) or skip each one")
        ->transform(CLI::IsMember({"stop", "filter"}, CLI::ignore_case).description(""))
        ->type_name("stop|filter")
        ->default_str("stop");
    c->add_option("--refinement-iterations", a.options.reexpand.refinement_iterations,
                  "HRsR: flip passes around each split vertex")
        ->capture_default_str();
    c->add_option("--fold-repair-rounds", a.options.rsr.fold_repair_rounds,
                  "Rounds of edge flips that undo folds (intersecting triangles); 0 = off")
        ->capture_default_str();
    add_threads_option(*c, a.threads);
    c->add_option("--report", a.report,
                  "Write a JSON report (counts, topology, dropped points, timings)");
    c->add_flag("-q,--quiet", a.quiet, "No progress bar or summary");
    return c;
}

namespace {

// D-26's flips, then D-32's removal.
nlohmann::json fold_repair_json(const ReconstructionReport& r) {
    return {{"intersecting_pairs_found", r.fold_repair.pairs_before},
            {"flips", r.fold_repair.flips},
            {"intersecting_pairs_after_flips", r.fold_repair.pairs_after},
            {"vertices_removed", r.fold_removal.vertices_removed},
            {"vertices_put_back", r.fold_removal.vertices_reinserted},
            {"holes_filled_again", r.fold_removal.holes_refilled},
            {"faces_cut", r.fold_removal.faces_cut},
            {"vertex_copies", r.fold_removal.vertex_copies},
            {"points_in_no_triangle_placed", r.fold_removal.points_placed},
            {"points_joined_border", r.fold_removal.points_joined_border},
            {"small_holes_closed", r.fold_removal.small_holes_closed},
            {"slits_closed", r.fold_removal.slits_closed},
            {"pieces_absorbed", r.fold_removal.pieces_absorbed},
            {"points_absorbed", r.fold_removal.points_absorbed},
            {"piece_holes_closed", r.fold_removal.piece_holes_closed},
            {"faces_against_normals", r.fold_removal.faces_against_normals},
            {"facing_flips", r.fold_removal.facing_flips},
            {"facing_refills", r.fold_removal.facing_refills},
            {"faces_against_normals_left", r.fold_removal.faces_against_normals_left},
            {"intersecting_pairs_left", r.fold_removal.pairs_after}};
}

// D-42, D-43: the tiles' work and how evenly it was spread (wall-clock, so it varies by run).
nlohmann::json tile_times_json(const TileTimes& t) {
    return {{"tiles", t.tiles},
            {"stretches", t.stretches},
            {"work_seconds", t.work},
            {"slowest_tile_seconds", t.slowest},
            {"balance", t.balance()}};
}

// The collapse and the re-expansion (§6–§8), and D-30 / D-34 on their mesh.
nlohmann::json hrsr_json(const ReconstructionReport& r) {
    const ReexpansionStats& e = r.reexpansion;
    return {{"coarse_points", r.coarse_points},
            {"coarse_small_holes_filled", r.coarse_small_holes_filled},
            {"records", e.records},
            {"records_replayed", e.replayed},
            {"records_failed",
             {{"no_split_pair", e.failed_no_pair}, {"node_not_in_mesh", e.skipped_no_vertex}}},
            {"unresolved_crossings", e.unresolved_crossings},
            {"crossing_flips", e.crossing_flips},
            {"boundary_triangles_removed", e.triangles_removed},
            {"unsampled_triangles_removed", r.unsampled_triangles_removed},
            {"border_slivers_peeled", e.border_slivers_peeled},
            {"border_splits", e.border_splits},
            {"border_notches_closed", r.border_notches_closed},
            {"improvement_flips", e.improvement_flips},
            {"merged_by_l_min", e.merged_by_l_min},
            {"stopped_at_l_min", e.stopped_at_l_min},
            {"tiles", e.tiles},
            {"records_replayed_in_tiles", e.replayed_in_tiles},
            {"records_deferred_at_tile_borders", e.deferred_at_tile_borders},
            {"records_deferred_replayed_in_tile_groups", e.late_replayed_in_groups},
            {"tile_times",
             {{"collapse", tile_times_json(r.collapse_tile_times)},
              {"re-expansion", tile_times_json(e.tile_times)}}}};
}

nlohmann::json report_json(const ReconstructArguments& a, const ReconstructionReport& r) {
    const MeshStats& m = r.mesh;
    nlohmann::json timings = nlohmann::json::array();
    for (const auto& [phase, seconds] : r.timings)
        timings.push_back({{"phase", phase}, {"seconds", seconds}});
    const PreprocessOptions& p = a.options.rsr.preprocess;
    return {{"tool", "hrsr"},
            {"version", HRSR_VERSION},
            {"command", "reconstruct"},
            {"method", a.method},
            {"input", inputs_json(a.inputs)},
            {"output", a.output},
            {"options",
             {{"k", p.k},
              {"r", p.r},
              {"theta", p.theta_degrees},
              {"distance", p.distance == DistanceMode::Tangent ? "tangent" : "euclidean"},
              {"normals", p.normals == NormalSource::Input ? "input" : "reestimate"},
              {"k_normals", p.k_normals},
              {"k_smoothing", p.k_smoothing},
              {"min_component_size", p.min_component_size},
              {"n", a.options.rsr.min_handle_loop},
              {"handles", a.options.rsr.handles},
              {"orient_outward", a.options.rsr.orient_outward},
              {"threads", a.threads},
              {"collapse_ratio", a.options.collapse.collapse_ratio},
              {"collapse_k", a.options.collapse.collapse_k},
              {"l_min", r.l_min},
              {"l_min_mode", a.options.reexpand.l_min_mode == LMinMode::Stop ? "stop" : "filter"},
              {"refinement_iterations", a.options.reexpand.refinement_iterations},
              {"fold_repair_rounds", a.options.rsr.fold_repair_rounds}}},
            {"points",
             {{"input", r.preprocess.input_points},
              {"used", r.points_used},
              {"dropped",
               {{"non_finite", r.preprocess.count(PointFate::NonFinite)},
                {"no_normal", r.preprocess.count(PointFate::NoNormal)},
                {"small_component", r.preprocess.count(PointFate::SmallComponent) +
                                        r.dropped_small_coarse_component.size()},
                {"not_in_any_triangle", r.not_in_triangle.size()},
                {"fold", r.dropped_fold.size()}}},
              {"merged_duplicates", r.preprocess.count(PointFate::Duplicate)},
              {"merged_into_other_vertices", r.merged_points},
              {"not_in_any_triangle_indices", r.not_in_triangle},
              {"fold_indices", r.dropped_fold},
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
              {"largest_component", largest_component_json(m)},
              {"vertex_copies_for_non_manifold_points", r.vertex_copies},
              {"components_turned_outwards", r.flipped_components}}},
            {"rsr",
             {{"candidate_edges", r.candidates},
              {"tree_edges", r.tree_edges},
              {"face_split_edges", r.face_split_edges},
              {"handle_edges", r.handle_edges},
              {"handles", r.handles},
              {"handle_hop_limits", r.handle_hop_limits},
              {"small_holes_filled", r.small_holes_filled},
              {"ear_edges", r.ear_edges}}},
            {"fold_repair", fold_repair_json(r)},
            {"flat_faces",
             {{"found", r.flat_faces.found},
              {"flipped", r.flat_faces.flipped},
              {"removed_from_border", r.flat_faces.removed},
              {"left", r.flat_faces.left}}},
            {"hrsr", hrsr_json(r)},
            {"preprocess", to_json(r.preprocess)},
            {"timings", timings},
            {"peak_memory_bytes", peak_memory_bytes()}};
}

void print_summary(const ReconstructArguments& a, const ReconstructionReport& r) {
    const MeshStats& m = r.mesh;
    std::printf("hrsr reconstruct (%s): %zu input points -> %zu vertices, %zu triangles in %s\n",
                a.method.c_str(), r.preprocess.input_points, m.vertices, m.faces, a.output.c_str());
    std::printf(
        "  r_v %.4f %% of input points are vertices; dropped: %zu non-finite, %zu in small "
        "components, %zu not in any triangle, %zu in folds; merged: %zu duplicates, %zu into "
        "other vertices\n",
        100.0 * r.vertex_reference_ratio, r.preprocess.count(PointFate::NonFinite),
        r.preprocess.count(PointFate::SmallComponent) + r.dropped_small_coarse_component.size(),
        r.not_in_triangle.size(), r.dropped_fold.size(), r.preprocess.count(PointFate::Duplicate),
        r.merged_points);
    if (a.options.method == Method::Hrsr) {
        const ReexpansionStats& e = r.reexpansion;
        std::printf("  HRsR: RsR on %zu points; %zu of %zu splits replayed (%zu failed, %zu merged "
                    "by l_min), "
                    "%zu with an unresolved crossing\n",
                    r.coarse_points, e.replayed, e.records, e.failed_no_pair, e.merged_by_l_min,
                    e.unresolved_crossings);
        if (r.preprocess.denoised)
            std::printf("  noise: %.2f point spacings, so HRsR worked on smoothed positions (the "
                        "mesh keeps the input's)\n",
                        r.preprocess.relative_noise);
    } else if (r.preprocess.denoised) {
        std::printf("  noise: %.2f point spacings, so RsR used the input normals averaged over "
                    "the smoothing neighbourhood\n",
                    r.preprocess.relative_noise);
    }
    const std::string genus = genus_of_closed_components_text(m);
    const std::string largest = largest_component_text(m);
    std::printf(
        "  %zu components (genus of closed ones: %s; %s), %zu handles; boundary: %zu edges in "
        "%zu loops; non-manifold: %zu edges, %zu vertices\n",
        m.components.size(), genus.c_str(), largest.c_str(), r.handles, m.boundary_edges,
        m.boundary_loops, m.non_manifold_edges, m.non_manifold_vertices);
    if (!r.handle_hop_limits.empty()) {
        const auto [lo, hi] =
            std::minmax_element(r.handle_hop_limits.begin(), r.handle_hop_limits.end());
        const std::string hops =
            *lo == *hi ? std::to_string(*lo) : std::to_string(*lo) + "-" + std::to_string(*hi);
        std::printf("  handles: loops of at least n = %g input point spacings, i.e. endpoints "
                    "more than %s graph hops apart on the cloud RsR saw\n",
                    a.options.rsr.min_handle_loop, hops.c_str());
    }
    if (a.options.rsr.fold_repair_rounds > 0) {
        const FoldRemovalStats& f = r.fold_removal;
        std::printf("  folds: %zu intersecting triangle pairs, %zu edge flips, %zu pairs left; "
                    "%zu vertices taken out (%zu holes filled again), %zu faces cut, %zu pairs "
                    "left; %zu points in no triangle placed into a face; %zu small holes "
                    "and %zu slits closed; %zu small pieces joined the surface they lie on (%zu "
                    "of them closing the hole they lay in)\n",
                    r.fold_repair.pairs_before, r.fold_repair.flips, r.fold_repair.pairs_after,
                    f.vertices_removed, f.holes_refilled, f.faces_cut, f.pairs_after,
                    f.points_placed, f.small_holes_closed, f.slits_closed, f.pieces_absorbed,
                    f.piece_holes_closed);
    }
    if (r.fold_removal.faces_against_normals > 0)
        std::printf("  faces winding against their normals: %zu, %zu edges flipped, %zu fans "
                    "refilled, %zu left\n",
                    r.fold_removal.faces_against_normals, r.fold_removal.facing_flips,
                    r.fold_removal.facing_refills, r.fold_removal.faces_against_normals_left);
    if (r.flat_faces.found > 0)
        std::printf("  faces without area (corners on one line): %zu, %zu edges flipped, %zu taken "
                    "off the border, %zu left\n",
                    r.flat_faces.found, r.flat_faces.flipped, r.flat_faces.removed,
                    r.flat_faces.left);
    double total = 0;
    for (const auto& t : r.timings) total += t.second;
    std::printf("  %.2f s, peak memory %.0f MB\n", total, double(peak_memory_bytes()) / 1e6);
    if (!a.report.empty()) std::printf("  report: %s\n", a.report.c_str());
}

} // namespace

// "0.5" → a length; "1%" → a percentage of the bounding-box diagonal.
void parse_l_min(const std::string& text, ReconstructionOptions& o) {
    if (text.empty()) return;
    const bool percent = text.back() == '%';
    const std::string number = percent ? text.substr(0, text.size() - 1) : text;
    std::size_t used = 0;
    double value = 0;
    try {
        value = std::stod(number, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != number.size())
        throw InvalidOption(OptionId::LMin,
                            "must be a length or a percentage such as 1% (got \"" + text + "\")");
    (percent ? o.l_min_percent : o.reexpand.l_min) = value;
}

void run_reconstruct(const ReconstructArguments& args) {
    ReconstructArguments a = args;
    a.options.method = a.method == "rsr" ? Method::Rsr : Method::Hrsr;
    parse_l_min(a.l_min, a.options);
    for (const std::string& in : a.inputs) check_outputs(in, a.output, a.report);
    io::mesh_format_of(a.output); // an unknown extension is refused before any work
    validate(a.options);
    const PointSet input = io::read_point_sets(a.inputs, {a.attributes});

    TerminalProgress bar(!a.quiet);
    Progress progress(bar.callback());
    const Execution exec{a.threads, &progress};
    ReconstructionReport report;
    const Reconstruction mesh = naming_input(
        inputs_label(a.inputs), [&] { return reconstruct(input, a.options, exec, report); });
    bar.finish();

    std::vector<Vec3> positions;
    positions.reserve(mesh.vertex_input_index.size());
    for (std::uint32_t i : mesh.vertex_input_index) positions.push_back(input.positions[i]);
    // Copies made at non-manifold vertices share their point's index, so they get its values
    // too; a merged duplicate is represented by its first occurrence (D-3).
    const std::vector<std::string> left_out =
        io::write_mesh(a.output, positions, mesh.vertex_normals, mesh.triangles, input.precision,
                       gather(input.attributes, mesh.vertex_input_index), {a.ascii});
    for (const std::string& w : left_out) std::fprintf(stderr, "hrsr: warning: %s\n", w.c_str());

    print_warnings(input.warnings, report.preprocess);
    if (!a.report.empty()) write_json(a.report, report_json(a, report));
    if (!a.quiet) print_summary(a, report);
}

} // namespace hrsr::app
