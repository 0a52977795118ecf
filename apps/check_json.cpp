#include "check_json.h"

#include "mesh_summary.h"

#include <cstdio>

namespace hrsr::app {

namespace {

nlohmann::json to_json(const OneSidedDistance& d, double diagonal) {
    return {{"area_samples", d.area_samples},
            {"vertices", d.vertices},
            {"mean", d.mean},
            {"max", d.max},
            {"mean_of_diagonal", d.mean / diagonal},
            {"max_of_diagonal", d.max / diagonal}};
}

std::string format(const char* f, double a, double b = 0, double c = 0) {
    char line[256];
    std::snprintf(line, sizeof line, f, a, b, c);
    return line;
}

} // namespace

nlohmann::json to_json(const MeshCheck& c) {
    const MeshStats& m = c.topology;
    const MinAngleStats& a = c.faces.min_angle;
    nlohmann::json j = {
        {"vertices", m.vertices},
        {"faces", m.faces},
        {"file_vertices", c.file_vertices},
        {"unreferenced_vertices", m.unreferenced_vertices},
        {"coincident_vertices", c.coincident_vertices},
        {"edges", m.edges},
        {"boundary_edges", m.boundary_edges},
        {"boundary_loops", m.boundary_loops},
        {"non_manifold_edges", m.non_manifold_edges},
        {"non_manifold_vertices", m.non_manifold_vertices},
        {"components", m.components.size()},
        {"closed_components", genus_of_closed_components(m).size()},
        {"genus_of_closed_components", genus_of_closed_components(m)},
        {"largest_component", largest_component_json(m)},
        {"coherently_oriented", c.coherently_oriented()},
        {"inconsistently_oriented_edges", m.inconsistently_oriented_edges},
        {"degenerate_faces", c.faces.degenerate_faces},
        {"repeated_vertex_faces", c.faces.repeated_vertex_faces},
        {"duplicate_faces", c.faces.duplicate_faces},
        {"min_angle_degrees",
         {{"faces", a.faces},
          {"min", a.min},
          {"mean", a.mean},
          {"median", a.median},
          {"below_1", a.below_1_degree},
          {"below_10", a.below_10_degrees}}},
    };
    if (c.self_intersecting_pairs) {
        j["self_intersecting_pairs"] = *c.self_intersecting_pairs;
        j["first_intersecting_pairs"] = c.first_intersecting_pairs;
    } else {
        j["self_intersecting_pairs"] = nullptr;
    }
    j["faces_against_vertex_normals"] = c.faces_against_vertex_normals
                                            ? nlohmann::json(*c.faces_against_vertex_normals)
                                            : nlohmann::json(nullptr);
    if (c.vertex_reference) {
        const VertexReference& r = *c.vertex_reference;
        j["input"] = {{"points", r.input_points},
                      {"present_as_vertices", r.present},
                      {"tolerance", r.tolerance},
                      {"vertex_reference_ratio", r.ratio()}};
    }
    if (c.reference) {
        const ReferenceDistance& r = *c.reference;
        j["reference"] = {{"diagonal", r.diagonal},
                          {"chamfer", r.distance.chamfer()},
                          {"hausdorff", r.distance.hausdorff()},
                          {"chamfer_of_diagonal", r.chamfer()},
                          {"hausdorff_of_diagonal", r.hausdorff()},
                          {"mesh_to_reference", to_json(r.distance.a_to_b, r.diagonal)},
                          {"reference_to_mesh", to_json(r.distance.b_to_a, r.diagonal)}};
    }
    return j;
}

std::string summary(const std::string& path, const MeshCheck& c) {
    const MeshStats& m = c.topology;
    std::string s = "hrsr check: " + path + "\n";
    s += "  " + std::to_string(m.vertices) + " vertices, " + std::to_string(m.faces) +
         " triangles (" + std::to_string(m.unreferenced_vertices) + " unreferenced, " +
         std::to_string(c.coincident_vertices) + " coincident vertices)\n";
    s += "  " + std::to_string(m.components.size()) +
         " components (genus of closed ones: " + genus_of_closed_components_text(m) + "; " +
         largest_component_text(m) + "); boundary: " + std::to_string(m.boundary_edges) +
         " edges in " + std::to_string(m.boundary_loops) + " loops\n";
    s += "  non-manifold: " + std::to_string(m.non_manifold_edges) + " edges, " +
         std::to_string(m.non_manifold_vertices) + " vertices; orientation: " +
         (c.coherently_oriented()
              ? std::string("coherent")
              : std::to_string(m.inconsistently_oriented_edges) + " inconsistent edges") +
         "\n";
    s += "  faces: " + std::to_string(c.faces.degenerate_faces) + " degenerate, " +
         std::to_string(c.faces.duplicate_faces) + " duplicate, " +
         (c.self_intersecting_pairs ? std::to_string(*c.self_intersecting_pairs)
                                    : std::string("(not tested)")) +
         " self-intersecting pairs" +
         (c.faces_against_vertex_normals ? ", " + std::to_string(*c.faces_against_vertex_normals) +
                                               " against their vertices' normals"
                                         : std::string()) +
         "\n";
    const MinAngleStats& a = c.faces.min_angle;
    s += format("  min angle (deg): min %.3g, mean %.3g, median %.3g; ", a.min, a.mean, a.median) +
         std::to_string(a.below_1_degree) + " below 1, " + std::to_string(a.below_10_degrees) +
         " below 10\n";
    if (c.vertex_reference) {
        const VertexReference& r = *c.vertex_reference;
        s += format("  input: r_v %.4f %% (", 100.0 * r.ratio()) + std::to_string(r.present) +
             " of " + std::to_string(r.input_points) + " points are vertices)\n";
    }
    if (c.reference) {
        const ReferenceDistance& r = *c.reference;
        s += format("  reference: Chamfer %.3e, Hausdorff %.3e of the diagonal (%.6g)\n",
                    r.chamfer(), r.hausdorff(), r.diagonal);
    }
    return s;
}

} // namespace hrsr::app
