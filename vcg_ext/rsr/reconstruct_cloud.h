// RsR over a whole prepared cloud: every component reconstructed (large ones using all threads,
// small ones side by side), results merged in component order (deterministic).
#pragma once

#include "mesh/triangle_mesh.h"
#include "options.h"
#include "parallel.h"
#include "preprocess/preprocess.h"
#include "rsr/observer.h"

#include <string>
#include <utility>
#include <vector>

namespace hrsr::rsr {

struct CloudMesh {
    std::vector<Triangle> triangles; ///< over the cloud's point indices
    std::size_t candidates = 0, tree_edges = 0, face_split_edges = 0, handle_edges = 0,
                ear_edges = 0;
    std::size_t handles = 0;
    std::vector<std::size_t> handle_hop_limits; ///< per component reconstructed, in order (D-27)
    std::vector<std::pair<std::string, double>> timings; ///< summed over components
};

/// `cloud.component` / `component_count` must be set (preprocess(), or the HRsR hand-off). With an
/// observer the components run one after the other.
CloudMesh reconstruct_cloud(const PreparedCloud& cloud, const RsrOptions& options,
                            const Execution& exec, Observer* observer = nullptr);

/// Adds per-phase times into a running total (same phase names are summed).
void add_timings(std::vector<std::pair<std::string, double>>& total,
                 const std::vector<std::pair<std::string, double>>& more);

} // namespace hrsr::rsr
