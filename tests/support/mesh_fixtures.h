// Triangle meshes with known properties, for the tests of mesh checks.
#pragma once

#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

namespace hrsr::testing {

struct TestMesh {
    std::vector<Vec3> positions;
    std::vector<Triangle> triangles;
};

/// A UV sphere: two poles on the z axis and `rings` − 1 rings of `segments` vertices; closed,
/// genus 0, counter-clockwise seen from outside.
inline TestMesh uv_sphere(int rings = 16, int segments = 32, double radius = 1.0) {
    TestMesh m;
    m.positions.emplace_back(0, 0, radius);
    for (int i = 1; i < rings; ++i) {
        const double theta = M_PI * i / rings;
        for (int j = 0; j < segments; ++j) {
            const double phi = 2 * M_PI * j / segments;
            m.positions.emplace_back(radius * std::sin(theta) * std::cos(phi),
                                     radius * std::sin(theta) * std::sin(phi),
                                     radius * std::cos(theta));
        }
    }
    m.positions.emplace_back(0, 0, -radius);
    const auto ring = [&](int i, int j) {
        return std::uint32_t(1 + (i - 1) * segments + (j % segments));
    };
    const std::uint32_t south = std::uint32_t(m.positions.size() - 1);
    for (int j = 0; j < segments; ++j) {
        m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
        m.triangles.push_back({south, ring(rings - 1, j + 1), ring(rings - 1, j)});
        for (int i = 1; i + 1 < rings; ++i) {
            m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
            m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
        }
    }
    return m;
}

/// A torus around the z axis (ring radius R, tube radius r) on a periodic nu × nv grid;
/// closed, genus 1, counter-clockwise seen from outside.
inline TestMesh torus(int nu = 32, int nv = 16, double R = 1.0, double r = 0.3) {
    TestMesh m;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
            m.positions.emplace_back((R + r * std::cos(v)) * std::cos(u),
                                     (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
        }
    const auto at = [&](int i, int j) { return std::uint32_t((i % nu) * nv + (j % nv)); };
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return m;
}

/// A flat square patch in the plane z = `z`: (n+1)² vertices with spacing 1/n on [0,1]², two
/// triangles per cell, counter-clockwise seen from +z; one boundary loop of 4n edges.
inline TestMesh square_patch(int n = 8, double z = 0.0) {
    TestMesh m;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) m.positions.emplace_back(double(i) / n, double(j) / n, z);
    const auto at = [&](int i, int j) { return std::uint32_t(i * (n + 1) + j); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return m;
}

/// `m` moved by `d`.
inline TestMesh shifted(TestMesh m, const Vec3& d) {
    for (Vec3& p : m.positions) p += d;
    return m;
}

/// The vertices some triangle uses: a repair that keeps every point keeps this set.
inline std::set<std::uint32_t> used_vertices(const std::vector<Triangle>& triangles) {
    std::set<std::uint32_t> used;
    for (const Triangle& t : triangles) used.insert(t.begin(), t.end());
    return used;
}

} // namespace hrsr::testing
