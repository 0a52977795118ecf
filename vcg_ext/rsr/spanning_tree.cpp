#include "rsr/spanning_tree.h"

#include <cmath>

namespace hrsr::rsr {

SpanningForest candidate_spanning_tree(const CandidateGraph& g, const ComponentCloud& cloud) {
    return minimum_spanning_forest(g.graph, [&](std::uint32_t i, std::uint32_t j) {
        return (cloud.smoothed[i] - cloud.smoothed[j]).SquaredNorm();
    });
}

std::vector<Vec3> fix_leaf_normals(const SpanningForest& tree, const ComponentCloud& cloud) {
    const std::size_t n = tree.parent.size();
    constexpr std::uint32_t kUnmarked = SpanningForest::kRoot, kCollision = kUnmarked - 1;
    std::vector<std::uint32_t> degree(n, 0);
    std::vector<std::vector<std::uint32_t>> neighbours(n);
    for (std::uint32_t v = 0; v < n; ++v)
        if (tree.parent[v] != SpanningForest::kRoot) {
            ++degree[v];
            ++degree[tree.parent[v]];
            neighbours[v].push_back(tree.parent[v]);
            neighbours[tree.parent[v]].push_back(v);
        }
    const double along = std::cos(constants::kLeafFixAngleDegrees * M_PI / 180.0);
    std::vector<std::uint32_t> represented_by(n, kUnmarked);
    auto mark = [&](std::uint32_t v, std::uint32_t parent) {
        if (represented_by[v] == kUnmarked)
            represented_by[v] = parent;
        else if (represented_by[v] != parent)
            represented_by[v] = kCollision;
    };
    for (std::uint32_t a = 0; a < n; ++a) {
        const std::uint32_t b = tree.parent[a];
        if (b == SpanningForest::kRoot || (degree[a] != 1 && degree[b] != 1)) continue;
        const Vec3 e = cloud.smoothed[b] - cloud.smoothed[a];
        const Vec3 m = (cloud.normals[a] + cloud.normals[b]) * 0.5;
        const double length = e.Norm();
        if (length == 0 || std::abs(e.dot(m)) / length <= along) continue;
        const std::uint32_t leaf = degree[a] == 1 ? a : b, parent = leaf == a ? b : a;
        mark(leaf, parent);
        for (std::uint32_t w : neighbours[parent]) mark(w, parent);
    }
    std::vector<Vec3> normals = cloud.normals;
    for (std::uint32_t v = 0; v < n; ++v)
        if (represented_by[v] != kUnmarked && represented_by[v] != kCollision)
            normals[v] = cloud.normals[represented_by[v]];
    return normals;
}

} // namespace hrsr::rsr
