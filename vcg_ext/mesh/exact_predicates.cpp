#include "mesh/exact_predicates.h"

#include <gmpxx.h>

#include <cmath>

namespace hrsr::exact {

namespace {

// Half a unit in the last place of 1.0, Shewchuk's "epsilon" (1997, §4.2).
constexpr double kEpsilon = 0x1p-53;
// Shewchuk's first-stage bounds: |det - computed det| <= bound × permanent.
constexpr double kOrient2dBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
constexpr double kOrient3dBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;
// The bounds assume no underflow; below this permanent the exact path decides.
constexpr double kSmallestTrustedPermanent = 1e-250;

int sign(double x) {
    return (x > 0) - (x < 0);
}
int sign(const mpq_class& x) {
    return sgn(x);
}

// Whether the filter may decide: |det| beyond the bound (false for NaN or infinity too).
bool decided(double det, double permanent, double bound) {
    return permanent >= kSmallestTrustedPermanent && std::abs(det) > bound * permanent;
}

// mpq_class(double) converts exactly; the differences below are then exact as well.
int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    mpq_class m[3][3];
    for (int k = 0; k < 3; ++k) {
        m[0][k] = mpq_class(b[k]) - mpq_class(a[k]);
        m[1][k] = mpq_class(c[k]) - mpq_class(a[k]);
        m[2][k] = mpq_class(d[k]) - mpq_class(a[k]);
    }
    const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sign(det);
}

int orient2d_exact(const Vec3& a, const Vec3& b, const Vec3& c, int i, int j) {
    const mpq_class ax(a[i]), ay(a[j]);
    const mpq_class det = (mpq_class(b[i]) - ax) * (mpq_class(c[j]) - ay) -
                          (mpq_class(b[j]) - ay) * (mpq_class(c[i]) - ax);
    return sign(det);
}

} // namespace

int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    // Shewchuk's orient3d relative to d, whose sign is the opposite of ours.
    const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
    const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
    const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
    const double bc = bdx * cdy, cb = cdx * bdy, ca = cdx * ady, ac = adx * cdy, ab = adx * bdy,
                 ba = bdx * ady;
    const double det = adz * (bc - cb) + bdz * (ca - ac) + cdz * (ab - ba);
    const double permanent = (std::abs(bc) + std::abs(cb)) * std::abs(adz) +
                             (std::abs(ca) + std::abs(ac)) * std::abs(bdz) +
                             (std::abs(ab) + std::abs(ba)) * std::abs(cdz);
    if (decided(det, permanent, kOrient3dBound)) return -sign(det);
    return orient3d_exact(a, b, c, d);
}

int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int i, int j) {
    const double left = (b[i] - a[i]) * (c[j] - a[j]), right = (b[j] - a[j]) * (c[i] - a[i]);
    const double det = left - right;
    if (decided(det, std::abs(left) + std::abs(right), kOrient2dBound)) return sign(det);
    return orient2d_exact(a, b, c, i, j);
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
    // On one line exactly when the projections on all three coordinate planes are.
    return orient2d(a, b, c, 0, 1) == 0 && orient2d(a, b, c, 1, 2) == 0 &&
           orient2d(a, b, c, 2, 0) == 0;
}

} // namespace hrsr::exact
