// The points along a space-filling curve (D-40, issue 20 item 1): a cloud comes in the order
// its source wrote it (surface samples in random order, scans line by line), and every phase
// walks its points, neighbours and faces by index. In Morton order neighbours are near in
// memory too. Internal: reconstruct() runs on the reordered cloud and hands back a result in
// input indices (input_order.h).
#pragma once

#include "parallel.h"
#include "point_set.h"

#include <cstdint>
#include <vector>

namespace hrsr {

/// A permutation of a cloud's points along the curve.
struct SpatialOrder {
    std::vector<std::uint32_t> input_index; ///< per point in the new order: its input index
};

/// Morton (Z) order of the finite positions, quantised to 21 bits an axis over the longest side
/// of their bounding box, cut down where a few far outliers lie beyond half the central extent
/// (0.1 % to 99.9 % of the coordinates) on an axis: those are clamped into the outermost cells.
/// Points in one cell follow their exact coordinates, so only exact duplicates keep their input
/// order; non-finite positions come last, in input order.
SpatialOrder spatial_order(const std::vector<Vec3>& positions, const Execution& exec);

/// The points the algorithm reads (positions, and normals when the input has one per point),
/// in `order`; attributes and warnings stay with the input, whose indices the result speaks of.
/// Normals whose count does not match the points are copied as given, for sanitising to judge.
PointSet reordered(const PointSet& input, const SpatialOrder& order, const Execution& exec = {});

} // namespace hrsr
