// Handle phase of RsR (ALGORITHM.md §5.6, D-11): bridge far-apart sides of open faces to raise
// the genus where the data asks for it.
#pragma once

#include "knn.h"
#include "options.h"
#include "rsr/embedding.h"

#include <vector>

namespace hrsr::rsr {

struct HandleStats {
    std::size_t open_vertices = 0;
    std::size_t candidates = 0;
    std::size_t groups = 0;  ///< candidate groups (pairs of faces) of more than 5
    std::size_t handles = 0; ///< groups whose insertions merged two distinct faces (genus + 1 each)
    std::size_t edges_inserted = 0; ///< all handle-phase edges (merges and later splits)
    bool limited = false;      ///< the genus limit stopped a group that would have become a handle
    std::size_t hop_limit = 0; ///< graph hops a handle's endpoints had to be apart (D-27)
};

/// D-27: the graph hops that stand for a loop of `loop_spacings` input point spacings on a cloud
/// of `points` points that stands for `represented_points` input points. A graph hop is about one
/// point spacing, and spacings grow as 1/sqrt(density): on HRsR's coarse cloud (p = points /
/// represented) a loop of L input spacings is L · sqrt(p) hops. D-29: L is capped at
/// constants::kSmallSurfaceLoopFraction · sqrt(represented_points) on small surfaces. Never below
/// constants::kMinHandleHops.
std::size_t handle_hop_limit(double loop_spacings, std::size_t points,
                             std::size_t represented_points);

/// What a handle edge must satisfy besides the candidate graph and the geometry check.
struct HandleLimits {
    std::size_t hop_limit = 0; ///< its endpoints more than this many graph hops apart (D-27)
    /// D-31: no longer than constants::kOverlongFactor · reach[v] at either endpoint v (empty:
    /// no limit).
    const std::vector<double>* reach = nullptr;
};

/// Inserts handle edges within `limits` (the genus limit is options.handles); `roots` receives
/// their endpoints (explored first by the ears). `index` is the k-NN index of the rotation's
/// positions.
HandleStats insert_handles(Embedding& embedding, const KnnIndex& index, const RsrOptions& options,
                           const HandleLimits& limits, std::vector<std::uint32_t>& roots);

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
