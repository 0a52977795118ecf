#include "mesh/triangle_intersection.h"

#include "mesh/exact_predicates.h"

#include <algorithm>

namespace hrsr {

namespace {

using exact::orient2d;
using exact::orient3d;

// Two coordinate axes on which a plane projects one to one (its normal is not orthogonal to
// the third): coplanar figures meet exactly when their projections there do.
struct Axes {
    int i, j;
};

Axes projection_keeping_area(const Corners& t) {
    for (int dropped : {2, 0, 1})
        if (orient2d(t[0], t[1], t[2], (dropped + 1) % 3, (dropped + 2) % 3) != 0)
            return {(dropped + 1) % 3, (dropped + 2) % 3};
    return {0, 1}; // not reached for a non-degenerate triangle
}

// r, collinear with p and q in the projection, lies between them.
bool between(const Vec3& p, const Vec3& q, const Vec3& r, Axes ax) {
    for (int k : {ax.i, ax.j})
        if (r[k] < std::min(p[k], q[k]) || r[k] > std::max(p[k], q[k])) return false;
    return true;
}

// Closed segments pq and rs of one plane, in its projection.
bool segments_meet_2d(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s, Axes ax) {
    const int r_side = orient2d(p, q, r, ax.i, ax.j), s_side = orient2d(p, q, s, ax.i, ax.j),
              p_side = orient2d(r, s, p, ax.i, ax.j), q_side = orient2d(r, s, q, ax.i, ax.j);
    if ((r_side == 0 && between(p, q, r, ax)) || (s_side == 0 && between(p, q, s, ax)) ||
        (p_side == 0 && between(r, s, p, ax)) || (q_side == 0 && between(r, s, q, ax)))
        return true;
    return r_side * s_side < 0 && p_side * q_side < 0;
}

// p in the closed triangle t (not degenerate in the projection).
bool inside_2d(const Vec3& p, const Corners& t, Axes ax) {
    const int s0 = orient2d(t[0], t[1], p, ax.i, ax.j), s1 = orient2d(t[1], t[2], p, ax.i, ax.j),
              s2 = orient2d(t[2], t[0], p, ax.i, ax.j);
    return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

bool segment_meets_triangle_2d(const Vec3& p, const Vec3& q, const Corners& t, Axes ax) {
    if (inside_2d(p, t, ax)) return true;
    for (int k = 0; k < 3; ++k)
        if (segments_meet_2d(p, q, t[k], t[(k + 1) % 3], ax)) return true;
    return false;
}

bool triangles_meet_2d(const Corners& a, const Corners& b, Axes ax) {
    if (inside_2d(a[0], b, ax) || inside_2d(b[0], a, ax)) return true;
    for (int k = 0; k < 3; ++k)
        if (segment_meets_triangle_2d(a[k], a[(k + 1) % 3], b, ax)) return true;
    return false;
}

// Closed segment pq against the closed triangle t, given the sides of p and q of t's plane.
bool segment_meets_triangle(const Vec3& p, const Vec3& q, int p_side, int q_side,
                            const Corners& t) {
    if (p_side * q_side > 0) return false;
    if (p_side == 0 && q_side == 0)
        return segment_meets_triangle_2d(p, q, t, projection_keeping_area(t));
    // The line pq crosses the plane once, within the segment: it passes through the triangle
    // when it passes no edge on the other side than the others.
    const int s0 = orient3d(p, q, t[0], t[1]), s1 = orient3d(p, q, t[1], t[2]),
              s2 = orient3d(p, q, t[2], t[0]);
    return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

std::array<int, 3> sides(const Corners& plane, const Corners& t) {
    return {orient3d(plane[0], plane[1], plane[2], t[0]),
            orient3d(plane[0], plane[1], plane[2], t[1]),
            orient3d(plane[0], plane[1], plane[2], t[2])};
}

bool one_strict_side(const std::array<int, 3>& s) {
    return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0);
}

// Closed triangles with no shared corner. In distinct planes the two meet on the planes' line,
// where one triangle's stretch ends at its boundary inside the other: an edge of one meets the
// other triangle.
bool triangles_meet(const Corners& a, const Corners& b) {
    const std::array<int, 3> b_sides = sides(a, b);
    if (one_strict_side(b_sides)) return false;
    const std::array<int, 3> a_sides = sides(b, a);
    if (one_strict_side(a_sides)) return false;
    if (b_sides == std::array<int, 3>{0, 0, 0})
        return triangles_meet_2d(a, b, projection_keeping_area(a));
    for (int k = 0; k < 3; ++k) {
        const int n = (k + 1) % 3;
        if (segment_meets_triangle(a[k], a[n], a_sides[k], a_sides[n], b) ||
            segment_meets_triangle(b[k], b[n], b_sides[k], b_sides[n], a))
            return true;
    }
    return false;
}

// Corner ka of a is corner kb of b. They meet elsewhere exactly when the edge of one opposite
// the shared corner meets the other (the stretch they share ends on such an edge).
bool meet_beyond_shared_corner(const Corners& a, int ka, const Corners& b, int kb) {
    const Vec3 &a1 = a[(ka + 1) % 3], &a2 = a[(ka + 2) % 3];
    const Vec3 &b1 = b[(kb + 1) % 3], &b2 = b[(kb + 2) % 3];
    const int b1_side = orient3d(a[0], a[1], a[2], b1), b2_side = orient3d(a[0], a[1], a[2], b2);
    // b's other corners strictly on one side of a's plane: b touches that plane at the shared
    // corner only, so a cannot meet it elsewhere (most neighbours in a fan end here).
    if (b1_side * b2_side > 0) return false;
    return segment_meets_triangle(b1, b2, b1_side, b2_side, a) ||
           segment_meets_triangle(a1, a2, orient3d(b[0], b[1], b[2], a1),
                                  orient3d(b[0], b[1], b[2], a2), b);
}

// Corners ka of a (not shared) and kb of b are opposite the shared edge uv: the triangles
// overlap when they are coplanar and on the same side of the edge.
bool overlap_across_shared_edge(const Corners& a, int ka, const Vec3& opposite_b) {
    if (orient3d(a[0], a[1], a[2], opposite_b) != 0) return false;
    const Axes ax = projection_keeping_area(a);
    const Vec3 &u = a[(ka + 1) % 3], &v = a[(ka + 2) % 3];
    return orient2d(u, v, a[ka], ax.i, ax.j) * orient2d(u, v, opposite_b, ax.i, ax.j) > 0;
}

} // namespace

bool collinear_corners(const Vec3& a, const Vec3& b, const Vec3& c) {
    return exact::collinear(a, b, c);
}

bool mesh_triangles_intersect(const Corners& a, const Triangle& ia, const Corners& b,
                              const Triangle& ib) {
    int shared = 0, ka = 0, kb = 0;     // the last shared corner
    int unshared_a = 0, unshared_b = 0; // a corner of each that is not shared
    for (int i = 0; i < 3; ++i) {
        bool in_b = false;
        for (int j = 0; j < 3; ++j)
            if (ia[i] == ib[j]) {
                in_b = true;
                ++shared;
                ka = i;
                kb = j;
            }
        if (!in_b) unshared_a = i;
    }
    if (shared == 0) return triangles_meet(a, b);
    if (shared == 1) return meet_beyond_shared_corner(a, ka, b, kb);
    if (shared == 3) return true; // a duplicate face (D-32: a fin through a copy)
    for (int j = 0; j < 3; ++j)
        if (ib[j] != ia[0] && ib[j] != ia[1] && ib[j] != ia[2]) unshared_b = j;
    return overlap_across_shared_edge(a, unshared_a, b[unshared_b]);
}

} // namespace hrsr
