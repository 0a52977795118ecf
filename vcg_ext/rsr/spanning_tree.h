// The minimum spanning tree that starts RsR, and the ambiguous-leaf normal fix (§5.2).
#pragma once

#include "graph/spanning_forest.h"
#include "rsr/candidate_graph.h"

namespace hrsr::rsr {

/// Prim's tree over the candidate graph with cost |s_i − s_j|² (both distance modes).
SpanningForest candidate_spanning_tree(const CandidateGraph& g, const ComponentCloud& cloud);

/// Tangent mode: a leaf whose tree edge runs almost along the normals takes its parent's
/// normal, as do the other tree neighbours of that parent (unless claimed by two parents).
/// Returns the normals to use for rotation angles and geometry checks.
std::vector<Vec3> fix_leaf_normals(const SpanningForest& tree, const ComponentCloud& cloud);

} // namespace hrsr::rsr
