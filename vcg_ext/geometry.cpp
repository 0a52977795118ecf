#include "geometry.h"

#include <algorithm>
#include <cmath>

namespace hrsr {

namespace {

// Side of point p relative to the line from a along (bx, by), in the plane with basis (t1, t2).
double side_along(const TangentFrame& f, const Vec3& a, double bx, double by, const Vec3& p) {
    const double px = (p - a).dot(f.t1), py = (p - a).dot(f.t2);
    return bx * py - by * px;
}

// Side of point p relative to the directed line a→b, in the plane with basis (t1, t2).
double side(const TangentFrame& f, const Vec3& a, const Vec3& b, const Vec3& p) {
    return side_along(f, a, (b - a).dot(f.t1), (b - a).dot(f.t2), p);
}

TangentFrame plane_frame(const Vec3& plane_normal) {
    const double length = plane_normal.Norm();
    return tangent_frame(length > 0 ? plane_normal / length : plane_normal);
}

bool cross_in_plane(const Vec3& plane_normal, const Vec3& a, const Vec3& b, const Vec3& c,
                    const Vec3& d) {
    const TangentFrame f = plane_frame(plane_normal);
    return side(f, a, b, c) * side(f, a, b, d) <= 0 && side(f, c, d, a) * side(f, c, d, b) <= 0;
}

} // namespace

bool segments_cross(const SurfaceSegment& ab, const SurfaceSegment& cd) {
    return cross_in_plane((ab.na + ab.nb) * 0.5, ab.a, ab.b, cd.a, cd.b) ||
           cross_in_plane((cd.na + cd.nb) * 0.5, ab.a, ab.b, cd.a, cd.b);
}

SegmentCrossings::SegmentCrossings(const SurfaceSegment& ab)
    : a_(ab.a), b_(ab.b), frame_(plane_frame((ab.na + ab.nb) * 0.5)), bx_((b_ - a_).dot(frame_.t1)),
      by_((b_ - a_).dot(frame_.t2)) {}

// The same arithmetic as segments_cross, in the same order: the same answers to the bit.
bool SegmentCrossings::crossed_by(const SurfaceSegment& cd) const {
    if (side_along(frame_, a_, bx_, by_, cd.a) * side_along(frame_, a_, bx_, by_, cd.b) <= 0 &&
        side(frame_, cd.a, cd.b, a_) * side(frame_, cd.a, cd.b, b_) <= 0)
        return true;
    return cross_in_plane((cd.na + cd.nb) * 0.5, a_, b_, cd.a, cd.b);
}

namespace {
// The angle at `apex` of the triangle (apex, p, q); `degenerate` when a side has no length.
double corner_angle(const Vec3& apex, const Vec3& p, const Vec3& q, double degenerate) {
    const Vec3 u = p - apex, v = q - apex;
    const double nu = u.Norm(), nv = v.Norm();
    if (nu == 0 || nv == 0) return degenerate;
    return std::acos(std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0));
}
} // namespace

double largest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    return std::max(
        {corner_angle(a, b, c, M_PI), corner_angle(b, c, a, M_PI), corner_angle(c, a, b, M_PI)});
}

double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    if (a == b || b == c || c == a) return 0;
    const auto angle = [](const Vec3& u, const Vec3& v) {
        return std::atan2((u ^ v).Norm(), u.dot(v)); // accurate near 0 and π, unlike acos
    };
    // The smallest angle is opposite the shortest side: one angle to compute, not three.
    const double ab = (b - a).SquaredNorm(), bc = (c - b).SquaredNorm(), ca = (a - c).SquaredNorm();
    if (bc <= ab && bc <= ca) return angle(b - a, c - a);
    if (ca <= ab) return angle(c - b, a - b);
    return angle(a - c, b - c);
}

} // namespace hrsr
