#include "mesh/fold_search.h"

#include "mesh/welding.h"

namespace hrsr {

FoldSearch::FoldSearch(const std::vector<Vec3>& positions_, const std::vector<Triangle>& triangles,
                       const Execution& exec)
    : positions(positions_), representative(same_position_representatives(positions_)),
      geometry(positions_, welded_triangles(triangles, representative)), grid(geometry, exec),
      pairs(grid.all_pairs(geometry, exec)) {}

} // namespace hrsr
