// Topological measures of a triangle mesh: what the report and the tests assert on.
#pragma once

#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"

#include <cstddef>
#include <vector>

namespace hrsr {

struct ComponentTopology {
    std::size_t vertices = 0, edges = 0, faces = 0, boundary_loops = 0;
    long euler() const { return long(vertices) - long(edges) + long(faces); }
    bool closed() const { return boundary_loops == 0; }
    /// Genus of an orientable surface: (2 − χ − b) / 2.
    long genus() const { return (2 - euler() - long(boundary_loops)) / 2; }
};

struct MeshStats {
    std::size_t vertices = 0; ///< referenced by at least one triangle
    std::size_t unreferenced_vertices = 0;
    std::size_t faces = 0;
    std::size_t edges = 0;
    std::size_t boundary_edges = 0; ///< in exactly one triangle
    std::size_t boundary_loops = 0;
    std::size_t non_manifold_edges = 0;            ///< in three or more triangles
    std::size_t non_manifold_vertices = 0;         ///< whose triangles form more than one fan
    std::size_t inconsistently_oriented_edges = 0; ///< two triangles traversing it the same way
    std::size_t degenerate_faces = 0;              ///< repeating a vertex
    std::vector<ComponentTopology> components;     ///< edge-connected, by their first triangle
    long euler() const { return long(vertices) - long(edges) + long(faces); }
};

/// The component with the most triangles (the first of equals), or nullptr for an empty mesh:
/// the reconstructed surface when small pieces split off. Its genus counts its holes as
/// boundary loops, so a surface with the right handles but left open still reports them.
const ComponentTopology* largest_component(const MeshStats& mesh);

/// Measures `triangles` over `vertex_count` vertices; optionally also gives each triangle's
/// face-connected component (through shared edges; ids in order of first triangle).
MeshStats measure_mesh(std::size_t vertex_count, const std::vector<Triangle>& triangles,
                       std::vector<std::uint32_t>* triangle_component = nullptr,
                       const Execution& exec = Execution{1, nullptr});

/// Signed volume enclosed by the triangles of each of `count` components (positive when they wind
/// counter-clockwise seen from outside), in one pass over the triangles.
std::vector<double> signed_volumes(const std::vector<Vec3>& positions,
                                   const std::vector<Triangle>& triangles,
                                   const std::vector<std::uint32_t>& component, std::size_t count);

} // namespace hrsr
