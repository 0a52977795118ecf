#include "preprocess/components.h"

#include <algorithm>
#include <cmath>

namespace hrsr {

double normal_filter_cosine(const PreprocessOptions& options) {
    const double degrees = options.distance == DistanceMode::Tangent
                               ? options.theta_degrees
                               : constants::kEuclideanNormalAngleDegrees;
    return std::cos(degrees * M_PI / 180.0);
}

namespace {

// D-35: edges beyond the reach keep pieces apart only where each piece could stand alone; a
// smaller one rejoins the surface it was taken from (sizes as the reach left them: the result
// does not depend on the order of the edges).
void join_small_pieces(DisjointSets& sets, std::size_t n,
                       const std::vector<std::pair<std::uint32_t, std::uint32_t>>& beyond_reach,
                       std::size_t min_size, ComponentSplit& split) {
    if (beyond_reach.empty()) return;
    std::vector<std::size_t> size(n, 0);
    for (std::uint32_t i = 0; i < n; ++i) ++size[sets.find(i)];
    std::vector<std::uint8_t> small(n, 0);
    for (std::uint32_t i = 0; i < n; ++i) small[i] = size[sets.find(i)] < min_size;
    for (const auto& [i, j] : beyond_reach)
        if (small[i] || small[j]) sets.unite(i, j);
    for (const auto& [i, j] : beyond_reach)
        if (sets.find(i) != sets.find(j)) ++split.edges_beyond_reach;
}

} // namespace

ComponentSplit split_components(const CsrGraph& graph, const std::vector<Vec3>& positions,
                                const std::vector<Vec3>& smoothed, const std::vector<Vec3>& normals,
                                const PreprocessOptions& options, const Execution& exec,
                                const std::vector<double>& reach) {
    const std::size_t n = graph.size();
    const double min_cos = normal_filter_cosine(options);
    auto passes_filter = [&](std::size_t i, std::uint32_t j) {
        return normals[i].dot(normals[j]) >= min_cos;
    };

    // Mean length over the filtered edges, each undirected edge once (i < j); per-point sums
    // are added up sequentially so the result does not depend on the thread count.
    std::vector<double> length_sum(n, 0.0);
    std::vector<std::uint32_t> edge_count(n, 0);
    parallel_for(exec, n, [&](std::size_t i) {
        for (const std::uint32_t* j = graph.begin(i); j != graph.end(i); ++j) {
            if (*j <= i || !passes_filter(i, *j)) continue;
            length_sum[i] += (smoothed[*j] - smoothed[i]).Norm();
            ++edge_count[i];
        }
    });
    double total = 0;
    std::size_t edges = 0;
    for (std::size_t i = 0; i < n; ++i) {
        total += length_sum[i];
        edges += edge_count[i];
    }

    ComponentSplit split;
    split.cut_length = edges > 0 ? options.r * total / double(edges) : 0.0;
    const std::size_t min_size = std::min<std::size_t>(n, std::size_t(options.min_component_size));
    DisjointSets sets(n);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> beyond_reach;
    for (std::size_t i = 0; i < n; ++i)
        for (const std::uint32_t* j = graph.begin(i); j != graph.end(i); ++j) {
            if (*j <= i || !passes_filter(i, *j)) continue;
            if ((positions[*j] - positions[i]).Norm() > split.cut_length)
                ++split.edges_cut;
            else if (!reach.empty() &&
                     (smoothed[*j] - smoothed[i]).Norm() > std::max(reach[i], reach[*j]))
                beyond_reach.emplace_back(std::uint32_t(i), *j);
            else
                sets.unite(std::uint32_t(i), *j);
        }
    join_small_pieces(sets, n, beyond_reach, min_size, split);

    std::vector<std::size_t> root_size(n, 0);
    for (std::uint32_t i = 0; i < n; ++i) ++root_size[sets.find(i)];
    split.label.assign(n, ComponentSplit::kDropped);
    std::vector<std::uint32_t> root_label(n, ComponentSplit::kDropped);
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t root = sets.find(i);
        if (root_size[root] < min_size) {
            if (root == i) ++split.dropped_components;
            continue;
        }
        if (root_label[root] == ComponentSplit::kDropped) {
            root_label[root] = std::uint32_t(split.count++);
            split.sizes.push_back(root_size[root]);
        }
        split.label[i] = root_label[root];
    }
    return split;
}

} // namespace hrsr
