#include "mesh/outward.h"

#include <algorithm>
#include <utility>

namespace hrsr {

// One pass for all pieces: a pass per closed piece grew with pieces × triangles (55 closed pieces
// on the 20M dragon sample).
std::size_t turn_closed_components_outwards(const std::vector<Vec3>& positions,
                                            const MeshStats& stats,
                                            const std::vector<std::uint32_t>& component,
                                            std::vector<Triangle>& triangles,
                                            std::vector<Vec3>& normals) {
    const std::size_t count = stats.components.size();
    if (std::none_of(stats.components.begin(), stats.components.end(),
                     [](const ComponentTopology& c) { return c.closed(); }))
        return 0;
    const std::vector<double> volume = signed_volumes(positions, triangles, component, count);
    std::vector<std::uint8_t> turn(count, 0);
    std::size_t turned = 0;
    for (std::size_t c = 0; c < count; ++c)
        if (stats.components[c].closed() && volume[c] < 0) {
            turn[c] = 1;
            ++turned;
        }
    if (turned == 0) return 0;
    // Each vertex's first turned piece, and the other turned pieces where pieces touch at it.
    constexpr std::uint32_t kNone = ~0u;
    std::vector<std::uint32_t> first(normals.size(), kNone);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> more; // (vertex, piece)
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const std::uint32_t c = component[t];
        if (!turn[c]) continue;
        std::swap(triangles[t][1], triangles[t][2]);
        for (std::uint32_t v : triangles[t]) {
            if (first[v] == kNone)
                first[v] = c;
            else if (first[v] != c)
                more.emplace_back(v, c);
        }
    }
    std::sort(more.begin(), more.end());
    more.erase(std::unique(more.begin(), more.end()), more.end());
    std::vector<std::uint8_t> odd(normals.size(), 0);
    for (std::size_t v = 0; v < normals.size(); ++v) odd[v] = first[v] != kNone;
    for (const auto& [v, c] : more) odd[v] ^= 1;
    for (std::size_t v = 0; v < normals.size(); ++v)
        if (odd[v]) normals[v] = -normals[v];
    return turned;
}

} // namespace hrsr
