// Distances between two triangle surfaces from samples: Chamfer and Hausdorff.
#pragma once

#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"

#include <cstddef>
#include <vector>

namespace hrsr {

struct SurfaceDistanceOptions {
    /// Random points per surface, uniform by area (vcglib's Montecarlo sampler). Means are taken
    /// over them; maxima over them and every vertex used by a triangle.
    std::size_t area_samples = 200000;
    unsigned seed = 1; ///< of the sampler: the same inputs and seed give the same numbers
};

/// One direction: from the samples of a surface to the other surface.
struct OneSidedDistance {
    std::size_t area_samples = 0, vertices = 0;
    double mean = 0; ///< mean distance of an area sample to the other surface
    double max = 0;  ///< largest distance of an area sample or a vertex
};

struct SurfaceDistance {
    OneSidedDistance a_to_b, b_to_a;
    /// Symmetric Chamfer distance: (a_to_b.mean + b_to_a.mean) / 2.
    double chamfer() const { return 0.5 * (a_to_b.mean + b_to_a.mean); }
    /// (Sampled) Hausdorff distance: max(a_to_b.max, b_to_a.max).
    double hausdorff() const { return a_to_b.max > b_to_a.max ? a_to_b.max : b_to_a.max; }
};

/// A triangle surface: positions and the triangles over them.
struct Surface {
    const std::vector<Vec3>& positions;
    const std::vector<Triangle>& triangles;
};

/// Samples both surfaces and measures each sample's distance to the closest point of the other
/// (exact point-to-triangle distance through a uniform grid, vcglib's GridStaticPtr; samples in
/// parallel). Throws InvalidInput if either surface has no triangle.
SurfaceDistance surface_distance(const Surface& a, const Surface& b,
                                 const SurfaceDistanceOptions& options, const Execution& exec);

} // namespace hrsr
