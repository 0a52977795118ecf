// Handle phase of RsR (ALGORITHM.md §5.6, D-11): bridge far-apart sides of open faces to raise
// the genus where the data asks for it.
#pragma once

#include "options.h"
#include "rsr/faces.h"
#include "rsr/geometry_check.h"
#include "rsr/observer.h"

#include <vector>

namespace hrsr::rsr {

struct HandleStats {
    std::size_t open_vertices = 0;
    std::size_t candidates = 0;
    std::size_t groups = 0;  ///< candidate groups (pairs of faces) of more than 5
    std::size_t handles = 0; ///< groups whose insertions merged two distinct faces (genus + 1 each)
    std::size_t edges_inserted = 0; ///< all handle-phase edges (merges and later splits)
    bool limited = false; ///< the genus limit stopped a group that would have become a handle
};

/// Inserts handle edges; `roots` receives their endpoints (explored first by the ears).
/// `triangles` (those of the face-split phase) is only shown to the observer.
HandleStats insert_handles(RotationSystem& rotation, Faces& faces, GeometryCheck& geometry,
                           const KnnIndex& index, const RsrOptions& options,
                           const std::vector<LocalTriangle>& triangles,
                           std::vector<std::uint32_t>& roots, Observer* observer);

/// Hop distances in the current graph by breadth-first search bounded at a depth (D-11).
class BoundedBfs {
public:
    explicit BoundedBfs(std::size_t vertices) : stamp_(vertices, 0) {}
    /// Hop distance from a to b, or limit + 1 if it exceeds `limit`.
    std::size_t distance(const RotationSystem& rotation, std::uint32_t a, std::uint32_t b,
                         std::size_t limit);

private:
    std::vector<std::uint32_t> stamp_;
    std::uint32_t epoch_ = 0;
    std::vector<std::uint32_t> frontier_, next_;
};

} // namespace hrsr::rsr
