// The last step against self-intersections (deviation D-32): the folds that the flips of D-26
// could not undo are cut out, vertex by vertex.
#pragma once

#include "mesh/fold_search.h"
#include "mesh/small_holes_fill.h"
#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"
#include "reconstruction_stats.h"

#include <cstdint>
#include <vector>

namespace hrsr {

struct FoldRemoval {
    FoldRemovalStats stats;
    /// For each vertex of the result, the vertex of the given mesh it is: vertices left without
    /// a face are gone, copies of pinched vertices are appended (§5.8).
    std::vector<std::uint32_t> vertex_source;
};

/// D-32. Every pair of intersecting triangles (the rule of self_intersections.h, exact, on
/// `positions` as given: vertices at one position count as one) is taken in pair order while
/// both of its faces stand. One corner of the pair is removed with its fan, and the hole is
/// triangulated again: the corners whose fans take part in the most pairs are tried first, and
/// the triangulations (the one with the largest smallest angle, then the fans from each corner
/// of the hole) in order until one fits: no degenerate triangle, no edge the mesh already has,
/// no intersection with any face or with each other, and (before a second try that drops it)
/// each triangle facing the way its corners' `normals` do. Where no corner's hole can be filled
/// so, a disc of fans grown around a corner towards what stood in the way (up to 8 vertices)
/// is tried; where that fails too, one face of the pair goes: the one that opens the mesh least
/// (an edge on the border: the border only moves), then the one in more pairs. New faces
/// intersect nothing and every step removes a face of the pair, so no pair is left. Sequential, in
/// a fixed order: the same on any number of threads. `triangles` (a consistently oriented manifold,
/// one fan per vertex: only the corners of faces cut or added are split when pinched) is
/// rewritten over the result's vertices: kept faces in their order, then the new ones. Then
/// border loops of at most 5 edges (D-28's gaps, left by any phase) are closed where a fill fits
/// and every vertex it takes out goes back at once, else they stay as they were (D-38). Last,
/// the vertices taken out and those given without any face (D-37: points in no triangle) go into
/// a standing face near them, or close a border corner next to them, where that fits; vertices
/// still without a face are not in the result. Then (D-55) each piece of at most 200 faces but
/// the largest whose points all go back over faces of other pieces near it, once its faces are
/// gone, joins them so. Then (D-45) the loops of more than 5 edges of a
/// piece whose every border loop has at most `pinhole_edges` edges (and more interior than
/// border vertices) are closed so too, leaving out at most a vertex per 5 edges; and (D-48) the
/// slits, loops of up to 48 edges whose sides are at most 1.5 spacings apart, as D-38 closes a
/// gap. Last (D-64), faces winding against their corners' normals are turned by edge flips that
/// cross nothing; no vertex, piece or border changes. Two faces on the same three positions are
/// a pair (a fin folded flat onto a face through a pinched copy).
FoldRemoval remove_folds(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                         std::vector<Triangle>& triangles, const Execution& exec,
                         std::size_t pinhole_edges = kMaxFilledLoop);

/// The same on pairs already found (after repair_folds() on the same search, its pairs left):
/// `search` must be built over `triangles` as they are now. New faces are added to it.
FoldRemoval remove_folds(FoldSearch& search, const std::vector<Vec3>& normals,
                         std::vector<Triangle>& triangles,
                         std::size_t pinhole_edges = kMaxFilledLoop);

} // namespace hrsr
