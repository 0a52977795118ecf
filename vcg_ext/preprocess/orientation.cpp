#include "preprocess/orientation.h"

#include "graph/spanning_forest.h"
#include "parallel.h"

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

OpposedNormals opposed_normals(const KnnIndex& index, const std::vector<Vec3>& normals,
                               const Execution& exec) {
    // Per block, joined in block order (no table of every point's neighbours: only the few
    // opposed points are kept).
    std::vector<OpposedNormals> found(block_count(normals.size(), kCheapBlock));
    parallel_for_blocks(exec, normals.size(), kCheapBlock,
                        [&](std::size_t block, std::size_t first, std::size_t end) {
                            std::vector<Neighbour> near;
                            for (auto i = std::uint32_t(first); i < end; ++i) {
                                index.neighbours_of(i, kOpposedScreen, near);
                                bool any = false;
                                for (std::size_t c = 0; c < near.size(); ++c) {
                                    const bool opposed = normals[i].dot(normals[near[c].index]) < 0;
                                    if (c == 0 && opposed) ++found[block].to_nearest;
                                    any = any || opposed;
                                }
                                if (any) found[block].to_a_near_one.push_back(i);
                            }
                        });
    OpposedNormals out;
    for (const OpposedNormals& f : found) {
        out.to_nearest += f.to_nearest;
        out.to_a_near_one.insert(out.to_a_near_one.end(), f.to_a_near_one.begin(),
                                 f.to_a_near_one.end());
    }
    return out;
}

std::vector<std::uint32_t> turn_lone_flipped_normals(const KnnIndex& index,
                                                     std::vector<Vec3>& normals,
                                                     const std::vector<std::uint32_t>& candidates,
                                                     const Execution& exec) {
    std::vector<std::uint8_t> lone(candidates.size(), 0);
    parallel_for_blocks(exec, candidates.size(), kCheapBlock / 16,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            std::vector<Neighbour> near;
                            for (std::size_t c = first; c < end; ++c) {
                                const std::uint32_t i = candidates[c];
                                index.neighbours_of(i, kLoneFlipNeighbours, near);
                                int opposed = 0;
                                for (const Neighbour& n : near)
                                    opposed += normals[i].dot(normals[n.index]) < 0;
                                lone[c] = opposed >= kLoneFlipOpposed;
                            }
                        });
    std::vector<std::uint32_t> turned;
    for (std::size_t c = 0; c < candidates.size(); ++c)
        if (lone[c]) turned.push_back(candidates[c]);
    for (std::uint32_t i : turned) normals[i] = -normals[i];
    return turned;
}

} // namespace hrsr
