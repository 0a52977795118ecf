#include "mesh/fold_search.h"

#include "mesh/embedded_fans.h"
#include "mesh/welding.h"

namespace hrsr {

FoldSearch::FoldSearch(const std::vector<Vec3>& positions_, const std::vector<Triangle>& triangles,
                       const Execution& exec_)
    : positions(positions_), exec(without_progress(exec_)),
      representative(same_position_representatives(positions_, exec)),
      geometry(positions_, welded_triangles(triangles, representative, exec)),
      embedded_fan(embedded_fans(geometry, exec)), grid(geometry, exec_),
      pairs(grid.all_pairs(geometry, embedded_fan, exec_)) {}

} // namespace hrsr
