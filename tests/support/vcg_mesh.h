// A static vcglib triangle mesh for tests (double coordinates, face Mark and FF adjacency), built
// from a reconstruction over input points, to cross-check our results with vcglib's own tools.
#pragma once

#include "point_set.h"
#include "reconstruction.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace hrsr::testing {

class VcgVertex;
class VcgFace;
struct VcgUsedTypes
    : vcg::UsedTypes<vcg::Use<VcgVertex>::AsVertexType, vcg::Use<VcgFace>::AsFaceType> {};
class VcgVertex : public vcg::Vertex<VcgUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                                     vcg::vertex::BitFlags, vcg::vertex::Mark> {};
class VcgFace : public vcg::Face<VcgUsedTypes, vcg::face::VertexRef, vcg::face::BitFlags,
                                 vcg::face::FFAdj, vcg::face::Mark> {};
class VcgMesh : public vcg::tri::TriMesh<std::vector<VcgVertex>, std::vector<VcgFace>> {};

/// Fills `m` (which must be empty) with the triangles of `r`, at the positions of the input
/// points they refer to. Output vertices that share an input point (copies made for
/// non-manifold fans, §5.8) become one vcg vertex, so that faces meeting there share it as they
/// do geometrically. FF adjacency is computed.
inline void build_vcg_mesh(const PointSet& input, const Reconstruction& r, VcgMesh& m) {
    std::unordered_map<std::uint32_t, std::size_t> vertex_of_point;
    std::vector<std::size_t> vertex_of(r.vertex_input_index.size());
    for (std::size_t v = 0; v < r.vertex_input_index.size(); ++v)
        vertex_of[v] =
            vertex_of_point.emplace(r.vertex_input_index[v], vertex_of_point.size()).first->second;
    vcg::tri::Allocator<VcgMesh>::AddVertices(m, vertex_of_point.size());
    for (const auto& [point, vertex] : vertex_of_point) m.vert[vertex].P() = input.positions[point];
    vcg::tri::Allocator<VcgMesh>::AddFaces(m, r.triangles.size());
    for (std::size_t t = 0; t < r.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) m.face[t].V(k) = &m.vert[vertex_of[r.triangles[t][k]]];
    vcg::tri::UpdateTopology<VcgMesh>::FaceFace(m);
}

/// Faces that vcglib finds intersecting another face, each once, in mesh order (pairs sharing
/// an edge are never reported: a fold along a shared edge is not found).
inline std::vector<VcgFace*> self_intersecting_faces(VcgMesh& m) {
    std::vector<VcgFace*> faces;
    vcg::tri::Clean<VcgMesh>::SelfIntersections(m, faces);
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    return faces;
}

} // namespace hrsr::testing
