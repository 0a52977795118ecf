// A point cloud as it comes from a file or a MeshLab layer, before any cleaning.
#pragma once

#include "point_attributes.h"

#include <vcg/space/point3.h>

#include <cstddef>
#include <string>
#include <vector>

namespace hrsr {

/// Double precision everywhere inside the algorithm (ALGORITHM.md D-2).
using Vec3 = vcg::Point3d;

/// How the source stored its coordinates, so that writers can reproduce them bit-exactly.
enum class CoordinatePrecision { Float, Double };

/// Raw input points. `normals` is empty when the source had none; its size is *not* guaranteed
/// to match `positions` (a file may lie): sanitising (preprocess/sanitize.h) checks it.
struct PointSet {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    CoordinatePrecision precision = CoordinatePrecision::Float;
    /// Every other per-point value of the source (colour, intensity, ...), one per position;
    /// the algorithm ignores them, writers carry them to the vertices made from the points.
    std::vector<PointAttribute> attributes;
    /// What the reader left out and why (e.g. list properties), for the user.
    std::vector<std::string> warnings;

    std::size_t size() const { return positions.size(); }
    bool has_normals() const { return !normals.empty(); }
};

} // namespace hrsr
