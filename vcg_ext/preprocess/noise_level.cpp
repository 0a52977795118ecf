#include "preprocess/noise_level.h"

#include "geometry.h"
#include "options.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <optional>

namespace hrsr {

namespace {

constexpr std::size_t kNoiseSample = 20000;
constexpr int kFitNeighbours = 48; // 6 coefficients, enough points that noise is not fitted
constexpr int kSpacingRank = 6;
// Below this many points 48 neighbours are too large a part of the surface for one quadric (the
// eight, 315 vertices of a coarse mesh, measures 0.38).
constexpr std::size_t kFewestPoints = 1000;

struct Sample {
    double height = 0;  ///< |distance| of the point from the fitted quadric
    double spacing = 0; ///< distance to its sixth nearest neighbour
};

// Weighted least squares h ≈ c0 + c1 u + c2 v + c3 u² + c4 uv + c5 v² in the point's tangent
// frame (u, v scaled by the farthest tangential distance T), the point itself with weight T as
// in §4.4; c0 is the point's height above the fitted surface.
std::optional<Sample> fit(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                          std::size_t i, const std::vector<Neighbour>& neighbours) {
    if (neighbours.size() < std::size_t(kSpacingRank)) return std::nullopt;
    const double min_cos = std::cos(constants::kSmoothingNormalAngleDegrees * M_PI / 180.0);
    const Vec3& p = positions[i];
    const Vec3& n = normals[i];
    const TangentFrame frame = tangent_frame(n);
    double farthest = 0;
    for (const Neighbour& nb : neighbours) {
        const Vec3 d = positions[nb.index] - p;
        const double h = d.dot(n);
        farthest = std::max(farthest, std::sqrt(std::max(0.0, d.SquaredNorm() - h * h)));
    }
    if (!(farthest > 0)) return std::nullopt;
    using Vector6 = Eigen::Matrix<double, 6, 1>;
    Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
    Vector6 right = Vector6::Zero();
    const auto add = [&](double u, double v, double h, double w) {
        Vector6 m;
        m << 1, u, v, u * u, u * v, v * v;
        normal_matrix += w * m * m.transpose();
        right += w * h * m;
    };
    add(0, 0, 0, farthest);
    for (const Neighbour& nb : neighbours) {
        if (std::abs(normals[nb.index].dot(n)) < min_cos) continue;
        const Vec3 d = positions[nb.index] - p;
        const double h = d.dot(n);
        const double t = std::sqrt(std::max(0.0, d.SquaredNorm() - h * h));
        // A small floor keeps the farthest kept neighbour in the fit.
        add(d.dot(frame.t1) / farthest, d.dot(frame.t2) / farthest, h,
            farthest - t + 1e-3 * farthest);
    }
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(normal_matrix);
    if (solver.info() != Eigen::Success) return std::nullopt;
    const double height = solver.solve(right)[0];
    if (!std::isfinite(height)) return std::nullopt;
    return Sample{std::abs(height), (positions[neighbours[kSpacingRank - 1].index] - p).Norm()};
}

double median(std::vector<double>& values) {
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

} // namespace

double relative_noise(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                      const KnnIndex& index, const Execution& exec) {
    if (positions.size() < kFewestPoints) return 0;
    const std::size_t step = std::max<std::size_t>(1, positions.size() / kNoiseSample);
    const std::size_t count = (positions.size() + step - 1) / step;
    std::vector<std::optional<Sample>> samples(count);
    parallel_for(exec, count, [&](std::size_t s) {
        thread_local std::vector<Neighbour> found;
        index.neighbours_of(std::uint32_t(s * step), kFitNeighbours, found);
        samples[s] = fit(positions, normals, s * step, found);
    });
    std::vector<double> heights, spacings;
    for (const auto& s : samples)
        if (s) {
            heights.push_back(s->height);
            spacings.push_back(s->spacing);
        }
    if (heights.empty()) return 0;
    const double spacing = median(spacings);
    return spacing > 0 ? median(heights) / spacing : 0;
}

} // namespace hrsr
