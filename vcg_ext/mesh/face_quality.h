// Per-triangle quality: degenerate and duplicate faces, minimum angles.
#pragma once

#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <cstddef>
#include <vector>

namespace hrsr {

struct MinAngleStats {
    std::size_t faces = 0;                ///< non-degenerate triangles measured
    double min = 0, mean = 0, median = 0; ///< of each triangle's smallest angle, degrees
    std::size_t below_1_degree = 0, below_10_degrees = 0;
};

struct FaceQuality {
    /// A triangle repeating a vertex index, or whose corners are collinear or coincide: twice
    /// its area is at most 1e-12 × its longest edge squared (an angle below ~1e-12 rad).
    std::size_t degenerate_faces = 0;
    std::size_t repeated_vertex_faces = 0; ///< the part of degenerate_faces repeating an index
    /// Triangles on the same three vertex positions as an earlier triangle (either winding).
    std::size_t duplicate_faces = 0;
    MinAngleStats min_angle; ///< over the non-degenerate triangles
};

/// `welded` are the triangles with vertices at the same position merged (mesh/welding.h);
/// `triangles` the original ones (for repeated indices).
FaceQuality face_quality(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
                         const std::vector<Triangle>& welded);

/// Whether triangle abc is degenerate in the sense of FaceQuality::degenerate_faces.
bool is_degenerate(const Vec3& a, const Vec3& b, const Vec3& c);

} // namespace hrsr
