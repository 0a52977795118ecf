// Moving points along their normals towards the local surface (ALGORITHM.md §4.4), so that
// neighbourhoods and tangent-plane tests are insensitive to noise along the normal. Only the
// algorithm sees smoothed positions; outputs always carry the input coordinates.
#pragma once

#include "knn.h"

#include <vector>

namespace hrsr {

struct SmoothingResult {
    std::vector<Vec3> positions;
    double mean_shift = 0; ///< mean |displacement|, in the units of the input positions
    double max_shift = 0;
    std::vector<double> shift; ///< per point, along its normal
};

/// One smoothing round: each point moves along its normal by the weighted mean height of its
/// `neighbours` nearest points whose normals are within 30°, weights falling linearly with the
/// tangential distance. `index` must be built on `positions`. When `oriented` is false the
/// normals have arbitrary signs (PCA before orientation) and the filter compares |n_q · n_p|.
/// `reach`, if given, carries the neighbourhoods' radii between rounds (knn.h): this round's
/// are kept, then grown by the shifts for the moved points.
SmoothingResult smooth_along_normals(const std::vector<Vec3>& positions,
                                     const std::vector<Vec3>& normals, const KnnIndex& index,
                                     int neighbours, bool oriented, const Execution& exec,
                                     NeighbourReach* reach = nullptr);

/// One averaging round over oriented unit normals: each becomes the mean of its own and those of
/// its `neighbours` nearest points that face its side (n_q · n_p > 0: the other side of a thin
/// part is left out; no narrower cone, which would pull the mean back towards n_p). `index` is
/// built on the points the normals belong to.
std::vector<Vec3> averaged_normals(const std::vector<Vec3>& normals, const KnnIndex& index,
                                   int neighbours, const Execution& exec,
                                   NeighbourReach* reach = nullptr);

} // namespace hrsr
