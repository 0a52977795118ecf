#include "hrsr/input_reach.h"

#include "knn.h"

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
    std::vector<std::vector<double>> reach(
        ranks.size(), std::vector<double>(at.size(), std::numeric_limits<double>::infinity()));
    const int deepest = ranks.empty() ? 0 : *std::max_element(ranks.begin(), ranks.end());
    if (at.empty() || deepest < 1) return reach;
    const KnnIndex index(points);
    parallel_for(exec, at.size(), [&](std::size_t i) {
        thread_local std::vector<Neighbour> found;
        index.neighbours_of(at[i].value(), deepest, found);
        for (std::size_t r = 0; r < ranks.size(); ++r)
            if (ranks[r] >= 1 && std::size_t(ranks[r]) <= found.size())
                reach[r][i] = std::sqrt(found[std::size_t(ranks[r]) - 1].squared_distance);
    });
    return reach;
}

} // namespace hrsr
