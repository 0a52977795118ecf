// A static vcglib triangle mesh in double precision, for the checks and measures that reuse
// vcglib (triangle-triangle tests, point-to-surface distances, surface sampling).
#pragma once

#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <vcg/complex/complex.h>

#include <vector>

namespace hrsr {

class VcgVertex;
class VcgFace;
struct VcgUsedTypes
    : vcg::UsedTypes<vcg::Use<VcgVertex>::AsVertexType, vcg::Use<VcgFace>::AsFaceType> {};
class VcgVertex : public vcg::Vertex<VcgUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d,
                                     vcg::vertex::BitFlags> {};
class VcgFace : public vcg::Face<VcgUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d,
                                 vcg::face::BitFlags, vcg::face::Mark> {};
class VcgMesh : public vcg::tri::TriMesh<std::vector<VcgVertex>, std::vector<VcgFace>> {};

/// Fills the empty mesh `m` with `positions` and `triangles` (indices must be valid) and sets
/// unit face normals (zero for zero-area faces, which vcglib's distance code then treats as
/// segments). Vertex normals are `normals` if given (same size as `positions`), else zero.
void build_vcg_mesh(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                    const std::vector<Triangle>& triangles, VcgMesh& m);

} // namespace hrsr
