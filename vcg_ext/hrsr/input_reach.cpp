#include "hrsr/input_reach.h"

#include "knn.h"

#include <cmath>
#include <limits>

namespace hrsr {

std::vector<double> input_reach(const std::vector<Vec3>& points, const std::vector<PointIndex>& at,
                                int rank, const Execution& exec) {
    std::vector<double> reach(at.size(), std::numeric_limits<double>::infinity());
    if (at.empty() || rank < 1) return reach;
    const KnnIndex index(points);
    parallel_for(exec, at.size(), [&](std::size_t i) {
        thread_local std::vector<Neighbour> found;
        index.neighbours_of(at[i].value(), rank, found);
        if (int(found.size()) == rank) reach[i] = std::sqrt(found.back().squared_distance);
    });
    return reach;
}

} // namespace hrsr
