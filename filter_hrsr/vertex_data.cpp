#include "vertex_data.h"

#include <vcg/complex/allocate.h>

#include <cstdint>
#include <set>
#include <typeindex>

namespace hrsr::plugin {
namespace {

/// Copies the named attribute `a` of `in` onto `out` when its type is T (vcglib records the
/// type of every attribute; its own look-up by name checks only the size, which would take an
/// int for a float).
template <typename T>
bool copy_attribute_as(const vcg::PointerToAttribute& a, CMeshO& in,
                       const std::vector<CVertexO*>& sources, CMeshO& out) {
    if (a._type != std::type_index(typeid(T))) return false;
    auto from = vcg::tri::Allocator<CMeshO>::FindPerVertexAttribute<T>(in, a._name);
    if (!vcg::tri::Allocator<CMeshO>::IsValidHandle(in, from)) return false;
    auto to = vcg::tri::Allocator<CMeshO>::AddPerVertexAttribute<T>(out, a._name);
    for (std::size_t k = 0; k < sources.size(); ++k) to[k] = from[sources[k]];
    return true;
}

/// The first of Ts that is the type of `a` copies it; false if none is.
template <typename... Ts>
bool copy_attribute(const vcg::PointerToAttribute& a, CMeshO& in,
                    const std::vector<CVertexO*>& sources, CMeshO& out) {
    return (copy_attribute_as<Ts>(a, in, sources, out) || ...);
}

} // namespace

std::vector<std::string> copy_vertex_data(MeshModel& in, const std::vector<CVertexO*>& sources,
                                          MeshModel& out) {
    // MeshLab allocates colour and quality always but uses them only where the data mask says
    // so (rendering, saving, filters): the mask, not the storage, tells what the layer has.
    const int components = MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY |
                           MeshModel::MM_VERTRADIUS | MeshModel::MM_VERTTEXCOORD;
    const int has = in.dataMask() & components;
    out.updateDataMask(has);
    for (std::size_t k = 0; k < sources.size(); ++k) {
        const CVertexO& from = *sources[k];
        CVertexO& to = out.cm.vert[k];
        if (has & MeshModel::MM_VERTCOLOR) to.C() = from.cC();
        if (has & MeshModel::MM_VERTQUALITY) to.Q() = from.cQ();
        if (has & MeshModel::MM_VERTRADIUS) to.R() = from.cR();
        if (has & MeshModel::MM_VERTTEXCOORD) to.T() = from.cT();
    }
    if (has & MeshModel::MM_VERTTEXCOORD) ml_copy_textures(in, out); // what T().N() refers to

    std::vector<std::string> left_out;
    // a copy: vcglib's look-up may re-insert an attribute into the set (padded ones)
    const std::set<vcg::PointerToAttribute> attributes = in.cm.vert_attr;
    for (const vcg::PointerToAttribute& a : attributes) {
        if (a._name.empty()) continue; // a filter's temporary attribute, not the user's
        // every scalar, point and colour type vcglib and MeshLab's filters and importers use
        const bool copied =
            copy_attribute<float, double, std::int8_t, std::uint8_t, std::int16_t, std::uint16_t,
                           std::int32_t, std::uint32_t, std::int64_t, std::uint64_t, bool, char,
                           vcg::Point2f, vcg::Point2d, vcg::Point2i, vcg::Point3f, vcg::Point3d,
                           vcg::Point3i, vcg::Point4f, vcg::Point4d, vcg::Point4i, vcg::Color4b>(
                a, in.cm, sources, out.cm);
        if (!copied) left_out.push_back(a._name);
    }
    return left_out;
}

} // namespace hrsr::plugin
