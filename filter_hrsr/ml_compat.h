// The few MeshLab plugin-API differences between versions (README "The MeshLab filter"), chosen
// by HRSR_ML_API (filter_hrsr/CMakeLists.txt reads it off the MeshLab headers). Built and run:
// 2020.09 (bookworm, meshlabserver), 2022.02 (API 2022) and 2025.07 (API 2023; RichPercentage)
// in the Debian trixie and sid roots of scripts/root/.
#pragma once

#include <utility>

#if HRSR_ML_API >= 2022
#include <common/mlexception.h>
#include <common/plugins/interfaces/filter_plugin.h>
using MLFilterBase = FilterPlugin;
#else
#include <common/interfaces.h>
#include <common/mlexception.h>
using MLFilterBase = MeshFilterInterface;
#endif

#if HRSR_ML_API >= 2023
using MLRichAbsPerc = RichPercentage;
#else
using MLRichAbsPerc = RichAbsPerc;
#endif

inline void ml_update_box_and_normals(MeshModel& m) {
#if HRSR_ML_API >= 2022
    m.updateBoxAndNormals();
#else
    m.UpdateBoxAndNormals();
#endif
}

/// `out` gets the texture list of `in` in the same order (texture coordinates refer to it by
/// index) and, from 2022.02 on, where MeshModel holds the images, the images too.
inline void ml_copy_textures(const MeshModel& in, MeshModel& out) {
    out.cm.textures = in.cm.textures;
#if HRSR_ML_API >= 2022
    for (const auto& [name, image] : in.getTextures()) out.addTexture(name, image);
#endif
}

/// A parameter of type P (constructor arguments `args`); `advanced` ones are shown in the
/// dialog's advanced group from 2022.02 on (2020.09 has no such group).
template <typename P, typename... Args>
P ml_parameter(bool advanced, Args&&... args) {
#if HRSR_ML_API >= 2022
    return P(std::forward<Args>(args)..., advanced);
#else
    (void)advanced;
    return P(std::forward<Args>(args)...);
#endif
}
