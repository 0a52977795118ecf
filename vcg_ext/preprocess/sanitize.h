// Validation and cleaning of a raw point set (ALGORITHM.md §4.1, §4.2; D-2, D-3).
#pragma once

#include "index_types.h"
#include "options.h"
#include "parallel.h"
#include "point_set.h"
#include "preprocess/report.h"

#include <cstdint>
#include <vector>

namespace hrsr {

/// The map between input coordinates and the normalised ones the algorithm works in (D-2):
/// normalised = (input − centre) · scale, with scale = 1 / bbox diagonal.
struct Normalisation {
    Vec3 centre{0, 0, 0};
    double scale = 1.0;
};

/// The finite, de-duplicated points, in the order given.
struct SanitizedCloud {
    IndexVector<PointIndex, InputIndex> input_index; ///< kept point -> index in the input
    std::vector<Vec3> positions;                     ///< normalised coordinates
    std::vector<Vec3> normals; ///< unit input normals; empty when they must be estimated
    Normalisation normalisation;
};

/// The order a cloud comes in. `Spatial`: as spatial_order() leaves it (D-40), points with
/// equal positions next to each other in index order, so that exact duplicates are found in one
/// pass instead of a sort of all points.
enum class InputOrder { Any, Spatial };

/// Drops non-finite points, checks the normals (falling back to estimation, with a warning in
/// the report, when any is unusable), merges exact duplicates into their first occurrence, and
/// normalises coordinates. Fills the report's per-point fates. Throws InvalidInput when no
/// finite point is left or the coordinates span more than the double range. `exec`: threads of
/// the duplicate sort, the normalisation and the near-duplicate screen (the same result for any
/// count; its progress is not used).
SanitizedCloud sanitize(const PointSet& input, const PreprocessOptions& options,
                        PreprocessReport& report, const Execution& exec = Execution{1, nullptr},
                        InputOrder order = InputOrder::Any);

} // namespace hrsr
