// The "spherical search space" test of RsR (ALGORITHM.md §5.5.2 step 3): a new edge must not
// cross, in the tangent plane, any current edge of a nearby point facing the same way.
#pragma once

#include "geometry.h"
#include "knn.h"
#include "rsr/rotation_system.h"

#include <vector>

namespace hrsr::rsr {

/// The nearby points one test looked at: the face split keeps them to learn later whether an
/// edge inserted since then could change the answer.
struct GeometryQuery {
    std::vector<std::uint32_t> ball;
    std::vector<std::uint32_t> near; ///< ball points facing the same way as the segment, sorted
};

class GeometryCheck {
public:
    /// `index` is built on `positions` (the smoothed ones); `normals` are those of the rotation.
    GeometryCheck(const KnnIndex& index, const std::vector<Vec3>& positions,
                  const std::vector<Vec3>& normals, const RotationSystem& rotation);

    /// True when no current edge {a, b} near the segment v1–v2 crosses it. Reads the rotation
    /// only: threads may test at once while nobody inserts. `query` receives the nearby points.
    bool passes(std::uint32_t v1, std::uint32_t v2, GeometryQuery& query) const {
        gather(v1, v2, query);
        return passes_gathered(v1, v2, query);
    }
    /// The same with the check's own scratch (not thread-safe).
    bool passes(std::uint32_t v1, std::uint32_t v2) { return passes(v1, v2, own_); }

    /// passes() in two halves, for callers that must know which rotations the test will read
    /// before it reads them (D-51): gather() fills `query` and reads positions and normals only;
    /// passes_gathered() then reads the rotations of query.near.
    void gather(std::uint32_t v1, std::uint32_t v2, GeometryQuery& query) const;
    bool passes_gathered(std::uint32_t v1, std::uint32_t v2, const GeometryQuery& query) const;

    /// True when some current edge of `a` (a point of a query's `near`) that the test of v1–v2
    /// considers crosses it: what an edge inserted at `a` after the test may have changed.
    bool crossed_at(std::uint32_t v1, std::uint32_t v2, std::uint32_t a) const;

private:
    bool faces_same_way(std::uint32_t x, std::uint32_t v1, std::uint32_t v2) const;
    SegmentCrossings segment(std::uint32_t v1, std::uint32_t v2) const;
    bool crosses(const SegmentCrossings& v1v2, std::uint32_t a, std::uint32_t b) const;

    const KnnIndex& index_;
    const std::vector<Vec3>& positions_;
    const std::vector<Vec3>& normals_;
    const RotationSystem& rotation_;
    GeometryQuery own_;
};

} // namespace hrsr::rsr
