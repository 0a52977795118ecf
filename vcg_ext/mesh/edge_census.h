// Edges and fans counted around each vertex: an undirected edge is met at its smaller endpoint,
// among that vertex's spokes sorted by their other endpoint, so one parallel pass over the
// corner lists (which the fans need anyway) replaces a sort of all half-edges.
#pragma once

#include "graph/concurrent_sets.h"
#include "mesh/triangle_mesh.h"
#include "parallel.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace hrsr {

struct EdgeCensus {
    std::size_t edges = 0, boundary_edges = 0, non_manifold_edges = 0;
    std::size_t inconsistently_oriented_edges = 0, non_manifold_vertices = 0;
    /// Boundary edges (smaller, larger endpoint) in order of the smaller, then of the larger.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary;
    /// Per vertex: the last triangle using it, ~0u for none.
    std::vector<std::uint32_t> last_triangle;
};

/// Counts the edges of `triangles` over `vertex_count` vertices: the same counts, boundary and
/// fans as a walk over half-edges sorted by (smaller, larger endpoint). Unites in `sets` the
/// triangles sharing an edge and sets `first_of_edge[3t + k]` when edge k (t[k], t[k + 1]) of
/// triangle t is the edge's first (smallest-numbered triangle's) half-edge. By blocks of
/// vertices in parallel; the result is the same for any thread count.
EdgeCensus census_edges(std::size_t vertex_count, const std::vector<Triangle>& triangles,
                        ConcurrentSets& sets, std::vector<std::uint8_t>& first_of_edge,
                        const Execution& exec);

} // namespace hrsr
