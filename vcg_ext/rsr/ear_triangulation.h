// Final ear triangulation of RsR (ALGORITHM.md §5.7, D-10, D-12): close the remaining polygonal
// faces by cutting ears, shortest first, as long as the new edge is not too long.
#pragma once

#include "options.h"
#include "rsr/candidate_graph.h"
#include "rsr/embedding.h"

#include <vector>

namespace hrsr::rsr {

struct EarStats {
    std::size_t ears = 0;              ///< edges inserted
    std::size_t closing_triangles = 0; ///< extra triangles closed on the far side of an ear edge
};

/// `lengths_cloud` gives the positions/normals for ear scores (those of the candidate graph);
/// `max_length` bounds them. Handle roots are explored first. Like GEL's, the ears have no
/// geometric test (embedding.geometry is not consulted; docs/STATUS.md). Where a crack stays
/// open because of a genus limit (D-13) the caller skips the ears, which would bridge it with
/// overlapping triangles.
EarStats triangulate_ears(Embedding& embedding, const ComponentCloud& lengths_cloud,
                          const std::vector<double>& max_length, DistanceMode mode,
                          const std::vector<std::uint32_t>& roots);

} // namespace hrsr::rsr
