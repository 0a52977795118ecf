// Oriented normals for a point cloud: the pre-processing stage on its own (what `hrsr normals`
// writes). Public API.
#pragma once

#include "options.h"
#include "parallel.h"
#include "point_set.h"
#include "preprocess/report.h"

#include <cstdint>
#include <vector>

namespace hrsr {

/// The points pre-processing kept, with their oriented unit normals.
struct OrientedPoints {
    std::vector<std::uint32_t> input_index; ///< kept point -> input point, increasing
    std::vector<Vec3> normals;              ///< per kept point; consistent per connected piece

    std::size_t size() const { return input_index.size(); }
};

/// ALGORITHM.md §4.1–4.6 (sanitising, normals from the input or PCA, orientation, the component
/// split): every input point not kept has its fate in `report`. Throws InvalidOption,
/// InvalidInput (nothing usable left) or Cancelled.
OrientedPoints estimate_normals(const PointSet& input, const PreprocessOptions& options,
                                const Execution& exec, PreprocessReport& report);

} // namespace hrsr
