// The library's entry point: point set in, triangle mesh and report out. Public API (README
// "Public API"): this header and the ones it includes use no internal type; progress and
// cancellation are watched through Execution's Progress (progress.h). The tests' observers of
// every mutation are internal (reconstruction_observed.h).
#pragma once

#include "mesh/mesh_stats.h"
#include "mesh/triangle_mesh.h"
#include "options.h"
#include "parallel.h"
#include "point_set.h"
#include "preprocess/report.h"
#include "reconstruction_stats.h"

#include <string>
#include <utility>
#include <vector>

namespace hrsr {

/// A reconstructed mesh over input points.
struct Reconstruction {
    std::vector<std::uint32_t> vertex_input_index; ///< output vertex -> input point; copies made
                                                   ///< for non-manifold vertices share it (§5.8)
    std::vector<Vec3> vertex_normals;              ///< unit; outward on closed components (D-6)
    std::vector<Triangle> triangles;               ///< counter-clockwise seen from the normals
};

struct ReconstructionReport {
    PreprocessReport preprocess;
    std::size_t points_used = 0; ///< points handed to RsR (after pre-processing)
    std::vector<std::uint32_t>
        not_in_triangle; ///< input indices of used points left out of every triangle
    std::size_t referenced_input_points =
        0;                              ///< output vertices' points + duplicates merged into them
    double vertex_reference_ratio = 0;  ///< r_v = referenced_input_points / input points
    std::size_t vertex_copies = 0;      ///< output vertices repeating a point (§5.8 fans)
    std::size_t flipped_components = 0; ///< closed components turned outwards (D-6)

    std::size_t candidates = 0, tree_edges = 0, face_split_edges = 0, handle_edges = 0,
                ear_edges = 0;
    std::size_t handles = 0; ///< handles inserted (merges of two faces), all components
    /// Graph hops a handle's endpoints had to be apart, per RsR component in component order:
    /// n input spacings on the cloud RsR saw (D-27).
    std::vector<std::size_t> handle_hop_limits;
    FoldRepairStats fold_repair;             ///< D-26, on the output mesh
    FoldRemovalStats fold_removal;           ///< D-32, after D-26
    FlatFaceStats flat_faces;                ///< D-36, after D-32
    std::vector<std::uint32_t> dropped_fold; ///< input indices of points D-32 took out
    std::size_t small_holes_filled = 0;      ///< D-28: boundary loops of at most 5 edges closed
    /// D-30 (HRsR): triangles removed for an edge no RsR candidate could be (over a hole).
    std::size_t unsampled_triangles_removed = 0;
    std::size_t border_notches_closed = 0; ///< D-34 (HRsR): ears over notches of the border
    MeshStats mesh;
    std::vector<std::pair<std::string, double>>
        timings; ///< (phase, seconds), summed over components

    // HRsR only.
    std::size_t coarse_points = 0; ///< points left after collapsing (given to RsR)
    /// D-39: loops of at most 5 edges closed on coarse pieces that have no longer border.
    std::size_t coarse_small_holes_filled = 0;
    std::size_t merged_points =
        0; ///< input points represented by another point's vertex (l_min, failed splits)
    std::vector<std::uint32_t> dropped_small_coarse_component; ///< input indices
    double l_min = 0;                                          ///< in input units
    TileTimes collapse_tile_times;                             ///< D-42
    ReexpansionStats reexpansion;
};

/// Rotation System Reconstruction of the whole cloud (§2.1): pre-processing, then RsR per
/// component, then assembly. Throws InvalidOption, InvalidInput or Cancelled.
Reconstruction reconstruct_rsr(const PointSet& input, const RsrOptions& options,
                               const Execution& exec, ReconstructionReport& report);

/// Hierarchical RsR (§2.2): pre-processing, collapse to a fraction p of the points, RsR on them,
/// re-expansion by vertex splits (down to l_min).
Reconstruction reconstruct_hrsr(const PointSet& input, const ReconstructionOptions& options,
                                const Execution& exec, ReconstructionReport& report);

/// Validates every option (InvalidOption names the first bad one, whichever method uses it), then
/// dispatches on options.method.
Reconstruction reconstruct(const PointSet& input, const ReconstructionOptions& options,
                           const Execution& exec, ReconstructionReport& report);

} // namespace hrsr
