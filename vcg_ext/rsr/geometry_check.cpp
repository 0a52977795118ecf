#include "rsr/geometry_check.h"

#include "geometry.h"

namespace hrsr::rsr {

GeometryCheck::GeometryCheck(const KnnIndex& index, const std::vector<Vec3>& positions,
                             const std::vector<Vec3>& normals, const RotationSystem& rotation)
    : index_(index), positions_(positions), normals_(normals), rotation_(rotation),
      stamp_(positions.size(), 0) {}

bool GeometryCheck::passes(std::uint32_t v1, std::uint32_t v2) {
    const Vec3& p1 = positions_[v1];
    const Vec3& p2 = positions_[v2];
    const Vec3 centre = (p1 + p2) * 0.5;
    const Vec3 m = (normals_[v1] + normals_[v2]) * 0.5; // not normalised (GEL's HRsR path)
    index_.within(centre, constants::kGeometryBallFactor * (p2 - p1).Norm(), ball_);

    if (++query_ == 0) { // stamps wrapped around: start afresh
        std::fill(stamp_.begin(), stamp_.end(), 0);
        query_ = 1;
    }
    auto faces_same_way = [&](std::uint32_t x) {
        return x != v1 && x != v2 && normals_[x].dot(m) > constants::kGeometryNormalDot;
    };
    for (std::uint32_t a : ball_)
        if (faces_same_way(a)) stamp_[a] = query_;
    for (std::uint32_t a : ball_) {
        if (stamp_[a] != query_) continue;
        for (const Dart& d : rotation_.darts(a)) {
            const std::uint32_t b = d.to;
            // Each unordered pair once: a pair of two ball points is tested from the smaller.
            if (!faces_same_way(b) || (stamp_[b] == query_ && b < a)) continue;
            if (segments_cross({p1, p2, normals_[v1], normals_[v2]},
                               {positions_[a], positions_[b], normals_[a], normals_[b]}))
                return false;
        }
    }
    return true;
}

} // namespace hrsr::rsr
