// Splitting the cloud into connected pieces and dropping small ones, after cutting long
// neighbour edges (ALGORITHM.md §4.6, D-7).
#pragma once

#include "graph/neighbour_graph.h"
#include "options.h"

#include <cstdint>
#include <vector>

namespace hrsr {

struct ComponentSplit {
    static constexpr std::uint32_t kDropped = 0xffffffffu;
    std::vector<std::uint32_t> label; ///< per point: component 0..count−1, or kDropped
    std::size_t count = 0; ///< kept components, labelled in order of their smallest point index
    std::size_t dropped_components = 0;
    std::vector<std::size_t> sizes; ///< per kept component
    double cut_length = 0;          ///< R, in the units of the positions
    std::size_t edges_cut = 0;
    std::size_t edges_beyond_reach = 0; ///< edges between pieces kept apart by `reach` (D-35)
};

/// `graph` is the symmetric kNN graph on the smoothed positions. Edges are kept when their
/// normals pass the filter (θ in tangent mode, 90° in Euclidean mode); R = r × the mean smoothed
/// length of the kept edges; an edge whose length on the *original* positions exceeds R is cut.
/// Components of fewer than min(N, min_component_size) points are dropped.
/// D-35: with `reach` (per point, or empty for none) an edge longer on the smoothed positions
/// than both its ends' reach joins two pieces only where one of them, apart, would be smaller
/// than that minimum size.
ComponentSplit split_components(const CsrGraph& graph, const std::vector<Vec3>& positions,
                                const std::vector<Vec3>& smoothed, const std::vector<Vec3>& normals,
                                const PreprocessOptions& options, const Execution& exec,
                                const std::vector<double>& reach = {});

/// Cosine of the normal-filter angle for the options' distance mode (§3.3).
double normal_filter_cosine(const PreprocessOptions& options);

} // namespace hrsr
