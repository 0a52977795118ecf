// Point clouds sampled from analytic surfaces, with exact outward normals, for tests.
#pragma once

#include "point_set.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace hrsr::testing {

/// Density of the samples: uniform over the surface area, or denser towards one side
/// (acceptance probability from 1 down to 0.1 along x) to test non-uniform sampling.
enum class Density { Uniform, Graded };

namespace detail {
/// The graded density's acceptance probability at p: 1 at x = −extent down to 0.1 at +extent.
inline double acceptance(const Vec3& p, double extent) {
    const double u = std::clamp((p[0] / extent + 1.0) / 2.0, 0.0, 1.0);
    return 1.0 - 0.9 * u;
}

inline bool accept(const Vec3& p, double extent, Density density, std::mt19937_64& rng) {
    if (density == Density::Uniform) return true;
    return std::uniform_real_distribution<double>(0, 1)(rng) < acceptance(p, extent);
}
} // namespace detail

/// n points on the sphere of radius `radius` centred at `centre`.
inline PointSet sample_sphere(std::size_t n, double radius = 1.0, Vec3 centre = Vec3(0, 0, 0),
                              Density density = Density::Uniform, unsigned seed = 1) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> gauss;
    PointSet s;
    s.precision = CoordinatePrecision::Double;
    while (s.size() < n) {
        Vec3 d(gauss(rng), gauss(rng), gauss(rng));
        if (d.Norm() < 1e-9) continue;
        d /= d.Norm();
        if (!detail::accept(d, 1.0, density, rng)) continue;
        s.positions.push_back(centre + d * radius);
        s.normals.push_back(d);
    }
    return s;
}

/// n points on the torus with ring radius R and tube radius r around the z axis, sampled
/// uniformly by area (rejection on the area element R + r cos v).
inline PointSet sample_torus(std::size_t n, double R = 1.0, double r = 0.35,
                             Density density = Density::Uniform, unsigned seed = 2) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), unit(0, 1);
    PointSet s;
    s.precision = CoordinatePrecision::Double;
    while (s.size() < n) {
        const double u = angle(rng), v = angle(rng);
        if (unit(rng) * (R + r) > R + r * std::cos(v)) continue;
        const Vec3 normal(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
        const Vec3 p(std::cos(u) * R, std::sin(u) * R, 0.0);
        const Vec3 q = p + normal * r;
        if (!detail::accept(q, R + r, density, rng)) continue;
        s.positions.push_back(q);
        s.normals.push_back(normal);
    }
    return s;
}

