#include "preprocess/smoothing.h"

#include "options.h"

#include <algorithm>
#include <cmath>

namespace hrsr {

namespace {

double displacement(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                    std::size_t i, const std::vector<Neighbour>& neighbours, bool oriented) {
    const double min_cos = std::cos(constants::kSmoothingNormalAngleDegrees * M_PI / 180.0);
    const Vec3& p = positions[i];
    const Vec3& n = normals[i];
    thread_local std::vector<std::pair<double, double>> kept; // (height, tangential distance)
    kept.clear();
    double farthest = 0; // T: the point itself has t = 0, so T >= 0
    for (const Neighbour& nb : neighbours) {
        const double cosine = normals[nb.index].dot(n);
        if ((oriented ? cosine : std::abs(cosine)) < min_cos) continue;
        const Vec3 d = positions[nb.index] - p;
        const double h = d.dot(n);
        const double t = std::sqrt(std::max(0.0, d.SquaredNorm() - h * h));
        kept.emplace_back(h, t);
        farthest = std::max(farthest, t);
    }
    // The point itself: height 0, weight T.
    double weighted = 0, total = farthest;
    for (const auto& [h, t] : kept) {
        weighted += (farthest - t) * h;
        total += farthest - t;
    }
    return total > 0 ? weighted / total : 0.0;
}

} // namespace

SmoothingResult smooth_along_normals(const std::vector<Vec3>& positions,
                                     const std::vector<Vec3>& normals, const KnnIndex& index,
                                     int neighbours, bool oriented, const Execution& exec,
                                     NeighbourReach* reach) {
    SmoothingResult result;
    const std::size_t n = positions.size();
    result.positions.resize(n);
    std::vector<double>& shift = result.shift;
    shift.assign(n, 0.0);
    if (reach) reach->begin_round(n, neighbours);
    parallel_for(exec, n, [&](std::size_t i) {
        thread_local std::vector<Neighbour> found;
        if (reach)
            reach->neighbours(index, std::uint32_t(i), found);
        else
            index.neighbours_of(std::uint32_t(i), neighbours, found);
        shift[i] = displacement(positions, normals, i, found, oriented);
        result.positions[i] = positions[i] + normals[i] * shift[i];
    });
    for (double s : shift) { // sequential: the same sum for any thread count
        result.mean_shift += std::abs(s);
        result.max_shift = std::max(result.max_shift, std::abs(s));
    }
    if (n > 0) result.mean_shift /= double(n);
    if (reach) reach->moved(positions, shift, without_progress(exec));
    return result;
}

std::vector<Vec3> averaged_normals(const std::vector<Vec3>& normals, const KnnIndex& index,
                                   int neighbours, const Execution& exec, NeighbourReach* reach) {
    std::vector<Vec3> averaged(normals.size());
    if (reach) reach->begin_round(normals.size(), neighbours);
    parallel_for(exec, normals.size(), [&](std::size_t i) {
        thread_local std::vector<Neighbour> found;
        if (reach)
            reach->neighbours(index, std::uint32_t(i), found);
        else
            index.neighbours_of(std::uint32_t(i), neighbours, found);
        Vec3 sum = normals[i];
        for (const Neighbour& nb : found)
            if (normals[nb.index].dot(normals[i]) > 0) sum += normals[nb.index];
        averaged[i] = sum / sum.Norm(); // sum · n_i >= 1: never zero
    });
    return averaged;
}

} // namespace hrsr
