#include "hrsr/collapse_graph.h"

#include "geometry.h"
#include "graph/neighbour_graph.h"
#include "knn.h"

#include <algorithm>
#include <utility>

namespace hrsr::collapsing {

EdgeKey CollapseGraph::edge_key(std::uint32_t a, std::uint32_t b) const {
    const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
    return {tangent_distance(x[hi] - x[lo], n[lo], n[hi]) * double(w[lo] + w[hi]), lo, hi};
}

void CollapseGraph::merge(std::uint32_t a, std::uint32_t b, std::vector<CollapseRecord>& records) {
    const double wa = w[a], wb = w[b], total = wa + wb;
    const Vec3 merged = (x[a] * wa + x[b] * wb) / total;
    Vec3 normal = (n[a] * wa + n[b] * wb) / total;
    const double length = normal.Norm();
    normal = length > 1e-12 ? normal / length : n[a]; // D-9
    records.push_back({a, b, x[a], x[b]});
    x[a] = merged;
    n[a] = normal;
    w[a] += w[b];
    alive[b] = 0;
    into[b] = a;
}

std::uint32_t CollapseGraph::survivor(std::uint32_t i) {
    std::uint32_t s = i;
    while (into[s] != s) s = into[s];
    for (std::uint32_t j = i; into[j] != s;) j = std::exchange(into[j], s);
    return s;
}

void CollapseGraph::relink(std::uint32_t c, std::uint32_t dead, std::uint32_t to) {
    erase(c, dead);
    auto& list = neighbours[c];
    if (to == c || std::find(list.begin(), list.end(), to) != list.end()) return;
    list.push_back(to);
    auto& back = neighbours[to];
    if (std::find(back.begin(), back.end(), c) == back.end()) back.push_back(c);
}

void CollapseGraph::erase(std::uint32_t c, std::uint32_t j) {
    auto& list = neighbours[c];
    list.erase(std::remove(list.begin(), list.end(), j), list.end());
}

CollapseGraph build_graph(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                          int k, const Execution& exec, std::unique_ptr<KnnIndex> index) {
    const std::size_t n = positions.size();
    CollapseGraph g{positions,
                    normals,
                    std::vector<std::uint32_t>(n, 1),
                    std::vector<std::uint8_t>(n, 1),
                    std::vector<std::vector<std::uint32_t>>(n),
                    std::vector<std::uint32_t>(n)};
    for (std::uint32_t i = 0; i < n; ++i) g.into[i] = i;
    // The kd-tree is freed before the union's arrays are allocated, the kNN graphs on return
    // (peak memory).
    if (!index) index = std::make_unique<KnnIndex>(g.x, exec);
    KnnTable table = knn_table(*index, k, exec);
    index.reset();
    const CsrGraph union_graph = symmetric_union(std::move(table), n, exec);
    // Each node's list is its own (by blocks of nodes in parallel).
    parallel_for_blocks(
        without_progress(exec), n, kCheapBlock,
        [&](std::size_t, std::size_t first, std::size_t end) {
            for (auto i = std::uint32_t(first); i < end; ++i) {
                auto& list = g.neighbours[i];
                list.reserve(std::size_t(union_graph.end(i) - union_graph.begin(i)));
                for (const std::uint32_t* j = union_graph.begin(i); j != union_graph.end(i); ++j)
                    if (g.n[i].dot(g.n[*j]) >= 0) // D-14: > 90° never linked
                        list.push_back(*j);
            }
        });
    return g;
}

} // namespace hrsr::collapsing
