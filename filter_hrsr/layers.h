// Between MeshLab layers and the core: the input layer's points, the output layer's mesh, and
// the selection of dropped points in the input layer.
#pragma once

#include "ml_compat.h"
#include "reconstruction.h"

#include <vector>

namespace hrsr::plugin {

/// The live (not deleted) vertices of a layer, faces ignored, with their per-vertex normals
/// (MeshLab always has them; unset ones are zero and the core then estimates normals).
struct LayerPoints {
    PointSet cloud;
    std::vector<CVertexO*> vertices; ///< cloud point i is vertices[i]
};
LayerPoints points_of(CMeshO& layer);

/// Fills the empty `out` with `mesh`: vertices at their input points (bit-exact), the core's
/// per-vertex normals, triangles, bounding box and face normals.
void fill_layer(const LayerPoints& in, const Reconstruction& mesh, CMeshO& out);

/// The input layer's vertex each mesh vertex is made from (entry k for mesh vertex k).
std::vector<CVertexO*> vertex_sources(const LayerPoints& in, const Reconstruction& mesh);

/// Selects the input points that no mesh vertex represents (neither a vertex nor an exact
/// duplicate merged into one) and clears the selection of the others; returns how many are
/// selected, which is input points − referenced input points of the report.
std::size_t select_dropped(LayerPoints& in, const Reconstruction& mesh,
                           const ReconstructionReport& report);

} // namespace hrsr::plugin
