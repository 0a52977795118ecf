// The "spherical search space" test of RsR (ALGORITHM.md §5.5.2 step 3): a new edge must not
// cross, in the tangent plane, any current edge of a nearby point facing the same way.
#pragma once

#include "knn.h"
#include "rsr/rotation_system.h"

#include <vector>

namespace hrsr::rsr {

class GeometryCheck {
public:
    /// `index` is built on `positions` (the smoothed ones); `normals` are those of the rotation.
    GeometryCheck(const KnnIndex& index, const std::vector<Vec3>& positions,
                  const std::vector<Vec3>& normals, const RotationSystem& rotation);

    /// True when no current edge {a, b} near the segment v1–v2 crosses it. Not thread-safe.
    bool passes(std::uint32_t v1, std::uint32_t v2);

private:
    const KnnIndex& index_;
    const std::vector<Vec3>& positions_;
    const std::vector<Vec3>& normals_;
    const RotationSystem& rotation_;
    std::vector<std::uint32_t> ball_;
    std::vector<std::uint32_t> stamp_; ///< stamp_[a] == query_: a is a qualifying ball point
    std::uint32_t query_ = 0;
};

} // namespace hrsr::rsr
