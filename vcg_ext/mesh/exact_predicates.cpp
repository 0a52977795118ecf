#include "mesh/exact_predicates.h"

#include <gmp.h>

#include <algorithm>
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

// Integers of GMP, kept per thread with room for typical coordinates: line and depth scanners
// put points exactly on planes and lines, so the exact path runs for many pairs there (a Kinect
// frame's fold search was two thirds allocation and conversion with temporaries).
class Scratch {
public:
    static constexpr int kValues = 12, kBits = 512;
    Scratch() {
        for (mpz_t& z : z_) mpz_init2(z, kBits);
    }
    ~Scratch() {
        for (mpz_t& z : z_) mpz_clear(z);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
    mpz_t& operator[](int k) { return z_[k]; }

    // values[k] as integers over one common power of two, exactly (doubles are dyadic): each is
    // its 53-bit mantissa, shifted by its exponent's distance above the lowest.
    void set_on_common_scale(const double* values, int n) {
        constexpr int kMantissaBits = 53;
        int lowest = std::numeric_limits<int>::max();
        for (int k = 0; k < n; ++k)
            if (values[k] != 0) {
                int e = 0;
                std::frexp(values[k], &e);
                lowest = std::min(lowest, e);
            }
        for (int k = 0; k < n; ++k) {
            int e = 0;
            const double mantissa = std::frexp(values[k], &e);
            // An integer below 2^53: exact in mpz_set_d (a long may have 32 bits); 0 stays 0.
            mpz_set_d(z_[k], std::ldexp(mantissa, kMantissaBits));
            if (values[k] != 0) mpz_mul_2exp(z_[k], z_[k], mp_bitcnt_t(e - lowest));
        }
    }

private:
    mpz_t z_[kValues + 9 + 2];
};

thread_local Scratch scratch;

int orient3d_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const double values[12] = {a[0], a[1], a[2], b[0], b[1], b[2],
                               c[0], c[1], c[2], d[0], d[1], d[2]};
    Scratch& z = scratch;
    z.set_on_common_scale(values, 12);
    // Rows b - a, c - a, d - a into slots 12 … 20; the minors' products into 21 and 22.
    auto m = [&](int r, int k) -> mpz_t& { return z[12 + 3 * r + k]; };
    for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) mpz_sub(m(r, k), z[3 * (r + 1) + k], z[k]);
    mpz_t &minor = z[21], &det = z[22];
    mpz_mul(minor, m(1, 1), m(2, 2));
    mpz_submul(minor, m(1, 2), m(2, 1));
    mpz_mul(det, m(0, 0), minor);
    mpz_mul(minor, m(1, 0), m(2, 2));
    mpz_submul(minor, m(1, 2), m(2, 0));
    mpz_submul(det, m(0, 1), minor);
    mpz_mul(minor, m(1, 0), m(2, 1));
    mpz_submul(minor, m(1, 1), m(2, 0));
    mpz_addmul(det, m(0, 2), minor);
    return mpz_sgn(det);
}

int orient2d_exact(const Vec3& a, const Vec3& b, const Vec3& c, int i, int j) {
    const double values[6] = {a[i], a[j], b[i], b[j], c[i], c[j]};
    Scratch& z = scratch;
    z.set_on_common_scale(values, 6);
    // (b - a) in 12, 13 and (c - a) in 14, 15; the determinant in 22.
    mpz_sub(z[12], z[2], z[0]);
    mpz_sub(z[13], z[3], z[1]);
    mpz_sub(z[14], z[4], z[0]);
    mpz_sub(z[15], z[5], z[1]);
    mpz_mul(z[22], z[12], z[15]);
    mpz_submul(z[22], z[13], z[14]);
    return mpz_sgn(z[22]);
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

PlaneSides::PlaneSides(const Vec3& a, const Vec3& b, const Vec3& c) : a_(a) {
    const Vec3 u = b - a, v = c - a;
    // A minor's product that underflowed, multiplied by a large difference d − a, would carry
    // an error the bound does not hold: with every difference zero or within 2^±400 none can
    // (products of coordinates given in floats never do). Else only orient3d() decides.
    for (int k = 0; k < 3; ++k)
        for (const double x : {u[k], v[k]})
            if (x != 0 && !(std::abs(x) >= 0x1p-400 && std::abs(x) <= 0x1p400)) trusted_ = false;
    const double yz = u[1] * v[2], zy = u[2] * v[1], zx = u[2] * v[0], xz = u[0] * v[2],
                 xy = u[0] * v[1], yx = u[1] * v[0];
    normal_ = Vec3(yz - zy, zx - xz, xy - yx);
    permanent_ =
        Vec3(std::abs(yz) + std::abs(zy), std::abs(zx) + std::abs(xz), std::abs(xy) + std::abs(yx));
}

int PlaneSides::side(const Vec3& d) const {
    // orient3d's determinant expanded along the row d − a instead of a column: three rounded
    // differences times 2 × 2 minors of rounded differences, summed, as Shewchuk's bound assumes.
    if (!trusted_) return 2;
    const double wx = d[0] - a_[0], wy = d[1] - a_[1], wz = d[2] - a_[2];
    const double det = wx * normal_[0] + wy * normal_[1] + wz * normal_[2];
    const double permanent =
        std::abs(wx) * permanent_[0] + std::abs(wy) * permanent_[1] + std::abs(wz) * permanent_[2];
    return decided(det, permanent, kOrient3dBound) ? sign(det) : 2;
}

int orient2d_filtered(double left, double right) {
    const double det = left - right;
    return decided(det, std::abs(left) + std::abs(right), kOrient2dBound) ? sign(det) : 2;
}

int orient2d(const Vec3& a, const Vec3& b, const Vec3& c, int i, int j) {
    const int filtered =
        orient2d_filtered((b[i] - a[i]) * (c[j] - a[j]), (b[j] - a[j]) * (c[i] - a[i]));
    return filtered != 2 ? filtered : orient2d_exact(a, b, c, i, j);
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
    // On one line exactly when the projections on all three coordinate planes are.
    return orient2d(a, b, c, 0, 1) == 0 && orient2d(a, b, c, 1, 2) == 0 &&
           orient2d(a, b, c, 2, 0) == 0;
}

} // namespace hrsr::exact
