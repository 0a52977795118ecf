// D-28: closing the tiniest holes of an output mesh, whatever phase left them (and D-39: those
// of HRsR's coarse mesh on pieces that are otherwise closed).
#pragma once

#include "index_types.h"
#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"

#include <cstddef>
#include <vector>

namespace hrsr {

/// Boundary loops of at most this many edges are closed (D-28): a loop through five input
/// points is a gap of about one point spacing, not a hole in the data.
inline constexpr std::size_t kMaxFilledLoop = 5;

/// Which short loops fill_small_holes closes.
enum class SmallHoleScope {
    Every,                  ///< every short loop (D-28)
    PiecesClosedButForThem, ///< only on pieces closed but for short loops (D-39)
};

/// D-53: with scope PiecesClosedButForThem, longer loops that count as pinholes too: those of at
/// most `max_edges` edges with a fan (see fill_small_holes) over sampled surface, i.e. a point of
/// `samples` within the reach of RsR's candidate edges (§5.1: the distance from a corner of the
/// loop to its rank-th nearest sample, at the corner where that is shortest) of every fan
/// triangle's centroid.
/// A hole in the data has no point near its middle; a gap that only a coarse sampling left is
/// sampled everywhere.
struct SampledLoops {
    std::size_t max_edges = 0;                  ///< 0: none
    const std::vector<Vec3>* samples = nullptr; ///< the cloud the loop's corners stand for
    int rank = 1;
};

/// Closes every boundary loop of 3 … `max_edges` distinct vertices, each of which borders no
/// other hole (with `scope` PiecesClosedButForThem: only on pieces, i.e. vertices joined by
/// triangles, whose every border loop is such a loop or one of `sampled`'s and whose interior
/// vertices outnumber their border vertices), by the best fan (one of the loop's triangulations;
/// best = largest smallest angle, at least 1°) whose diagonals are not edges yet and whose
/// triangles intersect neither the mesh nor an earlier fill (the `hrsr check` test): a fill never
/// adds a fold. New triangles follow the loop's winding, so the mesh stays edge- and
/// vertex-manifold and coherently oriented; a 3-loop that is already a triangle (a lone triangle's
/// outline) stays open. Vertex v lies at points[vertex_point[v]], or at points[v] when vertex_point
/// is empty. Returns the number of loops closed. Deterministic (loops in order of their smallest
/// vertex), the same for any thread count of `exec` (whose progress is not used).
std::size_t fill_small_holes(std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
                             const IndexVector<VertexIndex, PointIndex>& vertex_point = {},
                             std::size_t max_edges = kMaxFilledLoop,
                             SmallHoleScope scope = SmallHoleScope::Every,
                             const Execution& exec = Execution{1, nullptr},
                             const SampledLoops& sampled = {});

} // namespace hrsr
