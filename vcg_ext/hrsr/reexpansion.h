// HRsR re-expansion (ALGORITHM.md §8): the collapses replayed backwards as vertex splits.
#pragma once

#include "hrsr/collapse.h"
#include "index_types.h"
#include "mesh/split_mesh.h"
#include "mesh/triangle_mesh.h"
#include "options.h"
#include "parallel.h"
#include "reconstruction_stats.h"

#include <vector>

namespace hrsr {

struct ReexpandedMesh {
    IndexVector<VertexIndex, PointIndex> vertex_node; ///< the node (point) it stands for
    std::vector<Triangle> triangles;
    /// The border edges a → b as the triangles holding them run (D-34 closes notches on them).
    std::vector<std::array<std::uint32_t, 2>> border;
    /// Per node: the node whose vertex represents it (itself if it has its own vertex; kNoNode if
    /// dropped).
    IndexVector<PointIndex, PointIndex> alias;
    static constexpr PointIndex kNoNode{0xffffffffu};
};

/// Watches re-expansion (tests check invariants after every split without debug flags).
class ReexpansionObserver {
public:
    virtual ~ReexpansionObserver() = default;
    /// c was made room for (crossings resolved: `unresolved` left) and moved to x_a; the split
    /// created c2 at x_b. `removed` boundary triangles were removed for it (each changes
    /// (V, E, F) by (0, −1, −1)); the local flips have run (D-43: or wait, when they reached
    /// another tile).
    virtual void split_done(const SplitMesh& /*mesh*/, std::uint32_t /*c*/, std::uint32_t /*c2*/,
                            const Vec3& /*x_a*/, const Vec3& /*x_b*/, std::size_t /*removed*/,
                            bool /*unresolved*/) {}
    /// The mesh as the re-expansion hands it on (D-46: in node order).
    virtual void finished(const ReexpandedMesh& /*mesh*/) {}
};

/// The mesh RsR built on the coarse cloud, where the re-expansion starts.
struct CoarseMesh {
    /// Per vertex: its node (copies of a non-manifold node share it).
    IndexVector<VertexIndex, PointIndex> vertex_node;
    std::vector<Vec3> positions; ///< per vertex
    std::vector<Triangle> triangles;
};

/// What the re-expansion replays, and on what.
struct ReexpansionInput {
    /// Original positions and normals of all nodes (the algorithm's coordinates).
    const std::vector<Vec3>& points;
    const std::vector<Vec3>& normals;
    const CoarseMesh& coarse;
    /// Taken over (move them in): they are freed before the mesh is exported, which is the
    /// phase's memory peak.
    std::vector<CollapseRecord> records;
    const ReexpandOptions& options;
    double l_min = 0; ///< in the points' coordinates
};

/// Replays the records backwards on the coarse mesh.
ReexpandedMesh replay_collapses(ReexpansionInput input, const Execution& exec,
                                ReexpansionStats& stats, ReexpansionObserver* observer = nullptr);

} // namespace hrsr
