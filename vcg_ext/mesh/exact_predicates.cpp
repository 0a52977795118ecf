#include "mesh/exact_predicates.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

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

// Whether the filter may decide: |det| beyond the bound (false for NaN or infinity too).
bool decided(double det, double permanent, double bound) {
    return permanent >= kSmallestTrustedPermanent && std::abs(det) > bound * permanent;
}

// The coordinates as integers over one common power of two, exactly (doubles are dyadic):
// integer arithmetic then needs no fractions to reduce. Each value is its 53-bit mantissa,
// shifted by its exponent's distance above the lowest.
template <std::size_t N>
std::array<mpz_class, N> on_common_scale(const std::array<double, N>& values) {
    constexpr int kMantissaBits = 53;
    int lowest = std::numeric_limits<int>::max();
    for (double x : values)
        if (x != 0) {
            int e = 0;
            std::frexp(x, &e);
            lowest = std::min(lowest, e);
        }
    std::array<mpz_class, N> scaled;
    for (std::size_t k = 0; k < N; ++k) {
        if (values[k] == 0) continue;
        int e = 0;
        scaled[k] = std::ldexp(std::frexp(values[k], &e), kMantissaBits); // an integer
        mpz_mul_2exp(scaled[k].get_mpz_t(), scaled[k].get_mpz_t(), mp_bitcnt_t(e - lowest));
    }
    return scaled;
}

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const std::array<mpz_class, 12> v = on_common_scale<12>(
        {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]});
    mpz_class m[3][3];
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) m[r][k] = v[std::size_t(3 * (r + 1) + k)] - v[std::size_t(k)];
    const mpz_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sgn(det);
}

int orient2d_exact(const Vec3& a, const Vec3& b, const Vec3& c, int i, int j) {
    const std::array<mpz_class, 6> v = on_common_scale<6>({a[i], a[j], b[i], b[j], c[i], c[j]});
    const mpz_class det = (v[2] - v[0]) * (v[5] - v[1]) - (v[3] - v[1]) * (v[4] - v[0]);
    return sgn(det);
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
