// Area-weighted vertex normals of a triangle mesh, facing the way its triangles are wound: the
// normals a mesh's own points get in the tests that use meshes as clouds or fold fixtures.
#pragma once

#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <vector>

namespace hrsr::testing {

inline std::vector<Vec3> area_weighted_vertex_normals(const std::vector<Vec3>& positions,
                                                      const std::vector<Triangle>& triangles) {
    std::vector<Vec3> n(positions.size(), Vec3(0, 0, 0));
    for (const Triangle& t : triangles) {
        const Vec3 a = (positions[t[1]] - positions[t[0]]) ^ (positions[t[2]] - positions[t[0]]);
        for (std::uint32_t v : t) n[v] += a;
    }
    for (Vec3& v : n) v.Normalize();
    return n;
}

} // namespace hrsr::testing
