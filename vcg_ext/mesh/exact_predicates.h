// Exact orientation signs on double coordinates, for the self-intersection test.
#pragma once

#include "point_set.h"

namespace hrsr::exact {

/// The sign (1, 0 or -1) of ((b - a) × (c - a)) · (d - a): 1 when d lies on the side that the
/// normal of abc (right hand) points to, 0 when the four points are coplanar. Exact for finite
/// coordinates: a floating-point evaluation decides when Shewchuk's error bound allows it,
/// exact integer arithmetic (GMP) otherwise.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The sign of the same in the coordinate plane of axes (i, j): 1 when a, b, c turn
/// counter-clockwise with axis i to the right and axis j up, 0 when they are collinear there.
int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int i, int j);

/// The sign of a 2-D orientation determinant `left − right` whose two products were evaluated in
/// doubles from coordinate differences ((b_i − a_i)(c_j − a_j) and (b_j − a_j)(c_i − a_i), as
/// orient2d() does), when Shewchuk's error bound decides it; 2 when only orient2d() can. Lets a
/// caller that has the products already skip the call.
int orient2d_filtered(double left, double right);

/// orient3d(a, b, c, d) for many d against one plane abc, the plane's part of the determinant
/// evaluated once: side(d) is its sign where Shewchuk's error bound for orient3d decides it (the
/// same form of determinant, rows d − a, b − a, c − a), 2 where only orient3d() can.
class PlaneSides {
public:
    PlaneSides(const Vec3& a, const Vec3& b, const Vec3& c);
    int side(const Vec3& d) const;

private:
    Vec3 a_;
    Vec3 normal_;         ///< (b − a) × (c − a), each component a difference of two products
    Vec3 permanent_;      ///< per component, the sum of those products' magnitudes
    bool trusted_ = true; ///< no product of the minors can have underflowed
};

/// Whether a, b, c lie on one line (two or three of them coinciding included), exactly.
bool collinear(const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace hrsr::exact
