// D-42: the collapse in tiles of the spatial order (D-40), in parallel, in steps under a cost
// bound common to all tiles.
#pragma once

#include "hrsr/collapse_graph.h"
#include "options.h"
#include "reconstruction_stats.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

namespace hrsr::collapsing {

/// Tiles of consecutive nodes, a number that depends on the cloud's size only.
struct Tiles {
    std::size_t count, size;
    explicit Tiles(std::size_t n)
        : count(std::max<std::size_t>(1, (n + constants::kCollapseTilePoints - 1) /
                                             constants::kCollapseTilePoints)),
          size((n + count - 1) / count) {}
    std::uint32_t tile_of(std::uint32_t i) const { return std::uint32_t(i / size); }
    std::uint32_t begin(std::size_t t) const { return std::uint32_t(t * size); }
    std::uint32_t end(std::size_t t, std::size_t n) const {
        return std::uint32_t(std::min(n, (t + 1) * size));
    }
};

/// The tiles stop when less than 1/kTileRest of the budget is left; the whole graph does the
/// rest. A cloud whose budget is below kTileRest per tile is collapsed whole.
inline constexpr std::size_t kTileRest = 64;

struct TiledCollapse {
    std::vector<CollapseRecord> records; ///< step by step: the tiles in order, then across
    std::size_t restarts = 0;            ///< a step beyond the budget: started again lower
    TileTimes tile_times;                ///< of the last start
};

/// Collapses g in tiles until less than 1/kTileRest of `budget` is left (never beyond it); a
/// restart replaces g by `rebuild()`. The records are the same for any thread count.
TiledCollapse collapse_in_tiles(CollapseGraph& g, const Tiles& tiles, std::size_t budget,
                                const std::function<CollapseGraph()>& rebuild,
                                const Execution& exec);

} // namespace hrsr::collapsing
