// Point clouds sampled from analytic surfaces, with exact outward normals, for tests.
#pragma once

#include "point_set.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace hrsr::testing {

/// Density of the samples: uniform over the surface area, or denser towards one side
/// (acceptance probability from 1 down to 0.1 along x) to test non-uniform sampling.
enum class Density { Uniform, Graded };

namespace detail {
inline bool accept(const Vec3& p, double extent, Density density, std::mt19937_64& rng) {
    if (density == Density::Uniform) return true;
    const double u = std::clamp((p[0] / extent + 1.0) / 2.0, 0.0, 1.0);
    return std::uniform_real_distribution<double>(0, 1)(rng) < 1.0 - 0.9 * u;
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
