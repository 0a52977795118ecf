#include "preprocess/pca_normals.h"

#include "options.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cstdint>

namespace hrsr {

namespace {

// The automatic count for a cloud of n points whose neighbourhood should span `spanned` points'
// share of the surface: clamp(spanned, 16, 192), at most n / 40 on a small cloud (D-29).
int automatic_count(std::size_t n, std::size_t spanned) {
    using namespace constants;
    // D-29: on a tiny cloud 16 neighbours span a large share of the surface (the 315-point
    // "eight": a tube 12 spacings around), so the automatic count is also at most n / 40.
    const std::size_t small_cloud_cap =
        std::max<std::size_t>(kMinSmallCloudNeighbours, n / kSmallCloudPointsPerNeighbour);
    return int(std::min(std::clamp<std::size_t>(spanned, kMinNeighbours, kMaxNeighbours),
                        small_cloud_cap));
}

int at_most_all_others(std::size_t n, std::size_t wanted) {
    return int(std::min(wanted, n > 0 ? n - 1 : 0));
}

} // namespace

int neighbour_count(std::size_t n, int requested) {
    const std::size_t wanted = requested > 0
                                   ? std::size_t(requested)
                                   : automatic_count(n, n / constants::kPointsPerNeighbour);
    return at_most_all_others(n, wanted);
}

int coarse_neighbour_count(std::size_t input_points, std::size_t coarse_points, int requested) {
    using namespace constants;
    if (requested > 0) return at_most_all_others(coarse_points, std::size_t(requested));
    // D-44: the input's neighbourhood spans min(N / 2000, 192) of its N points; the coarse cloud's
    // spans the same share of the surface. Below N = 384,000 that is n / 2000, as on any cloud.
    const std::size_t clamp_from = std::size_t(kMaxNeighbours) * kPointsPerNeighbour;
    const std::size_t spanned = input_points <= clamp_from
                                    ? coarse_points / kPointsPerNeighbour
                                    : kMaxNeighbours * coarse_points / input_points;
    return at_most_all_others(coarse_points, automatic_count(coarse_points, spanned));
}

namespace {

// Returns false when the normal is undefined (all points on a line, or a single point).
// The positions are copied out first: the two passes below then read them from one place
// instead of scattered twice over the cloud (a third of the PCA's time at k = 192).
bool pca_normal(const std::vector<Vec3>& positions, std::uint32_t self,
                const std::vector<Neighbour>& neighbours, Vec3& normal) {
    thread_local std::vector<Eigen::Vector3d> points;
    points.clear();
    auto at = [&](std::uint32_t i) {
        const Vec3& p = positions[i];
        return Eigen::Vector3d(p[0], p[1], p[2]);
    };
    points.push_back(at(self));
    for (const Neighbour& nb : neighbours) points.push_back(at(nb.index));
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : points) centroid += p;
    centroid /= double(points.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& p : points) {
        const Eigen::Vector3d d = p - centroid;
        covariance += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    const Eigen::Vector3d& lambda = solver.eigenvalues(); // ascending
    if (solver.info() != Eigen::Success || !(lambda[2] > 0) ||
        lambda[1] <= constants::kPcaDegenerateRatio * lambda[2])
        return false;
    const Eigen::Vector3d n = solver.eigenvectors().col(0).normalized();
    normal = Vec3(n[0], n[1], n[2]);
    return true;
}

// D-5: a degenerate point copies the normal of the nearest point with a defined one.
void copy_from_nearest_valid(const std::vector<Vec3>& positions,
                             const std::vector<std::uint8_t>& valid, std::vector<Vec3>& normals,
                             const Execution& exec) {
    std::vector<Vec3> valid_points;
    std::vector<std::uint32_t> valid_index;
    for (std::uint32_t i = 0; i < positions.size(); ++i)
        if (valid[i]) {
            valid_points.push_back(positions[i]);
            valid_index.push_back(i);
        }
    const KnnIndex valid_tree(valid_points, exec);
    parallel_for(exec, positions.size(), [&](std::size_t i) {
        if (valid[i]) return;
        thread_local std::vector<Neighbour> found;
        valid_tree.nearest(positions[i], 1, found);
        normals[i] = normals[valid_index[found.front().index]];
    });
}

} // namespace

PcaNormals estimate_normals(const std::vector<Vec3>& positions, const KnnIndex& index,
                            int neighbours, const Execution& exec, NeighbourReach* reach) {
    PcaNormals result;
    const std::size_t n = positions.size();
    result.normals.assign(n, Vec3(0, 0, 0));
    std::vector<std::uint8_t> valid(n, 0);
    if (reach) reach->begin_round(n, neighbours);
    parallel_for(exec, n, [&](std::size_t i) {
        thread_local std::vector<Neighbour> found;
        if (reach)
            reach->neighbours(index, std::uint32_t(i), found);
        else
            index.neighbours_of(std::uint32_t(i), neighbours, found);
        valid[i] = pca_normal(positions, std::uint32_t(i), found, result.normals[i]) ? 1 : 0;
    });
    const std::size_t valid_count = std::size_t(std::count(valid.begin(), valid.end(), 1));
    result.degenerate = n - valid_count;
    if (valid_count == 0) {
        result.normals.clear();
    } else if (valid_count < n) {
        copy_from_nearest_valid(positions, valid, result.normals, exec);
    }
    return result;
}

} // namespace hrsr
