#include "mesh/fans.h"

#include "graph/neighbour_graph.h"

#include <algorithm>
#include <numeric>

namespace hrsr {

namespace {

// Numbers the fans at each vertex from its corners (in triangle order); scratch kept between
// vertices, so there is no allocation per vertex.
class FanNumbering {
public:
    FanNumbering(const std::vector<Triangle>& triangles, Fans& fans)
        : triangles_(triangles), fans_(fans) {}

    void number(std::uint32_t v, const std::uint32_t* corners, std::uint32_t count) {
        // Two corners at v are in one fan when their triangles share an edge at v, i.e. the
        // other endpoint of one of their edges at v is the same vertex.
        sets_.reset(count);
        spokes_.clear();
        for (std::uint32_t c = 0; c < count; ++c) {
            const std::uint32_t t = corners[c] / 3, k = corners[c] % 3;
            spokes_.emplace_back(triangles_[t][(k + 1) % 3], c);
            spokes_.emplace_back(triangles_[t][(k + 2) % 3], c);
        }
        std::sort(spokes_.begin(), spokes_.end());
        for (std::size_t s = 1; s < spokes_.size(); ++s)
            if (spokes_[s].first == spokes_[s - 1].first)
                sets_.unite(spokes_[s].second, spokes_[s - 1].second);
        fan_of_root_.assign(count, ~0u);
        for (std::uint32_t c = 0; c < count; ++c) {
            std::uint32_t& fan = fan_of_root_[sets_.find(c)];
            if (fan == ~0u) fan = fans_.fan_count[v]++;
            fans_.corner_fan[corners[c]] = fan;
        }
    }

private:
    const std::vector<Triangle>& triangles_;
    Fans& fans_;
    DisjointSets sets_{0};
    std::vector<std::pair<std::uint32_t, std::uint32_t>> spokes_; // (other endpoint, corner)
    std::vector<std::uint32_t> fan_of_root_;
};

} // namespace

Fans compute_fans(std::size_t n, const std::vector<Triangle>& triangles, const Execution& exec) {
    const VertexCorners at = corners_by_vertex(n, triangles, without_progress(exec));
    Fans fans;
    fans.corner_fan.assign(3 * triangles.size(), 0);
    fans.fan_count.assign(n, 0);
    // Blocks of vertices: each writes only its vertices' counts and corners.
    constexpr std::size_t kBlock = 4096;
    parallel_for_blocks(
        without_progress(exec), n, kBlock, [&](std::size_t, std::size_t first, std::size_t end) {
            FanNumbering numbering(triangles, fans);
            for (std::uint32_t v = std::uint32_t(first); v < end; ++v)
                if (at.end(v) > at.begin(v))
                    numbering.number(v, at.corner.data() + at.begin(v), at.end(v) - at.begin(v));
        });
    return fans;
}

Fans compute_fans(std::size_t n, const std::vector<Triangle>& triangles,
                  const std::vector<std::uint8_t>& only) {
    Fans fans;
    fans.corner_fan.assign(3 * triangles.size(), 0);
    fans.fan_count.assign(n, 1); // one fan (or none: no copy either way)
    std::vector<std::pair<std::uint32_t, std::uint32_t>> flagged; // (vertex, corner)
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (std::uint32_t k = 0; k < 3; ++k)
            if (only[triangles[t][k]]) flagged.emplace_back(triangles[t][k], 3 * t + k);
    std::sort(flagged.begin(), flagged.end()); // by vertex, then in triangle order
    std::vector<std::uint32_t> corners;
    FanNumbering numbering(triangles, fans);
    for (std::size_t first = 0, last; first < flagged.size(); first = last) {
        const std::uint32_t v = flagged[first].first;
        corners.clear();
        for (last = first; last < flagged.size() && flagged[last].first == v; ++last)
            corners.push_back(flagged[last].second);
        fans.fan_count[v] = 0;
        numbering.number(v, corners.data(), std::uint32_t(corners.size()));
    }
    return fans;
}

std::vector<std::uint32_t> split_non_manifold_vertices(std::size_t n,
                                                       std::vector<Triangle>& triangles,
                                                       const std::vector<std::uint8_t>* only,
                                                       const Execution& exec) {
    const Fans fans = only ? compute_fans(n, triangles, *only) : compute_fans(n, triangles, exec);
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
                                                      std::vector<Triangle>& triangles,
                                                      const std::vector<std::uint8_t>* only,
                                                      const Execution& exec) {
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
    std::vector<std::uint8_t> only_used;
    if (only) {
        only_used.resize(used.size());
        for (std::size_t w = 0; w < used.size(); ++w) only_used[w] = (*only)[used[w]];
    }
    std::vector<std::uint32_t> source =
        split_non_manifold_vertices(used.size(), triangles, only ? &only_used : nullptr, exec);
    for (std::uint32_t& v : source) v = used[v];
    return source;
}

} // namespace hrsr
