// The intersecting triangle pairs of a finished mesh and the structures that found them, built
// once and handed from D-26's flips (fold_repair.h) to D-32's removal (fold_removal.h): both work
// on the coordinates as written, so the second needs no search of its own.
#pragma once

#include "mesh/triangle_grid.h"
#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"

#include <cstdint>
#include <vector>

namespace hrsr {

struct FoldSearch {
    /// Finds every intersecting pair of `triangles` over `positions` (the rule of
    /// self_intersections.h, exact; vertices at one position count as one). `positions` must
    /// outlive the search. At least two triangles.
    FoldSearch(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
               const Execution& exec);

    const std::vector<Vec3>& positions;
    const Execution exec; ///< the threads the repair's whole-mesh passes use (no progress)
    const std::vector<std::uint32_t> representative; ///< per vertex: the first at its position
    TriangleGeometry geometry; ///< the triangles over representatives, kept up to date
    /// Per representative: its faces met only where they join when the search ran
    /// (embedded_fans.h); found before the grid, whose entries need more memory.
    const std::vector<std::uint8_t> embedded_fan;
    TriangleGrid grid;               ///< changed and added faces are filed again
    std::vector<TrianglePair> pairs; ///< sorted; kept exact by whoever changes `geometry`
};

} // namespace hrsr
