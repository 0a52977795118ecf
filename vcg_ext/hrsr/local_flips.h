// Local improvement after a vertex split (ALGORITHM.md §8.6).
#pragma once

#include "mesh/split_mesh.h"
#include "options.h"

namespace hrsr::reexpand {

/// Flip passes over the one-ring, the circle and the two-ring of vertex v (in that order, each
/// list from its longest edge to its shortest): an edge is flipped when it is flippable, the
/// four angles at its endpoints are all ≤ 90° and one is below the refinement angle. Returns
/// the number of flips.
std::size_t improve_around(SplitMesh& mesh, std::uint32_t v, const ReexpandOptions& options);

} // namespace hrsr::reexpand
