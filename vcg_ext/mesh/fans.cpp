#include "mesh/fans.h"

#include "graph/neighbour_graph.h"

#include <algorithm>
#include <numeric>

namespace hrsr {

Fans compute_fans(std::size_t n, const std::vector<Triangle>& triangles) {
    const VertexCorners at = corners_by_vertex(n, triangles);
    const std::vector<std::uint32_t>& offset = at.start;
    const std::vector<std::uint32_t>& corners = at.corner;

    Fans fans;
    fans.corner_fan.assign(3 * triangles.size(), 0);
    fans.fan_count.assign(n, 0);
    // Per-vertex scratch, reused: no allocation per vertex.
    DisjointSets sets(0);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> spokes; // (other endpoint, local corner)
    std::vector<std::uint32_t> fan_of_root;
    for (std::size_t v = 0; v < n; ++v) {
        const std::uint32_t first = offset[v], count = offset[v + 1] - first;
        if (count == 0) continue;
        // Two corners at v are in one fan when their triangles share an edge at v, i.e. the
        // other endpoint of one of their edges at v is the same vertex.
        sets.reset(count);
        spokes.clear();
        for (std::uint32_t c = 0; c < count; ++c) {
            const std::uint32_t corner = corners[first + c], t = corner / 3, k = corner % 3;
            spokes.emplace_back(triangles[t][(k + 1) % 3], c);
            spokes.emplace_back(triangles[t][(k + 2) % 3], c);
        }
        std::sort(spokes.begin(), spokes.end());
        for (std::size_t s = 1; s < spokes.size(); ++s)
            if (spokes[s].first == spokes[s - 1].first)
                sets.unite(spokes[s].second, spokes[s - 1].second);
        fan_of_root.assign(count, ~0u);
        for (std::uint32_t c = 0; c < count; ++c) { // corners are in triangle order
            std::uint32_t& fan = fan_of_root[sets.find(c)];
            if (fan == ~0u) fan = fans.fan_count[v]++;
            fans.corner_fan[corners[first + c]] = fan;
        }
    }
    return fans;
}

std::vector<std::uint32_t> split_non_manifold_vertices(std::size_t n,
                                                       std::vector<Triangle>& triangles) {
    const Fans fans = compute_fans(n, triangles);
    std::vector<std::uint32_t> source(n);
    std::iota(source.begin(), source.end(), 0u);
    std::vector<std::uint32_t> first_copy(n, 0);
    for (std::uint32_t v = 0; v < n; ++v) {
        first_copy[v] = std::uint32_t(source.size());
        for (std::uint32_t f = 1; f < fans.fan_count[v]; ++f) source.push_back(v);
    }
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t fan = fans.corner_fan[3 * t + std::uint32_t(k)];
            if (fan > 0) triangles[t][k] = first_copy[triangles[t][k]] + fan - 1;
        }
    return source;
}

std::vector<std::uint32_t> compact_and_split_vertices(std::size_t vertex_count,
                                                      std::vector<Triangle>& triangles) {
    std::vector<std::uint32_t> vertex_of(vertex_count, ~0u), used;
    for (const Triangle& t : triangles)
        for (std::uint32_t v : t) vertex_of[v] = 0;
    for (std::uint32_t v = 0; v < vertex_count; ++v)
        if (vertex_of[v] == 0) {
            vertex_of[v] = std::uint32_t(used.size());
            used.push_back(v);
        }
    for (Triangle& t : triangles)
        for (std::uint32_t& v : t) v = vertex_of[v];
    std::vector<std::uint32_t> source = split_non_manifold_vertices(used.size(), triangles);
    for (std::uint32_t& v : source) v = used[v];
    return source;
}

} // namespace hrsr
