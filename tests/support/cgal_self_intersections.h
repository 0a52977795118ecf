// CGAL's Polygon_mesh_processing::self_intersections on our triangles: the reference the exact
// pair test (mesh/self_intersections.h) is compared with, in tests/cgal and bench/. Never in the
// core.
#pragma once

#include "mesh/triangle_grid.h"
#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>
#include <optional>
#include <vector>

namespace hrsr::testing {

struct CgalIntersections {
    std::vector<TrianglePair> pairs; ///< i < j, sorted; i, j index the triangles as given
    std::size_t degenerate = 0;      ///< faces CGAL reports as a pair with themselves
};

/// None when CGAL's Surface_mesh refuses a triangle (the mesh is not a manifold polygon mesh).
inline std::optional<CgalIntersections>
cgal_self_intersections(const std::vector<Vec3>& positions,
                        const std::vector<Triangle>& triangles) {
    using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
    using Mesh = CGAL::Surface_mesh<Point>;
    Mesh mesh;
    for (const Vec3& p : positions) mesh.add_vertex(Point(p[0], p[1], p[2]));
    for (const Triangle& t : triangles)
        if (mesh.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]),
                          Mesh::Vertex_index(t[2])) == Mesh::null_face())
            return std::nullopt;
    std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> found;
    CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(found));
    CgalIntersections r;
    for (const auto& [f, g] : found) {
        if (f == g) {
            ++r.degenerate;
            continue;
        }
        r.pairs.emplace_back(std::min<std::uint32_t>(f, g), std::max<std::uint32_t>(f, g));
    }
    std::sort(r.pairs.begin(), r.pairs.end());
    return r;
}

} // namespace hrsr::testing
