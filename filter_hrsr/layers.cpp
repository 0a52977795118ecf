#include "layers.h"

#include <vcg/complex/allocate.h>

namespace hrsr::plugin {

LayerPoints points_of(CMeshO& layer) {
    LayerPoints p;
    p.cloud.precision = CoordinatePrecision::Float;
    for (CVertexO& v : layer.vert) {
        if (v.IsD()) continue;
        p.vertices.push_back(&v);
        p.cloud.positions.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
        p.cloud.normals.emplace_back(v.cN()[0], v.cN()[1], v.cN()[2]);
    }
    return p;
}

void fill_layer(const LayerPoints& in, const Reconstruction& mesh, CMeshO& out) {
    auto v = vcg::tri::Allocator<CMeshO>::AddVertices(out, mesh.vertex_input_index.size());
    for (std::size_t k = 0; k < mesh.vertex_input_index.size(); ++k, ++v) {
        v->P() = in.vertices[mesh.vertex_input_index[k]]->cP();
        const Vec3& n = mesh.vertex_normals[k];
        v->N() = CMeshO::CoordType(float(n[0]), float(n[1]), float(n[2]));
    }
    auto f = vcg::tri::Allocator<CMeshO>::AddFaces(out, mesh.triangles.size());
    for (const Triangle& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) f->V(k) = &out.vert[t[k]];
        ++f;
    }
    vcg::tri::UpdateBounding<CMeshO>::Box(out);
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(out); // keeps the per-vertex normals
}

std::vector<CVertexO*> vertex_sources(const LayerPoints& in, const Reconstruction& mesh) {
    std::vector<CVertexO*> sources;
    sources.reserve(mesh.vertex_input_index.size());
    for (std::uint32_t i : mesh.vertex_input_index) sources.push_back(in.vertices[i]);
    return sources;
}

std::size_t select_dropped(LayerPoints& in, const Reconstruction& mesh,
                           const ReconstructionReport& report) {
    std::vector<char> is_vertex(in.vertices.size(), 0);
    for (std::uint32_t i : mesh.vertex_input_index) is_vertex[i] = 1;
    const std::vector<std::uint32_t>& duplicate_of = report.preprocess.duplicate_of;
    std::size_t selected = 0;
    for (std::size_t i = 0; i < in.vertices.size(); ++i) {
        const bool represented =
            is_vertex[i] || (i < duplicate_of.size() && is_vertex[duplicate_of[i]]);
        if (represented) {
            in.vertices[i]->ClearS();
        } else {
            in.vertices[i]->SetS();
            ++selected;
        }
    }
    return selected;
}

} // namespace hrsr::plugin
