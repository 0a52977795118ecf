#include "hrsr/input_reach.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hrsr {

std::vector<double> input_reach(const std::vector<Vec3>& points, const std::vector<PointIndex>& at,
                                int rank, const Execution& exec) {
    return std::move(input_reach(points, at, std::vector<int>{rank}, exec).front());
}

std::vector<std::vector<double>> input_reach(const std::vector<Vec3>& points,
                                             const std::vector<PointIndex>& at,
                                             const std::vector<int>& ranks, const Execution& exec) {
    const int deepest = ranks.empty() ? 0 : *std::max_element(ranks.begin(), ranks.end());
    if (at.empty() || deepest < 1)
        return std::vector<std::vector<double>>(
            ranks.size(), std::vector<double>(at.size(), std::numeric_limits<double>::infinity()));
    const KnnIndex index(points, exec);
    return input_reach(index, at, ranks, exec);
}

std::vector<std::vector<double>> input_reach(const KnnIndex& index,
                                             const std::vector<PointIndex>& at,
                                             const std::vector<int>& ranks, const Execution& exec) {
    std::vector<std::vector<double>> reach(
        ranks.size(), std::vector<double>(at.size(), std::numeric_limits<double>::infinity()));
    const int deepest = ranks.empty() ? 0 : *std::max_element(ranks.begin(), ranks.end());
    if (at.empty() || deepest < 1) return reach;
    parallel_for(exec, at.size(), [&](std::size_t i) {
        thread_local std::vector<double> squared;
        index.squared_distances_at_ranks(at[i].value(), ranks, squared);
        for (std::size_t r = 0; r < ranks.size(); ++r) reach[r][i] = std::sqrt(squared[r]);
    });
    return reach;
}

} // namespace hrsr
