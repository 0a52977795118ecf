// `hrsr check`: everything we measure on a triangle mesh, optionally against the point cloud it
// was made from and a reference surface.
#pragma once

#include "mesh/face_quality.h"
#include "mesh/mesh_stats.h"
#include "mesh/self_intersections.h"
#include "mesh/surface_distance.h"
#include "parallel.h"
#include "point_set.h"

#include <optional>
#include <vector>

namespace hrsr {

struct CheckOptions {
    /// Test pairs of triangles for intersections (the slowest measure).
    bool self_intersections = true;
    /// r_v: an input point is a vertex if a mesh vertex lies within this fraction of the input's
    /// bounding-box diagonal.
    double vertex_tolerance = 1e-6;
    /// Chamfer / Hausdorff sampling.
    SurfaceDistanceOptions distance;
};

struct VertexReference {
    std::size_t input_points = 0;
    std::size_t present = 0; ///< input points with a mesh vertex (used by a triangle) close by
    double tolerance = 0;    ///< absolute
    double ratio() const { return input_points == 0 ? 0 : double(present) / double(input_points); }
};

struct ReferenceDistance {
    SurfaceDistance distance; ///< mesh = a, reference = b; absolute
    double diagonal = 0;      ///< of the reference's bounding box
    double chamfer() const { return distance.chamfer() / diagonal; }
    double hausdorff() const { return distance.hausdorff() / diagonal; }
};

struct MeshCheck {
    std::size_t file_vertices = 0;       ///< all vertices, used by a triangle or not
    std::size_t coincident_vertices = 0; ///< at the position of a vertex with a smaller index
    MeshStats topology;                  ///< V/F, boundary, non-manifold, components, genus
    bool coherently_oriented() const { return topology.inconsistently_oriented_edges == 0; }
    FaceQuality faces;
    std::optional<std::size_t> self_intersecting_pairs; ///< when tested
    /// Faces (with area) winding against the sum of their corners' normals, when the mesh has
    /// vertex normals: folds lying flat on the surface, which no intersecting pair shows (D-64's
    /// test).
    std::optional<std::size_t> faces_against_vertex_normals;
    std::vector<TrianglePair> first_intersecting_pairs; ///< up to 100, by triangle index
    std::optional<VertexReference> vertex_reference;    ///< with an input cloud
    std::optional<ReferenceDistance> reference;         ///< with a reference mesh
};

/// A mesh as positions and triangles over them, and its vertex normals if it has them.
struct MeshView {
    const std::vector<Vec3>& positions;
    const std::vector<Triangle>& triangles;
    const std::vector<Vec3>* normals = nullptr; ///< per position; null or empty: none
};

/// Measures `mesh`; `input` (may be null) gives r_v, `reference` (may be null) the distances.
/// Throws InvalidInput when a mesh has a non-finite vertex coordinate, an index out of range,
/// normals that are not one per vertex, or
/// the reference has no triangle, or when distances are asked for a mesh without triangles.
MeshCheck check_mesh(const MeshView& mesh, const PointSet* input, const MeshView* reference,
                     const CheckOptions& options, const Execution& exec);

} // namespace hrsr
