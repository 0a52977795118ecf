// Folded meshes with float coordinates (as a PLY file stores them): the fixtures of the exact
// self-intersection test and of its agreement with CGAL.
#pragma once

#include "mesh_fixtures.h"

#include <array>

namespace hrsr::testing {

/// `m` with every coordinate rounded to float.
inline TestMesh as_floats(TestMesh m) {
    for (Vec3& p : m.positions)
        for (int k = 0; k < 3; ++k) p[k] = double(float(p[k]));
    return m;
}

/// A square patch bent to z = h(x, y).
template <class Height>
TestMesh height_patch(int n, Height h) {
    TestMesh m = square_patch(n);
    for (Vec3& p : m.positions) p[2] = h(p[0], p[1]);
    return m;
}

/// A bowl whose centre vertex is pushed sideways past its neighbours and just under the surface
/// there: its fan crosses the triangles it now lies under.
inline TestMesh pushed_vertex() {
    const auto bowl = [](double x, double y) {
        return 0.25 * (x - 0.5) * (x - 0.5) + 0.15 * (y - 0.5) * (y - 0.5);
    };
    TestMesh m = height_patch(6, bowl);
    Vec3& centre = m.positions[3 * 7 + 3];
    centre = Vec3(0.8, 0.53, bowl(0.8, 0.53) - 0.005);
    return as_floats(m);
}

/// Two sheets 0.002 apart at their edges, crossing along x = 0.5 at a shallow angle.
inline TestMesh crossing_sheets() {
    TestMesh m = height_patch(8, [](double x, double) { return 0.001 * (x - 0.5); });
    const TestMesh other =
        shifted(height_patch(8, [](double x, double) { return -0.001 * (x - 0.5); }),
                Vec3(0.031, 0.047, 0));
    const auto offset = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
    for (Triangle f : other.triangles) {
        for (std::uint32_t& v : f) v += offset;
        m.triangles.push_back(f);
    }
    return as_floats(m);
}

/// A bent patch whose boundary vertex (1, 0.5) is folded back over the patch, just under it.
inline TestMesh boundary_fold() {
    const auto bend = [](double x, double) { return 0.2 * x * x; };
    TestMesh m = height_patch(4, bend);
    m.positions[4 * 5 + 2] = Vec3(0.55, 0.55, bend(0.55, 0) - 0.005);
    return as_floats(m);
}

/// A bent patch with a fin: a face folded back onto a border face across its border edge, its
/// third corner a copy of that face's (two faces on one place, as a pinched point's copies can
/// leave them; ALGORITHM.md D-32).
inline TestMesh fin_through_a_copy() {
    TestMesh m = height_patch(4, [](double x, double) { return 0.2 * x * x; });
    const Triangle border_face = m.triangles[8]; // (1, 0), (2, 0), (2, 1): first edge on y = 0
    const auto copy = std::uint32_t(m.positions.size());
    m.positions.push_back(m.positions[border_face[2]]);
    m.triangles.push_back({border_face[1], border_face[0], copy});
    return as_floats(m);
}

/// Two overlapping spheres (a circle of crossings) and a triangle piercing the first.
inline TestMesh overlapping_spheres() {
    TestMesh m = uv_sphere(20, 40);
    const TestMesh other = shifted(uv_sphere(20, 40, 0.8), Vec3(0.9, 0.1, 0.05));
    const auto offset = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
    for (Triangle f : other.triangles) {
        for (std::uint32_t& v : f) v += offset;
        m.triangles.push_back(f);
    }
    const auto last = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(),
                       {Vec3(-0.2, 0.1, 0.3), Vec3(-2, 0, 0.3), Vec3(-2, 0.3, 0.35)});
    m.triangles.push_back({last, last + 1, last + 2});
    return m;
}

/// Four float points exactly on the plane x + y + z = 1024, the fourth inside the triangle of
/// the first three (seen along z), where the double evaluation of ((b-a) × (c-a)) · (d-a) is
/// not 0 (found by a random search).
inline std::array<Vec3, 4> coplanar_float_points() {
    return {Vec3(0x1.cb2c8ep+8, 0x1.659e74p+8, 0x1.9e69fcp+7),
            Vec3(0x1.b6e594p+8, 0x1.d69d94p+8, 0x1.c9f36p+6),
            Vec3(0x1.2585ccp+8, 0x1.c89dc6p+8, 0x1.11dc6ep+8),
            Vec3(0x1.a7fb16p+8, 0x1.a3663p+8, 0x1.693d74p+7)};
}

/// Two triangles sharing the edge of the first two coplanar_float_points(), folded flat onto
/// each other (the second's third corner inside the first).
inline TestMesh flat_fold_on_floats() {
    const std::array<Vec3, 4> p = coplanar_float_points();
    return {{p[0], p[1], p[2], p[3]}, {{0, 1, 2}, {1, 0, 3}}};
}

/// A triangle whose corner touches the inside of another exactly, coordinates as in
/// coplanar_float_points(); the other two corners are far above.
inline TestMesh touching_on_floats() {
    const std::array<Vec3, 4> p = coplanar_float_points();
    return {{p[0], p[1], p[2], p[3], p[3] + Vec3(10, 0, 40), p[3] + Vec3(0, 10, 40)},
            {{0, 1, 2}, {3, 4, 5}}};
}

} // namespace hrsr::testing
