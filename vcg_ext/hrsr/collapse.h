// HRsR collapse phase (ALGORITHM.md §6): merge the shortest neighbour edges until a fraction p
// of the points is left, recording every merge so that it can be replayed as a vertex split.
#pragma once

#include "index_types.h"
#include "knn.h"
#include "options.h"
#include "parallel.h"
#include "point_set.h"
#include "reconstruction_stats.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace hrsr {

/// One merge of node `latent` into node `active` (ids are indices of the collapsed-from cloud,
/// PointIndex values: the collapse and the re-expansion work inside that one space).
struct CollapseRecord {
    std::uint32_t active, latent;
    Vec3 active_before, latent_before; ///< positions just before the merge
};

struct CollapsedCloud {
    IndexVector<CoarseIndex, PointIndex> survivors; ///< coarse point -> its node, increasing
    std::vector<Vec3> positions;         ///< per survivor: weighted mean of its merged points
    std::vector<Vec3> normals;           ///< per survivor: unit weighted mean normal (D-9)
    std::vector<std::uint32_t> weights;  ///< per survivor: number of points merged into it
    std::vector<CollapseRecord> records; ///< in the order they happened
    std::size_t budget = 0;              ///< collapses asked for
    bool ran_out_of_edges = false;       ///< stopped before the budget: no valid edge left
    std::size_t tiles = 1;               ///< D-42: tiles of the spatial order
    std::size_t tile_collapses = 0;      ///< D-42: collapses done inside the tiles, in parallel
    std::size_t tile_restarts = 0; ///< D-42: the tiles started again (a step beyond the budget)
    TileTimes tile_times;          ///< D-42: of the last start
};

/// Collapses the cloud (positions: the algorithm's unsmoothed coordinates; normals: unit,
/// oriented). Deterministic (D-10); the kNN queries run in parallel. `index_of_positions`, if
/// given, is a kd-tree on `positions` that the kNN graph uses instead of building one, and
/// frees as soon as it is made, as it would its own (peak memory).
CollapsedCloud collapse(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                        const CollapseOptions& options, const Execution& exec,
                        std::unique_ptr<KnnIndex> index_of_positions = nullptr);

} // namespace hrsr
