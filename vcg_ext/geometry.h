// Geometric primitives shared by all stages (ALGORITHM.md §3).
#pragma once

#include "options.h"
#include "point_set.h"

#include <cmath>

namespace hrsr {

/// An orthonormal tangent basis (t1, t2) of a unit normal n, with t1 × t2 = n.
struct TangentFrame {
    Vec3 t1, t2;
};

/// Branch-free basis of Duff et al. 2017 (D-1): computed from the normal alone, so the same
/// normal always gives the same frame. Also defined (arbitrarily, deterministically) for n = 0.
inline TangentFrame tangent_frame(const Vec3& n) {
    const double sign = std::copysign(1.0, n[2]);
    const double a = -1.0 / (sign + n[2]);
    const double b = n[0] * n[1] * a;
    return {Vec3(1.0 + sign * n[0] * n[0] * a, sign * b, -sign * n[0]),
            Vec3(b, sign + n[1] * n[1] * a, -n[1])};
}

/// Rotation angle in [0, 2π) of direction d around the frame's normal, counter-clockwise from
/// t1 seen from the tip of the normal (D-1). A direction whose tangent projection is shorter
/// than 1e-12 (in normalised units, D-2) is degenerate and gets angle 0.
inline double rotation_angle(const TangentFrame& f, const Vec3& d) {
    const double x = d.dot(f.t1), y = d.dot(f.t2);
    if (x * x + y * y < 1e-24) return 0.0;
    const double angle = std::atan2(y, x);
    return angle < 0 ? angle + 2.0 * M_PI : angle;
}

/// Counter-clockwise angle from rotation angle `from` to rotation angle `to`, in [0, 2π).
inline double ccw_angle(double from, double to) {
    const double d = to - from;
    return d < 0 ? d + 2.0 * M_PI : d;
}

/// Tangent ("projection") distance of §3.2 for e = q − p with unit normals n_p, n_q.
inline double tangent_distance(const Vec3& e, const Vec3& np, const Vec3& nq) {
    static const double kSwitch = std::cos(15.0 * M_PI / 180.0);
    const double e2 = e.SquaredNorm();
    if (std::abs(np.dot(nq)) < kSwitch) return std::sqrt(e2);
    const double hp = e.dot(np), hq = e.dot(nq);
    return 0.5 * (std::sqrt(std::max(0.0, e2 - hp * hp)) + std::sqrt(std::max(0.0, e2 - hq * hq)));
}

/// Edge length in the given mode between points p and q with unit normals np and nq.
inline double edge_length(DistanceMode mode, const Vec3& p, const Vec3& q, const Vec3& np,
                          const Vec3& nq) {
    return mode == DistanceMode::Tangent ? tangent_distance(q - p, np, nq) : (q - p).Norm();
}

/// A segment between two points of a surface, with the unit normals at its endpoints.
struct SurfaceSegment {
    const Vec3& a;
    const Vec3& b;
    const Vec3& na;
    const Vec3& nb;
};

/// Whether segment ab crosses segment cd "in the tangent plane" (§3.4): tested in the planes
/// orthogonal to the half-sums of the endpoint normals of each segment; touching or collinear
/// counts as crossing (conservative). Segments must not share an endpoint.
bool segments_cross(const SurfaceSegment& ab, const SurfaceSegment& cd);

/// segments_cross(ab, cd) for one ab and many cd: ab's plane and its direction in that plane are
/// worked out once (RsR's geometry check tests each candidate against every edge near it).
class SegmentCrossings {
public:
    explicit SegmentCrossings(const SurfaceSegment& ab);
    bool crossed_by(const SurfaceSegment& cd) const;

private:
    Vec3 a_, b_;
    TangentFrame frame_; ///< of ab's plane
    double bx_, by_;     ///< b − a in that frame
};

/// Largest interior angle of triangle abc, in radians (π for degenerate triangles).
double largest_angle(const Vec3& a, const Vec3& b, const Vec3& c);

/// The smallest interior angle of triangle (a, b, c) in radians; 0 when two corners coincide.
double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace hrsr
