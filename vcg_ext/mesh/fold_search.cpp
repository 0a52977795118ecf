#include "mesh/fold_search.h"

#include "mesh/welding.h"

namespace hrsr {

FoldSearch::FoldSearch(const std::vector<Vec3>& positions_, const std::vector<Triangle>& triangles,
                       const Execution& exec_)
    : positions(positions_), exec(without_progress(exec_)),
      representative(same_position_representatives(positions_, exec)),
      geometry(positions_, welded_triangles(triangles, representative, exec)),
      grid(geometry, exec_), pairs(grid.all_pairs(geometry, exec_)) {}

} // namespace hrsr
