// HRsR re-expansion (ALGORITHM.md §8): the collapses replayed backwards as vertex splits.
#pragma once

#include "hrsr/collapse.h"
#include "mesh/split_mesh.h"
#include "mesh/triangle_mesh.h"
#include "options.h"
#include "parallel.h"
#include "reconstruction_stats.h"

#include <vector>

namespace hrsr {

struct ReexpandedMesh {
    std::vector<std::uint32_t> vertex_node; ///< per vertex: the node (point) it stands for
    std::vector<Triangle> triangles;
    std::vector<std::uint32_t> alias; ///< per node: the node whose vertex represents it
                                      ///< (itself if it has its own vertex; kNoNode if dropped)
    static constexpr std::uint32_t kNoNode = 0xffffffffu;
};

/// Watches re-expansion (tests check invariants after every split without debug flags).
class ReexpansionObserver {
public:
    virtual ~ReexpansionObserver() = default;
    /// c was made room for (crossings resolved: `unresolved` left) and moved to x_a; the split
    /// created c2 at x_b. `removed` boundary triangles were removed for it (each changes
    /// (V, E, F) by (0, −1, −1)); the local flips have run.
    virtual void split_done(const SplitMesh& /*mesh*/, std::uint32_t /*c*/, std::uint32_t /*c2*/,
                            const Vec3& /*x_a*/, const Vec3& /*x_b*/, std::size_t /*removed*/,
                            bool /*unresolved*/) {}
};

/// Replays `records` backwards on the coarse mesh. `coarse_vertex_node[v]` is the node of each
/// coarse mesh vertex (copies of a non-manifold node share it). `points` and `normals` are the
/// original positions and normals of all nodes (the algorithm's coordinates). `l_min` is in
/// those coordinates. `records` is taken by value (pass it with std::move): it is freed before
/// the mesh is exported, which is the phase's memory peak.
ReexpandedMesh replay_collapses(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                const std::vector<std::uint32_t>& coarse_vertex_node,
                                const std::vector<Vec3>& coarse_positions,
                                const std::vector<Triangle>& coarse_triangles,
                                std::vector<CollapseRecord> records, const ReexpandOptions& options,
                                double l_min, const Execution& exec, ReexpansionStats& stats,
                                ReexpansionObserver* observer = nullptr);

} // namespace hrsr
