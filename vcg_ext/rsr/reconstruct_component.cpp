#include "rsr/reconstruct_component.h"

#include "rsr/candidate_graph.h"
#include "rsr/spanning_tree.h"

#include <chrono>

namespace hrsr::rsr {

namespace {

class Stopwatch {
public:
    explicit Stopwatch(ComponentStats& stats) : stats_(stats) {}
    void lap(const char* phase) {
        const auto now = std::chrono::steady_clock::now();
        stats_.timings.emplace_back(phase, std::chrono::duration<double>(now - start_).count());
        start_ = now;
    }

private:
    ComponentStats& stats_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void begin(const Execution& exec, const char* phase) {
    if (exec.progress) exec.progress->begin(phase);
}

} // namespace

std::vector<LocalTriangle> reconstruct_component(const ComponentCloud& cloud,
                                                 const RsrOptions& options, const Execution& exec,
                                                 ComponentStats& stats, Observer* observer) {
    std::vector<LocalTriangle> triangles;
    if (cloud.smoothed.size() < 3) return triangles;
    const PreprocessOptions& pre = options.preprocess;
    Stopwatch clock(stats);

    begin(exec, "candidate graph");
    const KnnIndex index(cloud.smoothed, exec);
    const CandidateGraph graph = build_candidate_graph(cloud, index, pre, exec);
    const std::vector<CandidateEdge> candidates =
        in_tile_order(face_split_candidates(graph, cloud, pre.distance, exec), exec); // D-50
    stats.candidates = candidates.size();
    clock.lap("candidate graph");

    begin(exec, "spanning tree");
    const SpanningForest tree = candidate_spanning_tree(graph, cloud);
    stats.graph_pieces = tree.trees;
    // Rotation angles and geometry checks see the leaf-fixed normals (§5.2).
    const std::vector<Vec3> normals =
        pre.distance == DistanceMode::Tangent ? fix_leaf_normals(tree, cloud) : cloud.normals;
    RotationSystem rotation(cloud.smoothed, normals);
    for (std::uint32_t v : tree.order)
        if (tree.parent[v] != SpanningForest::kRoot) rotation.insert_edge(tree.parent[v], v);
    stats.tree_edges = rotation.edge_count();
    Faces faces(rotation);
    faces.label_all();
    if (observer) observer->tree_built(rotation, faces);
    clock.lap("spanning tree");

    begin(exec, "face split");
    GeometryCheck geometry(index, cloud.smoothed, normals, rotation);
    Embedding embedding{rotation, faces, geometry, triangles, observer};
    stats.face_split = split_faces(embedding, candidates, exec);
    clock.lap("face split");

    // The handle search also runs with a genus limit (even 0) to learn whether the limit left a
    // crack open that needed a handle.
    std::vector<std::uint32_t> roots;
    begin(exec, "handles");
    const HandleLimits limits{
        handle_hop_limit(options.min_handle_loop, cloud.smoothed.size(),
                         std::max(cloud.represented_points, cloud.smoothed.size())),
        &cloud.handle_reach};
    stats.handles = insert_handles(embedding, index, options, limits, roots);
    clock.lap("handles");
    // D-13: the ear phase never merges faces (D-12), so it also runs for a limited genus, except
    // where the limit left such a crack open: ears then zip it partly and fold over the surface
    // near its ends (measured: 43 of 19,804 faces self-intersecting on a 10k double torus with
    // handles = 0; none without ears). That crack stays a hole, as in GEL for genus 0.
    if (!stats.handles.limited) {
        begin(exec, "ear triangulation");
        stats.ears = triangulate_ears(embedding, cloud, graph.max_length, pre.distance, roots);
    }
    stats.small_holes = close_small_holes(embedding);
    clock.lap("ear triangulation");
    if (observer) observer->finished(rotation, faces, triangles);
    return triangles;
}

} // namespace hrsr::rsr
