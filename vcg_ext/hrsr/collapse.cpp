#include "hrsr/collapse.h"

#include "hrsr/collapse_graph.h"
#include "hrsr/collapse_tiles.h"
#include "hrsr/range_collapser.h"

#include <cmath>

namespace hrsr {

namespace {

// Nothing to collapse: every point is a survivor.
CollapsedCloud uncollapsed(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals) {
    const std::size_t n = positions.size();
    CollapsedCloud result;
    result.survivors.reserve(n);
    for (std::uint32_t i = 0; i < n; ++i) result.survivors.push_back(PointIndex(i));
    result.positions = positions;
    result.normals = normals;
    result.weights.assign(n, 1);
    return result;
}

} // namespace

CollapsedCloud collapse(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                        const CollapseOptions& options, const Execution& exec,
                        std::unique_ptr<KnnIndex> index_of_positions) {
    using namespace collapsing;
    validate(options);
    const std::size_t n = positions.size();
    const std::size_t budget =
        n - std::min(n, std::size_t(std::llround(double(n) * options.collapse_ratio)));
    if (budget == 0) {
        index_of_positions.reset(); // before the copies (peak memory)
        return uncollapsed(positions, normals);
    }
    CollapsedCloud result;
    result.budget = budget;
    if (exec.progress) exec.progress->begin("collapse graph");
    const Tiles tiles(n);
    result.tiles = tiles.count;
    // A restart of the tiles builds the graph again, with a kd-tree of its own.
    auto rebuild = [&] {
        return build_graph(positions, normals, options.collapse_k, exec,
                           std::move(index_of_positions));
    };
    CollapseGraph g = rebuild();
    if (exec.progress) exec.progress->begin("collapse");
    // D-42; one tile: the whole graph is the tile, in the global order exactly.
    if (tiles.count > 1 && budget >= kTileRest * tiles.count) {
        TiledCollapse tiled = collapse_in_tiles(g, tiles, budget, rebuild, exec);
        result.records = std::move(tiled.records);
        result.tile_collapses = result.records.size();
        result.tile_restarts = tiled.restarts;
        result.tile_times = tiled.tile_times;
    }
    result.records.reserve(budget);
    if (result.records.size() < budget) {
        RangeCollapser whole(g, 0, std::uint32_t(n), &exec);
        while (result.records.size() < budget)
            if (!whole.collapse_next(result.records)) {
                result.ran_out_of_edges = true; // §6.2: stop gracefully, report the ratio reached
                break;
            }
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        if (!g.alive[i]) continue;
        result.survivors.push_back(PointIndex(i));
        result.positions.push_back(g.x[i]);
        result.normals.push_back(g.n[i]);
        result.weights.push_back(g.w[i]);
    }
    return result;
}

} // namespace hrsr
