#include "check_command.h"

#include "check_json.h"
#include "command_line.h"
#include "errors.h"
#include "io/mesh_reader.h"
#include "io/point_set_reader.h"
#include "report_json.h"

#include <cstdio>
#include <optional>

namespace hrsr::app {

CLI::App* add_check_command(CLI::App& app, CheckArguments& a) {
    CLI::App* c = app.add_subcommand(
        "check", "Measure a triangle mesh: size, boundary, non-manifold edges and vertices,\n"
                 "components and genus, orientation, degenerate/duplicate/self-intersecting\n"
                 "faces, minimum angles, faces winding against their vertices' normals (when\n"
                 "the mesh has normals); with --input the share of input points that are\n"
                 "vertices (r_v), with --reference Chamfer and Hausdorff distances.");
    c->add_option("mesh", a.mesh, "Triangle mesh (.ply, ascii or binary)")->required();
    c->add_option("--input", a.input,
                  "Point cloud the mesh was made from (.ply/.xyz/.txt/.obj): gives r_v");
    c->add_option("--reference", a.reference,
                  "Reference mesh (.ply): symmetric Chamfer and Hausdorff distances relative to "
                  "its bounding-box diagonal");
    c->add_flag("--json", a.json, "Print the results as JSON instead of the summary");
    c->add_option("--report", a.report, "Also write the JSON results to this file");
    c->add_option("--vertex-tolerance", a.options.vertex_tolerance,
                  "r_v: distance to a vertex, as a fraction of the input's diagonal")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    c->add_option("--samples", a.options.distance.area_samples,
                  "Distances: random points per surface (uniform by area)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    c->add_flag_function(
        "--no-self-intersections", [&a](std::int64_t) { a.options.self_intersections = false; },
        "Skip the triangle-pair intersection test (the slowest measure)");
    add_threads_option(*c, a.threads);
    return c;
}

void run_check(const CheckArguments& a) {
    if (!a.report.empty()) {
        check_output_is_not_input(a.mesh, a.report);
        if (!a.input.empty()) check_output_is_not_input(a.input, a.report);
        if (!a.reference.empty()) check_output_is_not_input(a.reference, a.report);
    }
    const io::MeshFile mesh = io::read_mesh(a.mesh);
    std::optional<PointSet> input;
    if (!a.input.empty()) input = io::read_point_set(a.input, {false}); // positions only: r_v
    std::optional<io::MeshFile> reference;
    if (!a.reference.empty()) reference = io::read_mesh(a.reference);

    const MeshView view{mesh.points.positions, mesh.triangles, &mesh.points.normals};
    std::optional<MeshView> reference_view;
    if (reference)
        reference_view.emplace(MeshView{reference->points.positions, reference->triangles});
    const Execution exec{a.threads, nullptr};
    const MeshCheck check = naming_input(a.mesh, [&] {
        return check_mesh(view, input ? &*input : nullptr,
                          reference_view ? &*reference_view : nullptr, a.options, exec);
    });
    nlohmann::json document = to_json(check);
    document["mesh"] = a.mesh;
    document["polygons_triangulated"] = mesh.polygons_triangulated;
    if (!a.input.empty()) document["input"]["file"] = a.input;
    if (!a.reference.empty()) document["reference"]["file"] = a.reference;
    if (!a.report.empty()) write_json(a.report, document);
    if (a.json)
        std::printf("%s\n", document.dump(2).c_str());
    else
        std::fputs(summary(a.mesh, check).c_str(), stdout);
}

} // namespace hrsr::app
