// RsR on one connected component (ALGORITHM.md §5, Appendix A.1).
#pragma once

#include "options.h"
#include "parallel.h"
#include "rsr/ear_triangulation.h"
#include "rsr/face_split.h"
#include "rsr/handles.h"
#include "rsr/small_holes.h"

#include <vector>

namespace hrsr::rsr {

struct ComponentStats {
    std::size_t candidates = 0; ///< face-split candidate edges
    std::size_t tree_edges = 0;
    std::size_t graph_pieces = 0; ///< connected pieces of the candidate graph (1 unless the k graph
                                  ///< is sparser than §4.6's)
    FaceSplitStats face_split;
    HandleStats handles;
    EarStats ears;
    SmallHoleStats small_holes;
    std::vector<std::pair<std::string, double>> timings; ///< (phase, seconds)
};

/// Triangles over the component's local vertex indices, counter-clockwise seen from the normals.
std::vector<LocalTriangle> reconstruct_component(const ComponentCloud& cloud,
                                                 const RsrOptions& options, const Execution& exec,
                                                 ComponentStats& stats,
                                                 Observer* observer = nullptr);

} // namespace hrsr::rsr
