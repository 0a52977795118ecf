// The state RsR's insertion phases (ALGORITHM.md §5.5–5.7) share and grow: the rotation system,
// its face labels, the geometry check of new edges, the triangles recorded so far and the observer
// watching. reconstruct_component() builds it once; each phase takes it instead of five objects.
#pragma once

#include "rsr/component.h"
#include "rsr/faces.h"
#include "rsr/geometry_check.h"
#include "rsr/observer.h"
#include "rsr/rotation_system.h"

#include <vector>

namespace hrsr::rsr {

struct Embedding {
    RotationSystem& rotation;
    Faces& faces;
    GeometryCheck& geometry; ///< consulted by the face split and the handles (not by the ears)
    std::vector<LocalTriangle>& triangles; ///< counter-clockwise seen from the normals
    Observer* observer = nullptr;

    /// Records the face (a, b, c) of the rotation as an output triangle: each of its edges counts
    /// one more triangle, the face is marked (nothing enters it any more) and the triangle is
    /// appended.
    void record_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        record_triangle({a, b, c}, triangles);
    }
    /// The same, appending the triangle to `list` (a thread's own, D-51).
    void record_triangle(const LocalTriangle& t, std::vector<LocalTriangle>& list);

    /// Tells the observer (if any) that edge {u, v} was inserted in `phase` and recorded the last
    /// `new_triangles` triangles.
    void edge_inserted(Phase phase, std::uint32_t u, std::uint32_t v,
                       std::size_t new_triangles) const {
        if (observer)
            observer->edge_inserted(phase, u, v, rotation, faces, triangles, new_triangles);
    }
};

} // namespace hrsr::rsr
