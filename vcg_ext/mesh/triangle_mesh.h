// An indexed triangle mesh (no positions: vertices are referred to by index).
#pragma once

#include "parallel.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hrsr {

using Triangle = std::array<std::uint32_t, 3>;

/// The triangle corners at each vertex (CSR): corners of vertex v are
/// corner[start[v]] … corner[start[v + 1] − 1], each 3 t + k, in increasing triangle order.
struct VertexCorners {
    std::vector<std::uint32_t> start, corner;
    std::uint32_t begin(std::uint32_t v) const { return start[v]; }
    std::uint32_t end(std::uint32_t v) const { return start[v + 1]; }
};

VertexCorners corners_by_vertex(std::size_t vertex_count, const std::vector<Triangle>& triangles);
/// The same lists, built by one task per thread, each over its own range of vertices.
VertexCorners corners_by_vertex(std::size_t vertex_count, const std::vector<Triangle>& triangles,
                                const Execution& exec);

/// Orders faces by their smallest vertex, stably (faces sharing it keep their order), for any
/// thread count: on vertices in spatial order the faces follow it too.
void sort_by_smallest_vertex(std::vector<Triangle>& triangles, const Execution& exec);

} // namespace hrsr
