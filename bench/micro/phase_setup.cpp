#include "phase_setup.h"

#include "mesh/fans.h"
#include "rsr/ear_triangulation.h"
#include "rsr/face_split.h"
#include "rsr/handles.h"
#include "rsr/reconstruct_component.h"
#include "rsr/small_holes.h"
#include "rsr/spanning_tree.h"
#include "samplers.h"

#include <map>

namespace hrsr::bench {

const rsr::ComponentCloud& torus_cloud(std::size_t n) {
    static std::map<std::size_t, rsr::ComponentCloud> clouds;
    rsr::ComponentCloud& c = clouds[n];
    if (c.positions.empty()) {
        const PointSet s = testing::sample_torus(n);
        c.positions = c.smoothed = s.positions;
        c.normals = s.normals;
    }
    return c;
}

RsrState::RsrState(const rsr::ComponentCloud& c) : cloud(c), index(c.smoothed) {}

void RsrState::run(RsrPhase phase) {
    switch (phase) {
    case RsrPhase::CandidateGraph:
        graph = rsr::build_candidate_graph(cloud, index, options.preprocess, {});
        candidates = rsr::in_tile_order(
            rsr::face_split_candidates(graph, cloud, options.preprocess.distance, {}), {});
        break;
    case RsrPhase::SpanningTree:
        tree = rsr::candidate_spanning_tree(graph, cloud);
        normals = rsr::fix_leaf_normals(tree, cloud);
        rotation = std::make_unique<rsr::RotationSystem>(cloud.smoothed, normals);
        for (std::uint32_t v : tree.order)
            if (tree.parent[v] != SpanningForest::kRoot) rotation->insert_edge(tree.parent[v], v);
        faces = std::make_unique<rsr::Faces>(*rotation);
        faces->label_all();
        break;
    case RsrPhase::FaceSplit:
        geometry = std::make_unique<rsr::GeometryCheck>(index, cloud.smoothed, normals, *rotation);
        embedding = std::make_unique<rsr::Embedding>(
            rsr::Embedding{*rotation, *faces, *geometry, triangles, nullptr});
        rsr::split_faces(*embedding, candidates, {});
        break;
    case RsrPhase::Handles:
        rsr::insert_handles(*embedding, index, options,
                            {rsr::handle_hop_limit(options.min_handle_loop, cloud.smoothed.size(),
                                                   cloud.smoothed.size()),
                             nullptr},
                            roots);
        break;
    case RsrPhase::Ears:
        rsr::triangulate_ears(*embedding, cloud, graph.max_length, options.preprocess.distance,
                              roots);
        rsr::close_small_holes(*embedding);
        break;
    }
}

void RsrState::run_until(RsrPhase phase) {
    for (int p = 0; p < int(phase); ++p) run(RsrPhase(p));
}

ReexpansionStart reexpansion_start(const rsr::ComponentCloud& cloud,
                                   const CollapseOptions& options) {
    ReexpansionStart m;
    m.collapsed = collapse(cloud.positions, cloud.normals, options, {});
    rsr::ComponentCloud coarse;
    coarse.positions = coarse.smoothed = m.collapsed.positions;
    coarse.normals = m.collapsed.normals;
    rsr::ComponentStats stats;
    const std::vector<rsr::LocalTriangle> local =
        rsr::reconstruct_component(coarse, RsrOptions{}, {}, stats);
    // As reconstruct_hrsr's assembly: used survivors only, non-manifold vertices split.
    std::vector<std::uint32_t> vertex_of(coarse.positions.size(), ~0u), point_of_vertex;
    for (const rsr::LocalTriangle& t : local)
        for (std::uint32_t p : t) vertex_of[p] = 0;
    for (std::uint32_t p = 0; p < vertex_of.size(); ++p)
        if (vertex_of[p] == 0) {
            vertex_of[p] = std::uint32_t(point_of_vertex.size());
            point_of_vertex.push_back(p);
        }
    for (const rsr::LocalTriangle& t : local)
        m.mesh.triangles.push_back({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]});
    for (std::uint32_t v : split_non_manifold_vertices(point_of_vertex.size(), m.mesh.triangles)) {
        m.mesh.vertex_node.push_back(m.collapsed.survivors[CoarseIndex(point_of_vertex[v])]);
        m.mesh.positions.push_back(m.collapsed.positions[point_of_vertex[v]]);
    }
    return m;
}

} // namespace hrsr::bench
