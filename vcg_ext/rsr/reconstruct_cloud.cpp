#include "rsr/reconstruct_cloud.h"

#include "rsr/reconstruct_component.h"

#include <algorithm>

namespace hrsr::rsr {

namespace {

// Components this large use every thread inside; smaller ones run side by side.
constexpr std::size_t kLargeComponent = 20000;

struct ComponentResult {
    std::vector<std::uint32_t> points; ///< prepared-cloud indices, increasing
    std::vector<LocalTriangle> triangles;
    ComponentStats stats;
};

std::vector<ComponentResult> split_by_component(const PreparedCloud& cloud) {
    std::vector<ComponentResult> parts(cloud.component_count);
    for (std::uint32_t i = 0; i < cloud.size(); ++i) parts[cloud.component[i]].points.push_back(i);
    return parts;
}

// Each point's index within its component (for the known kNN rows).
std::vector<std::uint32_t> local_indices(const PreparedCloud& cloud,
                                         const std::vector<ComponentResult>& parts) {
    std::vector<std::uint32_t> local(cloud.size(), 0);
    for (const ComponentResult& part : parts)
        for (std::uint32_t i = 0; i < part.points.size(); ++i) local[part.points[i]] = i;
    return local;
}

void reconstruct_part(const PreparedCloud& cloud, ComponentResult& part, const RsrOptions& options,
                      const std::vector<std::uint32_t>& local_index, const Execution& exec,
                      Observer* observer) {
    ComponentCloud local;
    if (cloud.neighbours.size() == cloud.size() && !part.points.empty())
        local.known_neighbours = {&cloud.neighbours, part.points.data(), cloud.component.data(),
                                  local_index.data(), cloud.component[part.points.front()]};
    for (std::uint32_t i : part.points) {
        local.positions.push_back(cloud.positions[i]);
        local.smoothed.push_back(cloud.smoothed[i]);
        local.normals.push_back(cloud.normals[i]);
        local.represented_points += cloud.weights.empty() ? 1 : cloud.weights[i];
        if (!cloud.handle_reach.empty()) local.handle_reach.push_back(cloud.handle_reach[i]);
    }
    part.triangles = reconstruct_component(local, options, exec, part.stats, observer);
}

void reconstruct_parts(const PreparedCloud& cloud, std::vector<ComponentResult>& parts,
                       const RsrOptions& options, const Execution& exec, Observer* observer) {
    const std::vector<std::uint32_t> local_index = cloud.neighbours.size() == cloud.size()
                                                       ? local_indices(cloud, parts)
                                                       : std::vector<std::uint32_t>();
    std::vector<std::size_t> small;
    for (std::size_t c = 0; c < parts.size(); ++c) {
        if (observer || parts[c].points.size() >= kLargeComponent)
            reconstruct_part(cloud, parts[c], options, local_index, exec, observer);
        else
            small.push_back(c);
    }
    if (exec.progress && !small.empty()) exec.progress->begin("small components");
    const Execution inner{1, nullptr};
    parallel_for(exec, small.size(), [&](std::size_t s) {
        reconstruct_part(cloud, parts[small[s]], options, local_index, inner, nullptr);
    });
}

} // namespace

void add_timings(std::vector<std::pair<std::string, double>>& total,
                 const std::vector<std::pair<std::string, double>>& more) {
    // Not a structured binding: C++17 lambdas cannot capture those (GCC allows it, clang not).
    for (const std::pair<std::string, double>& timing : more) {
        auto it = std::find_if(total.begin(), total.end(),
                               [&](const auto& e) { return e.first == timing.first; });
        if (it == total.end())
            total.push_back(timing);
        else
            it->second += timing.second;
    }
}

CloudMesh reconstruct_cloud(const PreparedCloud& cloud, const RsrOptions& options,
                            const Execution& exec, Observer* observer) {
    std::vector<ComponentResult> parts = split_by_component(cloud);
    reconstruct_parts(cloud, parts, options, exec, observer);
    CloudMesh mesh;
    for (const ComponentResult& part : parts) {
        for (const LocalTriangle& t : part.triangles)
            mesh.triangles.push_back({part.points[t[0]], part.points[t[1]], part.points[t[2]]});
        const ComponentStats& s = part.stats;
        mesh.candidates += s.candidates;
        mesh.tree_edges += s.tree_edges;
        mesh.face_split_edges += s.face_split.inserted;
        mesh.handle_edges += s.handles.edges_inserted;
        mesh.handles += s.handles.handles;
        if (s.handles.hop_limit > 0) mesh.handle_hop_limits.push_back(s.handles.hop_limit);
        mesh.ear_edges += s.ears.ears;
        add_timings(mesh.timings, s.timings);
    }
    return mesh;
}

} // namespace hrsr::rsr