/// A genus-2 surface: the smooth union of two tori (ring radius R, tube radius r, around the z
/// axis) centred at (±offset, 0, 0), as the zero set of f = smin(d_left, d_right) with the
/// tori's signed distances d and the polynomial smooth minimum of width `blend`. With the
/// defaults the two tubes fuse into one bar between the holes (their centre lines are 0.4
/// apart there), the holes have radius R − r = 0.6 and their centres are 2.4 apart, and the
/// other torus's tube stays about 0.4 from each hole's rim (≈ 10 sample spacings at 20k
/// points): the holes are far apart compared with the spacing. Points: random points on both tori,
/// projected on f = 0 by Newton steps along ∇f, then thinned by a minimum distance
/// (Poisson-disk-like, through a grid) so that the density is even, the distance chosen so that n
/// points (±2 %) are expected after the `density` grading: the thinning counts each kept point by
/// its acceptance probability, so a graded cloud thins to about n / 0.55 points before the
/// grading keeps about n of them (a uniform cloud's count is unchanged: every weight is 1).
/// Normals: ∇f normalised (outward).
/// `holes` tori in a row along x (centres 2 · offset apart) make a surface of genus `holes`; the
/// double torus is holes = 2 (the same points for the same seed).
inline PointSet sample_multi_torus(std::size_t n, int holes, Density density = Density::Uniform,
                                   unsigned seed = 4, double R = 1.0, double r = 0.4,
                                   double offset = 1.2, double blend = 0.15) {
    struct Field {
        int holes;
        double R, r, offset, blend;
        double centre(int i) const { return (2.0 * i - (holes - 1)) * offset; }
        // Signed distance of the torus centred at (cx, 0, 0) and its gradient.
        double torus(const Vec3& p, double cx, Vec3& grad) const {
            const double x = p[0] - cx, y = p[1], z = p[2];
            const double rho = std::max(std::sqrt(x * x + y * y), 1e-12);
            const double a = rho - R, len = std::max(std::sqrt(a * a + z * z), 1e-12);
            grad = Vec3(a / len * x / rho, a / len * y / rho, z / len);
            return len - r;
        }
        // Smooth minimum of the tori from left to right (for two: smin(left, right)).
        double value(const Vec3& p, Vec3& grad) const {
            double a = torus(p, centre(0), grad);
            for (int i = 1; i < holes; ++i) {
                Vec3 ga = grad, gb;
                const double b = torus(p, centre(i), gb);
                const double h = std::clamp(0.5 + 0.5 * (b - a) / blend, 0.0, 1.0);
                grad = ga * h + gb * (1.0 - h); // exact gradient of the polynomial smooth minimum
                a = b + (a - b) * h - blend * h * (1.0 - h);
            }
            return a;
        }
    };
    const Field field{holes, R, r, offset, blend};
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> angle(0, 2 * M_PI), unit(0, 1);

    // Candidates: six times as many as wanted before the grading (a graded cloud keeps about
    // 0.55 of them, so it draws twice as many), projected on the surface.
    const std::size_t wanted_candidates = (density == Density::Graded ? 12 : 6) * n;
    std::vector<Vec3> candidates, normals;
    while (candidates.size() < wanted_candidates) {
        const double u = angle(rng), v = angle(rng);
        if (unit(rng) * (R + r) > R + r * std::cos(v)) continue;
        const double cx = field.centre(std::min(int(unit(rng) * holes), holes - 1));
        const Vec3 radial(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
        Vec3 p = Vec3(cx + std::cos(u) * R, std::sin(u) * R, 0.0) + radial * r, grad;
        double f = 0;
        for (int step = 0; step < 20; ++step) {
            f = field.value(p, grad);
            if (std::abs(f) < 1e-13) break;
            p -= grad * (f / grad.SquaredNorm());
        }
        f = field.value(p, grad);
        if (!(std::abs(f) < 1e-10) || grad.Norm() < 1e-6) continue; // did not converge
        candidates.push_back(p);
        normals.push_back(grad / grad.Norm());
    }

    // Minimum-distance thinning in candidate order (random), through a hash grid of cell = d.
    const auto thin = [&](double d, std::vector<std::size_t>& kept) {
        kept.clear();
        std::unordered_map<std::int64_t, std::vector<std::size_t>> grid;
        const auto cell = [&](const Vec3& p, int k) { return std::int64_t(std::floor(p[k] / d)); };
        const auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
            return ((i + 4096) * 8192 + (j + 4096)) * 8192 + (k + 4096);
        };
        for (std::size_t c = 0; c < candidates.size(); ++c) {
            const Vec3& p = candidates[c];
            const std::int64_t i = cell(p, 0), j = cell(p, 1), k = cell(p, 2);
            bool free = true;
            for (std::int64_t a = i - 1; a <= i + 1 && free; ++a)
                for (std::int64_t b = j - 1; b <= j + 1 && free; ++b)
                    for (std::int64_t e = k - 1; e <= k + 1 && free; ++e) {
                        const auto it = grid.find(key(a, b, e));
                        if (it == grid.end()) continue;
                        for (std::size_t q : it->second)
                            if ((candidates[q] - p).SquaredNorm() < d * d) free = false;
                    }
            if (!free) continue;
            grid[key(i, j, k)].push_back(c);
            kept.push_back(c);
        }
    };
    // The expected count after the grading scales roughly as 1/d²: correct the distance until
    // about n points are expected.
    const double extent = field.centre(holes - 1) + R + r;
    const auto expected_count = [&](const std::vector<std::size_t>& kept) {
        if (density == Density::Uniform) return double(kept.size());
        double sum = 0;
        for (std::size_t c : kept) sum += detail::acceptance(candidates[c], extent);
        return sum;
    };
    std::vector<std::size_t> kept;
    double d = 0.1;
    thin(d, kept);
    for (int round = 0; round < 8; ++round) {
        const double expected = expected_count(kept);
        if (std::abs(expected - double(n)) <= 0.02 * double(n)) break;
        d *= std::sqrt(expected / double(n));
        thin(d, kept);
    }

    PointSet s;
    s.precision = CoordinatePrecision::Double;
    for (std::size_t c : kept) {
        if (!detail::accept(candidates[c], extent, density, rng)) continue;
        s.positions.push_back(candidates[c]);
        s.normals.push_back(normals[c]);
    }
    return s;
}

