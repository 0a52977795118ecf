// Edge flips that undo folds: intersecting triangle pairs in a reconstruction (deviation D-26).
#pragma once

#include "mesh/fold_search.h"
#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"
#include "reconstruction_stats.h"

#include <cstddef>
#include <vector>

namespace hrsr {

/// D-26. RsR and the re-expansion test crossings only in tangent planes, so the output can fold
/// in 3-D: triangles around a vertex then overlap. This finds the intersecting pairs (the rule
/// of self_intersections.h) and, for each pair in order, flips the first edge, among the faces
/// around the pair's corners, whose flip lowers the number of intersections its two faces take
/// part in, without creating a degenerate triangle or folding the edge beyond both a right
/// angle and its old dihedral (a sharp fold along an edge is not an intersection, only one
/// folded flat is, so a flip must not just move the fold there). Faces flipped in a round wait for
/// the next one; a pair that found no flip is tried again only once a face around it has changed;
/// up to `rounds` rounds. Only the pairs touching flipped faces are tested again (against a grid of
/// the faces), so the count stays exact; the work after the first search is sequential, so the
/// result is the same on any number of threads. `triangles` (a consistently oriented manifold over
/// `positions`) keep their order; flips keep the vertices, the edge count, the boundary and the
/// genus.
FoldRepairStats repair_folds(const std::vector<Vec3>& positions, std::vector<Triangle>& triangles,
                             int rounds, const Execution& exec);

/// The same on pairs already found: `search` (built over `triangles`) follows the flips, and its
/// pairs end as the pairs left, ready for remove_folds().
FoldRepairStats repair_folds(FoldSearch& search, std::vector<Triangle>& triangles, int rounds);

} // namespace hrsr
