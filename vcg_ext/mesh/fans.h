// Fans: the triangles around a vertex that are connected through edges at that vertex. A vertex
// with more than one fan is non-manifold (two surface sheets touching at a point).
#pragma once

#include "mesh/triangle_mesh.h"
#include "parallel.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hrsr {

struct Fans {
    std::vector<std::uint32_t>
        corner_fan; ///< per triangle corner (3t + k): fan number at that vertex, 0-based
    std::vector<std::uint32_t> fan_count; ///< per vertex
};

/// Fans are numbered per vertex in the order of their smallest triangle index (deterministic);
/// vertices in parallel (`exec`'s threads, no progress), the same result for any thread count.
Fans compute_fans(std::size_t vertex_count, const std::vector<Triangle>& triangles,
                  const Execution& exec = Execution{1, nullptr});

/// The same for the vertices flagged in `only` (per vertex); every other vertex is taken to have
/// one fan (the caller knows its faces did not change since it had one).
Fans compute_fans(std::size_t vertex_count, const std::vector<Triangle>& triangles,
                  const std::vector<std::uint8_t>& only);

/// Gives every extra fan of a non-manifold vertex its own copy of the vertex (§5.8): copies are
/// appended after the existing vertices, in (vertex, fan) order, and `triangles` is rewritten.
/// Returns, for every vertex of the result, the vertex it copies (itself for the originals).
/// With `only`, only the flagged vertices are looked at (compute_fans above).
std::vector<std::uint32_t>
split_non_manifold_vertices(std::size_t vertex_count, std::vector<Triangle>& triangles,
                            const std::vector<std::uint8_t>* only = nullptr,
                            const Execution& exec = Execution{1, nullptr});

/// The vertices `triangles` use (of `vertex_count`), renumbered in index order, then split as
/// above: `triangles` is rewritten over the result. Returns, for every vertex of the result, the
/// vertex of the given numbering it stands for (copies share it); unused vertices are left out.
/// `only`, if given, flags (in the given numbering) the vertices that may have several fans.
std::vector<std::uint32_t>
compact_and_split_vertices(std::size_t vertex_count, std::vector<Triangle>& triangles,
                           const std::vector<std::uint8_t>* only = nullptr,
                           const Execution& exec = Execution{1, nullptr});

} // namespace hrsr
