#include "preprocess/orientation.h"

#include "graph/spanning_forest.h"

#include <cmath>

namespace hrsr {

OrientationResult orient_normals(const CsrGraph& graph, const std::vector<Vec3>& positions,
                                 const std::vector<double>& radius, std::vector<Vec3>& normals) {
    auto cost = [&](std::uint32_t i, std::uint32_t j) {
        const Vec3 d = positions[i] - positions[j];
        const double rho = 0.5 * (radius[i] + radius[j]);
        const double across =
            rho > 0 ? (std::abs(d.dot(normals[i])) + std::abs(d.dot(normals[j]))) / rho : 0.0;
        return 1.0 - std::abs(normals[i].dot(normals[j])) + across;
    };
    const SpanningForest forest = minimum_spanning_forest(graph, cost);
    OrientationResult result;
    result.components = forest.trees;
    // Parents come first in `order`, so each parent's normal is final when its child is
    // visited: the same outcome as a breadth-first traversal of the finished tree.
    for (std::uint32_t v : forest.order) {
        const std::uint32_t p = forest.parent[v];
        if (p != SpanningForest::kRoot && normals[v].dot(normals[p]) < 0) {
            normals[v] = -normals[v];
            ++result.flips;
        }
    }
    return result;
}

std::size_t opposed_nearest_normals(const KnnIndex& index, const std::vector<Vec3>& normals,
                                    const Execution& exec) {
    const KnnTable nearest = knn_table(index, 1, exec);
    std::size_t opposed = 0;
    for (std::size_t i = 0; i < nearest.size(); ++i)
        if (normals[i].dot(normals[nearest.row(i)[0]]) < 0) ++opposed;
    return opposed;
}

} // namespace hrsr
