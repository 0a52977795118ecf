#include "mesh/vcg_mesh.h"

#include <vcg/complex/allocate.h>

namespace hrsr {

void build_vcg_mesh(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                    const std::vector<Triangle>& triangles, VcgMesh& m) {
    vcg::tri::Allocator<VcgMesh>::AddVertices(m, positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        m.vert[v].P() = positions[v];
        m.vert[v].N() = normals.size() == positions.size() ? normals[v] : Vec3(0, 0, 0);
    }
    vcg::tri::Allocator<VcgMesh>::AddFaces(m, triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        VcgFace& f = m.face[t];
        for (int k = 0; k < 3; ++k) f.V(k) = &m.vert[triangles[t][k]];
        const Vec3 n = (f.P(1) - f.P(0)) ^ (f.P(2) - f.P(0));
        const double length = n.Norm();
        f.N() = length > 0 ? n / length : Vec3(0, 0, 0);
    }
}

} // namespace hrsr
