#include "mesh/embedded_fans.h"

#include "mesh/exact_predicates.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hrsr {

namespace {

// The sector of face (v, from, to) at v: from `from` to `to` in the face's turning sense, with
// the differences from v to both (rounded; their signs are exact).
struct Sector {
    std::uint32_t from, to;
    Vec3 to_from, to_to;
};

// Fans of more faces are left to the pair test (a vertex of a reconstructed surface has about
// six).
constexpr std::uint32_t kMaxFaces = 24;

class FanCertifier {
public:
    FanCertifier(const TriangleGeometry& g, const VertexCorners& corners)
        : g_(g), corners_(corners) {}

    bool embedded(std::uint32_t v) {
        const std::uint32_t begin = corners_.begin(v);
        count_ = corners_.end(v) - begin;
        if (count_ < 3 || count_ > kMaxFaces) return false; // no closed fan has fewer faces
        const Vec3& p = g_.position(v);
        Vec3 normal(0, 0, 0); // the direction to look along first
        for (std::uint32_t c = 0; c < count_; ++c) {
            const std::uint32_t corner = corners_.corner[begin + c];
            const Triangle& t = g_.triangle(corner / 3);
            const std::uint32_t k = corner % 3;
            Sector& s = sectors_[c];
            s.from = t[(k + 1) % 3];
            s.to = t[(k + 2) % 3];
            if (s.from == v || s.to == v || s.from == s.to) return false; // a repeated corner
            s.to_from = g_.position(s.from) - p;
            s.to_to = g_.position(s.to) - p;
            normal += s.to_from ^ s.to_to;
        }
        if (!closed()) return false;
        if (covers_once_along(normal)) return true;
        const Vec3 size(std::abs(normal[0]), std::abs(normal[1]), std::abs(normal[2]));
        const int first =
            size[0] >= size[1] ? (size[0] >= size[2] ? 0 : 2) : (size[1] >= size[2] ? 1 : 2);
        for (int step = 0; step < 3; ++step) {
            const int dropped = (first + step) % 3;
            if (covers_once(p, (dropped + 1) % 3, (dropped + 2) % 3)) return true;
        }
        return false;
    }

private:
    // Every neighbour starts exactly one sector and ends exactly one: the sectors chain into
    // cycles around v (a border, a repeated face or a non-manifold edge breaks this). Counted
    // for each sector over all, without branches (a fan has few sectors): GCC vectorises the
    // inner loop over the two id arrays (checked with -fopt-info-vec), hence their copies.
    bool closed() {
        const std::uint32_t n = count_; // a local: the arrays' stores cannot change it
        for (std::uint32_t c = 0; c < n; ++c) {
            starts_[c] = sectors_[c].from;
            ends_[c] = sectors_[c].to;
        }
        for (std::uint32_t c = 0; c < n; ++c) {
            const std::uint32_t start = starts_[c], end = ends_[c];
            std::uint32_t same_start = 0, same_end = 0, starting_at_end = 0;
            for (std::uint32_t k = 0; k < n; ++k) {
                same_start += starts_[k] == start ? 1 : 0;
                same_end += ends_[k] == end ? 1 : 0;
                starting_at_end += starts_[k] == end ? 1 : 0;
            }
            if (same_start != 1 || same_end != 1 || starting_at_end != 1) return false;
        }
        return true;
    }

