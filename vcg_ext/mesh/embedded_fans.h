// Vertices whose faces provably meet one another only where the mesh joins them. The search for
// intersecting pairs (triangle_grid.h) skips every pair of faces that shares such a vertex: on a
// reconstructed surface nearly all the pairs whose boxes overlap are neighbours (the lion: 3.4 M
// of 3.6 M share a vertex), and nearly every vertex has such a fan.
#pragma once

#include "mesh/triangle_grid.h"
#include "parallel.h"

#include <cstdint>
#include <vector>

namespace hrsr {

/// Per vertex of `g`'s positions, 1 when its faces form one closed fan (each neighbour once at
/// the start and once at the end of a face's sector) and, projected along some direction, all
/// turn the same way around it and cover the directions around it exactly once (the sectors
/// containing one ray number one). The projection then maps the fan one to one, so two of its
/// faces meet only in the vertex and the edges they share: no pair of them intersects by the rule
/// of self_intersections.h. The directions tried: the fan's normal (every sign from a filter
/// with a safe error bound, underflow included; a sign it cannot decide, zero included, fails
/// the direction), then the coordinate axes (exact: orientation signs and comparisons of
/// coordinates). 0 for vertices on a border, with several fans, more than 24 faces or a
/// degenerate face, and where the fan folds over. Vertices in parallel, the same result for any
/// thread count.
std::vector<std::uint8_t> embedded_fans(const TriangleGeometry& g, const Execution& exec);

/// Whether triangles a and b share a vertex whose fan `embedded` certifies (empty: none).
inline bool share_embedded_fan(const Triangle& a, const Triangle& b,
                               const std::vector<std::uint8_t>& embedded) {
    if (embedded.empty()) return false;
    for (std::uint32_t u : a)
        if ((u == b[0] || u == b[1] || u == b[2]) && embedded[u]) return true;
    return false;
}

} // namespace hrsr
