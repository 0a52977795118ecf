// The state each benchmarked phase starts from: the earlier phases run exactly as
// rsr::reconstruct_component() and reconstruct_hrsr() chain them (those functions are not
// split into callable steps, so the chain is repeated here; keep it in step with them).
#pragma once

#include "graph/spanning_forest.h"
#include "hrsr/collapse.h"
#include "hrsr/reexpansion.h"
#include "knn.h"
#include "mesh/triangle_mesh.h"
#include "options.h"
#include "rsr/candidate_graph.h"
#include "rsr/component.h"
#include "rsr/embedding.h"
#include "rsr/faces.h"
#include "rsr/geometry_check.h"
#include "rsr/rotation_system.h"

#include <memory>
#include <vector>

namespace hrsr::bench {

/// A torus cloud of n points with exact normals, used as the smoothed positions too (no
/// pre-processing: the benchmarks time the reconstruction phases).
const rsr::ComponentCloud& torus_cloud(std::size_t n);

/// The RsR phases in the order reconstruct_component() runs them.
enum class RsrPhase { CandidateGraph, SpanningTree, FaceSplit, Handles, Ears };

/// The state of RsR on one component as its phases build it up.
struct RsrState {
    const rsr::ComponentCloud& cloud;
    RsrOptions options;
    KnnIndex index;
    rsr::CandidateGraph graph;
    std::vector<rsr::CandidateEdge> candidates;
    SpanningForest tree;
    std::vector<Vec3> normals; ///< leaf-fixed
    std::unique_ptr<rsr::RotationSystem> rotation;
    std::unique_ptr<rsr::Faces> faces;
    std::unique_ptr<rsr::GeometryCheck> geometry;
    std::vector<rsr::LocalTriangle> triangles;
    std::unique_ptr<rsr::Embedding> embedding; ///< of the four above, from the face split on
    std::vector<std::uint32_t> roots;

    explicit RsrState(const rsr::ComponentCloud& c);
    /// Runs one phase; the phases before it must have run. CandidateGraph: candidate graph and
    /// face-split candidates; SpanningTree: tree, rotation system, face labels; FaceSplit;
    /// Handles; Ears: ears and small holes.
    void run(RsrPhase phase);
    /// Runs every phase before `phase`.
    void run_until(RsrPhase phase);
};

/// What re-expansion starts from: the collapse records and the RsR mesh of the survivors.
struct ReexpansionStart {
    CollapsedCloud collapsed;
    CoarseMesh mesh;
};

ReexpansionStart reexpansion_start(const rsr::ComponentCloud& cloud,
                                   const CollapseOptions& options);

} // namespace hrsr::bench
