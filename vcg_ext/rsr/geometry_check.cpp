#include "rsr/geometry_check.h"

#include "geometry.h"

#include <algorithm>

namespace hrsr::rsr {

GeometryCheck::GeometryCheck(const KnnIndex& index, const std::vector<Vec3>& positions,
                             const std::vector<Vec3>& normals, const RotationSystem& rotation)
    : index_(index), positions_(positions), normals_(normals), rotation_(rotation) {}

// The mean of the ends' normals is not normalised (GEL's HRsR path).
bool GeometryCheck::faces_same_way(std::uint32_t x, std::uint32_t v1, std::uint32_t v2) const {
    const Vec3 m = (normals_[v1] + normals_[v2]) * 0.5;
    return x != v1 && x != v2 && normals_[x].dot(m) > constants::kGeometryNormalDot;
}

SegmentCrossings GeometryCheck::segment(std::uint32_t v1, std::uint32_t v2) const {
    return SegmentCrossings({positions_[v1], positions_[v2], normals_[v1], normals_[v2]});
}

bool GeometryCheck::crosses(const SegmentCrossings& v1v2, std::uint32_t a, std::uint32_t b) const {
    return v1v2.crossed_by({positions_[a], positions_[b], normals_[a], normals_[b]});
}

void GeometryCheck::gather(std::uint32_t v1, std::uint32_t v2, GeometryQuery& q) const {
    const Vec3& p1 = positions_[v1];
    const Vec3& p2 = positions_[v2];
    index_.within((p1 + p2) * 0.5, constants::kGeometryBallFactor * (p2 - p1).Norm(), q.ball);
    q.near.clear();
    for (std::uint32_t a : q.ball)
        if (faces_same_way(a, v1, v2)) q.near.push_back(a);
    std::sort(q.near.begin(), q.near.end());
}

bool GeometryCheck::passes_gathered(std::uint32_t v1, std::uint32_t v2,
                                    const GeometryQuery& q) const {
    const SegmentCrossings v1v2 = segment(v1, v2);
    for (std::uint32_t a : q.near)
        for (const Dart& d : rotation_.darts(a)) {
            const std::uint32_t b = d.to;
            // Each unordered pair once: a pair of two near points is tested from the larger.
            if (!faces_same_way(b, v1, v2) ||
                (b < a && std::binary_search(q.near.begin(), q.near.end(), b)))
                continue;
            if (crosses(v1v2, a, b)) return false;
        }
    return true;
}

bool GeometryCheck::crossed_at(std::uint32_t v1, std::uint32_t v2, std::uint32_t a) const {
    const SegmentCrossings v1v2 = segment(v1, v2);
    for (const Dart& d : rotation_.darts(a))
        if (faces_same_way(d.to, v1, v2) && crosses(v1v2, a, d.to)) return true;
    return false;
}

} // namespace hrsr::rsr
