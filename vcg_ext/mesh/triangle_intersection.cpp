#include "mesh/triangle_intersection.h"

#include <vcg/space/intersection3.h>
#include <vcg/space/segment3.h>

#include <algorithm>
#include <cmath>

namespace hrsr {

namespace {

enum class Crossing { None, Inside, Outside };

// The segment of `a` opposite its corner k, pulled half-way towards that corner, against the
// triangle `b`: where it meets b's plane inside b, whether that is strictly inside (vcglib's
// EPSIL margins) or not.
Crossing pulled_edge_crossing(const Corners& a, int k, const Corners& b) {
    // Most pairs around a vertex have a's other corners clearly on one side of b's plane: then
    // the segment cannot meet b, and vcglib's test (which would say so too) is skipped. The
    // margin keeps every near-touching case for the exact test.
    const Vec3 normal = (b[1] - b[0]) ^ (b[2] - b[0]);
    const double side1 = (a[(k + 1) % 3] - a[k]).dot(normal),
                 side2 = (a[(k + 2) % 3] - a[k]).dot(normal);
    const double scale =
        normal.Norm() * std::max((a[(k + 1) % 3] - a[k]).Norm(), (a[(k + 2) % 3] - a[k]).Norm());
    if (std::min(std::abs(side1), std::abs(side2)) > 1e-6 * scale && (side1 > 0) == (side2 > 0))
        return Crossing::None;
    const Vec3 half_shared = a[k] * 0.5;
    const vcg::Segment3<double> edge(a[(k + 1) % 3] * 0.5 + half_shared,
                                     a[(k + 2) % 3] * 0.5 + half_shared);
    double u = 0, v = 0;
    if (!vcg::IntersectionSegmentTriangle(edge, b[0], b[1], b[2], u, v)) return Crossing::None;
    constexpr double kMargin = 0.000001; // vcglib's EPSIL in the same test
    return u + v >= 1 || u <= kMargin || v <= kMargin ? Crossing::Outside : Crossing::Inside;
}

} // namespace

bool mesh_triangles_intersect(const Corners& a, const Triangle& ia, const Corners& b,
                              const Triangle& ib) {
    int shared = 0, ka = 0, kb = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (ia[i] == ib[j]) {
                ++shared;
                ka = i;
                kb = j;
            }
    if (shared == 0) return vcg::IntersectionTriangleTriangle(a[0], a[1], a[2], b[0], b[1], b[2]);
    if (shared > 1) return false;
    // vcglib pulls both edges towards a's copy of the shared corner; the ids say they are one.
    Corners b_at_a = b;
    b_at_a[kb] = a[ka];
    // As in vcglib, the first segment that meets the other triangle decides, inside or not.
    const Crossing first = pulled_edge_crossing(a, ka, b);
    if (first != Crossing::None) return first == Crossing::Inside;
    return pulled_edge_crossing(b_at_a, kb, a) == Crossing::Inside;
}

} // namespace hrsr