/// The genus-2 surface above (holes = 2); see sample_multi_torus.
inline PointSet sample_double_torus(std::size_t n, Density density = Density::Uniform,
                                    unsigned seed = 4) {
    return sample_multi_torus(n, 2, density, seed);
}

/// n points of the grid's surface `shape` ("sphere", "torus", "double_torus", "triple_torus") with
/// the sizes the tests and bench/topology.sh use; std::invalid_argument for another name.
inline PointSet sample_surface(const std::string& shape, std::size_t n, Density density) {
    if (shape == "sphere") return sample_sphere(n, 1.0, Vec3(0, 0, 0), density);
    if (shape == "torus") return sample_torus(n, 1.0, 0.35, density);
    if (shape == "double_torus") return sample_multi_torus(n, 2, density);
    if (shape == "triple_torus") return sample_multi_torus(n, 3, density);
    throw std::invalid_argument("unknown shape '" + shape + "'");
}

/// Moves every point by isotropic Gaussian noise of standard deviation `sigma` (model units);
/// normals stay the exact ones of the clean surface.
inline void add_noise(PointSet& s, double sigma, unsigned seed = 5) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> gauss(0.0, sigma);
    for (Vec3& p : s.positions) p += Vec3(gauss(rng), gauss(rng), gauss(rng));
}

/// The bounding-box diagonal of the points.
inline double bounding_box_diagonal(const PointSet& s) {
    if (s.positions.empty()) return 0;
    Vec3 lo = s.positions[0], hi = s.positions[0];
    for (const Vec3& p : s.positions)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    return (hi - lo).Norm();
}

/// A jittered square grid in the z = 0 plane (an open disc-like patch with boundary).
inline PointSet sample_plane(std::size_t side, double spacing = 1.0, unsigned seed = 3) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(-0.2 * spacing, 0.2 * spacing);
    PointSet s;
    s.precision = CoordinatePrecision::Double;
    for (std::size_t i = 0; i < side; ++i)
        for (std::size_t j = 0; j < side; ++j) {
            s.positions.emplace_back(double(i) * spacing + jitter(rng),
                                     double(j) * spacing + jitter(rng), 0.0);
            s.normals.emplace_back(0, 0, 1);
        }
    return s;
}

/// Two open cones of height 1 meeting at their apex (an hourglass), sampled ring by ring with
/// `rings` rings each, the apex's normal across the axis: both cones reach the apex, which a
/// manifold mesh can only hold as two vertices (a vertex copy, §5.8).
inline PointSet sample_hourglass(int rings) {
    PointSet s;
    s.precision = CoordinatePrecision::Double;
    for (int side : {1, -1})
        for (int k = 1; k <= rings; ++k) {
            const double h = double(k) / rings;
            const int around = std::max(6, int(std::lround(2 * M_PI * k / std::sqrt(2.0))));
            const double twist = side > 0 ? 0.3 * k : 0.5 * k;
            for (int j = 0; j < around; ++j) {
                const double t = 2 * M_PI * j / around + twist;
                s.positions.emplace_back(h * std::cos(t), h * std::sin(t), side * h);
                s.normals.push_back(Vec3(std::cos(t), std::sin(t), -side) / std::sqrt(2.0));
            }
        }
    s.positions.emplace_back(0, 0, 0);
    s.normals.emplace_back(1, 0, 0);
    return s;
}

/// Appends `b` to `a` (normals kept only if both have them).
inline void append(PointSet& a, const PointSet& b) {
    const bool normals = a.has_normals() && b.has_normals();
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    if (normals)
        a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    else
        a.normals.clear();
}

inline PointSet without_normals(PointSet s) {
    s.normals.clear();
    return s;
}

} // namespace hrsr::testing