    // The same test as covers_once() below, looking along `normal` (any direction; the fan's
    // normal suits a rough surface best) at the ray along the coordinate axis most nearly in the
    // plane orthogonal to it (its smallest component). Each sign comes from a filter with a safe
    // error bound on rounded differences; where one cannot decide (near zero, or exactly zero),
    // the fan is not certified here.
    bool covers_once_along(const Vec3& normal) const {
        // Scaled by a power of two (exactly) to a largest component in [1, 2): a product of
        // differences that underflows then errs by less than 2^-1073 in a term, far below the
        // bound's slack over the smallest trusted permanent (unscaled, a huge component could
        // magnify that error past the bound).
        const double largest =
            std::max({std::abs(normal[0]), std::abs(normal[1]), std::abs(normal[2])});
        if (!std::isfinite(largest) || largest == 0) return false;
        int exponent = 0;
        std::frexp(largest, &exponent);
        const Vec3 n = normal * std::ldexp(1.0, 1 - exponent);
        int ray_axis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::abs(n[k]) < std::abs(n[ray_axis])) ray_axis = k;
        // m = n × e_ray, exactly: heights X · m are 0 on the ray's line in the projection
        // along n, positive on its counter-clockwise side.
        Vec3 m(0, 0, 0);
        const int i = (ray_axis + 1) % 3, j = (ray_axis + 2) % 3;
        m[i] = n[j];
        m[j] = -n[i];
        const auto height = [&](const Vec3& x) {
            return decided_sign(x[i] * m[i] + x[j] * m[j],
                                std::abs(x[i] * m[i]) + std::abs(x[j] * m[j]));
        };
        int turn = 0, covers = 0;
        for (std::uint32_t c = 0; c < count_; ++c) {
            const Vec3 &a = sectors_[c].to_from, &b = sectors_[c].to_to;
            double det = 0, permanent = 0;
            for (int k = 0; k < 3; ++k) {
                const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
                const double left = a[k1] * b[k2], right = a[k2] * b[k1];
                det += (left - right) * n[k];
                permanent += (std::abs(left) + std::abs(right)) * std::abs(n[k]);
            }
            const int side = decided_sign(det, permanent);
            if (side == 0 || (turn != 0 && side != turn)) return false;
            turn = side;
            const int a_height = height(a), b_height = height(b);
            if (a_height == 0 || b_height == 0) return false;
            const bool contains_ray =
                turn > 0 ? (a_height < 0 && b_height > 0) : (b_height < 0 && a_height > 0);
            if (contains_ray && ++covers > 1) return false;
        }
        return covers == 1;
    }

    // The sign of a sum of at most three products of rounded differences and factors of at most
    // 2 (the scaled normal), `permanent` the sum of their magnitudes, where the rounding errors
    // cannot change it; 0 where they could, an exact zero included. The errors (ε = 2^-53): two
    // rounded differences, their product, the difference of two products, the product by a
    // factor, the sum of three terms, about 6 ε of the permanent (Shewchuk's orient3d, with its
    // third row rounded too, has (7 + 56 ε) ε), plus underflow, below 2^-1073 a term.
    static int decided_sign(double value, double permanent) {
        constexpr double kBound = 9 * 0x1p-53;      // 9 ε: 3 ε of slack
        constexpr double kSmallestTrusted = 1e-250; // 3 ε of it dwarfs any underflow
        if (!(permanent >= kSmallestTrusted) || !(std::abs(value) > kBound * permanent)) return 0;
        return value > 0 ? 1 : -1;
    }

    // In the coordinate plane (i, j): every sector turns the same way (strictly), and exactly
    // one contains the ray from v along +i (half-open: its start included, its end not). Sectors
    // turning one way around v along closed cycles cover every direction as often as their
    // winding numbers add up to, so one cover of one ray means one cycle that tiles the
    // directions around v once, and each face, not degenerate there, is the one-to-one image of its
    // sector's part. A counter-clockwise sector narrower than π contains that ray exactly when it
    // starts on or below v's height and ends above it (the mirror image for clockwise ones):
    // comparisons of coordinates, exact.
    bool covers_once(const Vec3& p, int i, int j) const {
        int turn = 0, covers = 0;
        for (std::uint32_t c = 0; c < count_; ++c) {
            const Vec3 &a = sectors_[c].to_from, &b = sectors_[c].to_to;
            // orient2d(p, from, to) from the differences at hand; the exact one when undecided.
            int side = exact::orient2d_filtered(a[i] * b[j], a[j] * b[i]);
            if (side == 2)
                side = exact::orient2d(p, g_.position(sectors_[c].from),
                                       g_.position(sectors_[c].to), i, j);
            if (side == 0 || (turn != 0 && side != turn)) return false;
            turn = side;
            const bool contains_ray = turn > 0 ? (a[j] <= 0 && 0 < b[j]) : (b[j] < 0 && 0 <= a[j]);
            if (contains_ray && ++covers > 1) return false;
        }
        return covers == 1;
    }

    const TriangleGeometry& g_;
    const VertexCorners& corners_;
    std::array<Sector, kMaxFaces> sectors_;
    std::array<std::uint32_t, kMaxFaces> starts_, ends_;
    std::uint32_t count_ = 0;
};

} // namespace

std::vector<std::uint8_t> embedded_fans(const TriangleGeometry& g, const Execution& exec) {
    const std::size_t n = g.vertex_count();
    const VertexCorners corners = corners_by_vertex(n, g.triangles(), without_progress(exec));
    std::vector<std::uint8_t> embedded(n, 0);
    parallel_for_blocks(without_progress(exec), n, kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            FanCertifier certifier(g, corners);
                            for (std::size_t v = first; v < end; ++v)
                                embedded[v] = certifier.embedded(std::uint32_t(v)) ? 1 : 0;
                        });
    return embedded;
}

} // namespace hrsr
