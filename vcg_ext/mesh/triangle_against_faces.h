// One triangle tested against many faces near it (the fold repair's and removal's inner loops).
#pragma once

#include "mesh/exact_predicates.h"
#include "mesh/triangle_grid.h"

namespace hrsr {

/// One triangle t of a TriangleGeometry tested against many of its faces (a fill's candidate
/// against the faces near it): t's plane is evaluated once, and a face whose corners that t
/// lacks lie strictly on one side of it is passed without the exact pair test, which would
/// begin with the same signs and stop there.
class TriangleAgainstFaces {
public:
    TriangleAgainstFaces(const TriangleGeometry& g, const Triangle& t)
        : g_(g), t_(t), plane_(g.position(t[0]), g.position(t[1]), g.position(t[2])) {}

    /// g.intersect_unboxed(t, b).
    bool intersects(const Triangle& b) const {
        int side = 0;
        for (std::uint32_t v : b) {
            if (v == t_[0] || v == t_[1] || v == t_[2]) continue;
            const int s = plane_.side(g_.position(v));
            if (s == 0 || s == 2 || (side != 0 && s != side)) return g_.intersect_unboxed(t_, b);
            side = s;
        }
        return side == 0 && g_.intersect_unboxed(t_, b); // b has all of t's corners
    }

private:
    const TriangleGeometry& g_;
    const Triangle t_;
    const exact::PlaneSides plane_;
};

} // namespace hrsr
