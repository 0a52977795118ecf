#include "reconstruction.h"

#include "mesh/fans.h"
#include "preprocess/preprocess.h"
#include "rsr/reconstruct_component.h"

#include <algorithm>
#include <chrono>

namespace hrsr {

namespace {

// Components this large use every thread inside; smaller ones run side by side.
constexpr std::size_t kLargeComponent = 20000;

struct ComponentResult {
    std::vector<std::uint32_t> points; ///< prepared-cloud indices, increasing
    std::vector<rsr::LocalTriangle> triangles;
    rsr::ComponentStats stats;
};

std::vector<ComponentResult> split_by_component(const PreparedCloud& cloud) {
    std::vector<ComponentResult> parts(cloud.component_count);
    for (std::uint32_t i = 0; i < cloud.size(); ++i) parts[cloud.component[i]].points.push_back(i);
    return parts;
}

void reconstruct_part(const PreparedCloud& cloud, ComponentResult& part, const RsrOptions& options,
                      const Execution& exec, rsr::Observer* observer) {
    rsr::ComponentCloud local;
    for (std::uint32_t i : part.points) {
        local.positions.push_back(cloud.positions[i]);
        local.smoothed.push_back(cloud.smoothed[i]);
        local.normals.push_back(cloud.normals[i]);
    }
    part.triangles = rsr::reconstruct_component(local, options, exec, part.stats, observer);
}

void reconstruct_parts(const PreparedCloud& cloud, std::vector<ComponentResult>& parts,
                       const RsrOptions& options, const Execution& exec, rsr::Observer* observer) {
    std::vector<std::size_t> small;
    for (std::size_t c = 0; c < parts.size(); ++c) {
        if (observer || parts[c].points.size() >= kLargeComponent)
            reconstruct_part(cloud, parts[c], options, exec, observer);
        else
            small.push_back(c);
    }
    if (exec.progress && !small.empty()) exec.progress->begin("small components");
    const Execution inner{1, nullptr};
    parallel_for(exec, small.size(), [&](std::size_t s) {
        reconstruct_part(cloud, parts[small[s]], options, inner, nullptr);
    });
}

void add_timings(std::vector<std::pair<std::string, double>>& total,
                 const std::vector<std::pair<std::string, double>>& more) {
    for (const auto& [phase, seconds] : more) {
        auto it = std::find_if(total.begin(), total.end(),
                               [&](const auto& e) { return e.first == phase; });
        if (it == total.end())
            total.emplace_back(phase, seconds);
        else
            it->second += seconds;
    }
}

// D-6: closed components enclosing a negative volume are turned inside out.
void orient_outward(const PreparedCloud& cloud, Reconstruction& mesh,
                    const std::vector<std::uint32_t>& source, ReconstructionReport& report) {
    std::size_t count = 0;
    const std::vector<std::uint32_t> component =
        triangle_components(source.size(), mesh.triangles, count);
    std::vector<Vec3> positions(source.size());
    for (std::size_t v = 0; v < source.size(); ++v) positions[v] = cloud.positions[source[v]];
    const MeshStats stats = measure_mesh(source.size(), mesh.triangles);
    for (std::uint32_t c = 0; c < count; ++c) {
        if (!stats.components[c].closed() ||
            signed_volume(positions, mesh.triangles, component, c) >= 0)
            continue;
        ++report.flipped_components;
        std::vector<std::uint8_t> flip_vertex(source.size(), 0);
        for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
            if (component[t] != c) continue;
            std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
            for (std::uint32_t v : mesh.triangles[t]) flip_vertex[v] = 1;
        }
        for (std::size_t v = 0; v < source.size(); ++v)
            if (flip_vertex[v]) mesh.vertex_normals[v] = -mesh.vertex_normals[v];
    }
}

// Output vertices are the used points in input order, then copies for non-manifold fans.
Reconstruction assemble(const PreparedCloud& cloud, const std::vector<ComponentResult>& parts,
                        const RsrOptions& options, ReconstructionReport& report) {
    std::vector<Triangle> triangles;
    for (const ComponentResult& part : parts)
        for (const rsr::LocalTriangle& t : part.triangles)
            triangles.push_back({part.points[t[0]], part.points[t[1]], part.points[t[2]]});
    std::vector<std::uint32_t> vertex_of(cloud.size(), ~0u), point_of_vertex;
    for (const Triangle& t : triangles)
        for (std::uint32_t p : t) vertex_of[p] = 0;
    for (std::uint32_t p = 0; p < cloud.size(); ++p) {
        if (vertex_of[p] == ~0u) {
            report.not_in_triangle.push_back(cloud.input_index[p]);
            continue;
        }
        vertex_of[p] = std::uint32_t(point_of_vertex.size());
        point_of_vertex.push_back(p);
    }
    for (Triangle& t : triangles)
        for (std::uint32_t& p : t) p = vertex_of[p];
    const std::vector<std::uint32_t> copies_of =
        split_non_manifold_vertices(point_of_vertex.size(), triangles);
    report.vertex_copies = copies_of.size() - point_of_vertex.size();

    Reconstruction mesh;
    mesh.triangles = std::move(triangles);
    std::vector<std::uint32_t> source(copies_of.size());
    for (std::size_t v = 0; v < copies_of.size(); ++v) {
        source[v] = point_of_vertex[copies_of[v]];
        mesh.vertex_input_index.push_back(cloud.input_index[source[v]]);
        mesh.vertex_normals.push_back(cloud.normals[source[v]]);
    }
    if (options.orient_outward) orient_outward(cloud, mesh, source, report);
    return mesh;
}

void account(const PointSet& input, const Reconstruction& mesh, ReconstructionReport& report) {
    const PreprocessReport& pre = report.preprocess;
    std::vector<std::uint8_t> referenced(input.size(), 0);
    for (std::uint32_t i : mesh.vertex_input_index) referenced[i] = 1;
    for (std::size_t i = 0; i < input.size(); ++i)
        if (pre.fate[i] == PointFate::Duplicate && referenced[pre.duplicate_of[i]])
            referenced[i] = 1;
    report.referenced_input_points =
        std::size_t(std::count(referenced.begin(), referenced.end(), 1));
    report.vertex_reference_ratio =
        input.size() ? double(report.referenced_input_points) / double(input.size()) : 0;
    report.mesh = measure_mesh(mesh.vertex_input_index.size(), mesh.triangles);
}

} // namespace

Reconstruction reconstruct_rsr(const PointSet& input, const RsrOptions& options,
                               const Execution& exec, ReconstructionReport& report,
                               rsr::Observer* observer) {
    validate(options);
    const PreparedCloud cloud = preprocess(input, options.preprocess, exec, report.preprocess);
    report.points_used = cloud.size();
    report.timings = report.preprocess.timings;

    std::vector<ComponentResult> parts = split_by_component(cloud);
    reconstruct_parts(cloud, parts, options, exec, observer);
    for (const ComponentResult& part : parts) {
        const rsr::ComponentStats& s = part.stats;
        report.candidates += s.candidates;
        report.tree_edges += s.tree_edges;
        report.face_split_edges += s.face_split.inserted;
        report.handle_edges += s.handles.edges_inserted;
        report.handles += s.handles.handles;
        report.ear_edges += s.ears.ears;
        add_timings(report.timings, s.timings);
    }
    const auto start = std::chrono::steady_clock::now();
    Reconstruction mesh = assemble(cloud, parts, options, report);
    account(input, mesh, report);
    report.timings.emplace_back(
        "assembly",
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return mesh;
}

} // namespace hrsr
