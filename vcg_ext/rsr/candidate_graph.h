// The candidate kNN graph of RsR and its face-split candidates (ALGORITHM.md §5.1, §5.5.1).
#pragma once

#include "graph/neighbour_graph.h"
#include "options.h"
#include "rsr/component.h"

#include <vector>

namespace hrsr::rsr {

struct CandidateGraph {
    CsrGraph graph; ///< symmetric union of the normal-filtered kNN relations
    std::vector<double>
        pre_max_length; ///< Euclidean distance to the ⌊2k/3⌋-th neighbour (before filtering)
    std::vector<double> max_length; ///< longest len(i, j) over the edges of i
};

/// The neighbour rank ⌊2k/3⌋ (at most the points − 1, at least 1) whose distance bounds a
/// point's candidate edges (§5.1, D-8).
int candidate_rank(int k, std::size_t points);

/// kNN (k true neighbours) on the smoothed positions, filtered by the normal angle (§3.3).
CandidateGraph build_candidate_graph(const ComponentCloud& cloud, const KnnIndex& index,
                                     const PreprocessOptions& options, const Execution& exec);

struct CandidateEdge {
    double length;
    std::uint32_t i, j; ///< i < j
};

/// Edges {i, j} of the graph with len ≤ pre_max_length at both ends, sorted by (len, i, j)
/// (D-10).
std::vector<CandidateEdge> face_split_candidates(const CandidateGraph& g,
                                                 const ComponentCloud& cloud, DistanceMode mode,
                                                 const Execution& exec);

} // namespace hrsr::rsr
