// Making room for a vertex split (ALGORITHM.md §8.3, D-17): link edges of the vertex's fan that
// the new edge would cross in the tangent plane are flipped away, or, on the boundary, the
// triangle is removed.
#pragma once

#include "mesh/split_mesh.h"

namespace hrsr::reexpand {

struct CrossingStats {
    std::size_t flips = 0;
    std::size_t triangles_removed = 0;
    std::size_t unresolved = 0; ///< crossings left (could not be flipped or removed)
    bool round_limit = false;   ///< the round cap was hit
};

/// For c (still at its current position) and the split segment x_a – x_b: repeatedly finds a
/// crossed link edge (segment x_a → x_b, then x_b → x_a, each extended by 11 %) and resolves
/// it, at most kCrossingRounds rounds. `normal` is used when c's mesh normal degenerates.
CrossingStats resolve_crossings(SplitMesh& mesh, std::uint32_t c, const Vec3& x_a, const Vec3& x_b,
                                const Vec3& normal);

/// Whether the split segment still crosses a link edge of c (for tests and reports).
bool has_crossing(const SplitMesh& mesh, std::uint32_t c, const Vec3& x_a, const Vec3& x_b,
                  const Vec3& normal);

} // namespace hrsr::reexpand
