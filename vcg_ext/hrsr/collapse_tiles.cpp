#include "hrsr/collapse_tiles.h"

#include "hrsr/range_collapser.h"

#include <limits>
#include <memory>
#include <queue>

namespace hrsr::collapsing {

namespace {

constexpr int kTileSteps = 96; ///< steps of the common cost bound, at most
constexpr double kTileAim = 8; ///< a step aims at 1/kTileAim of what is left

// The tiles, their collapsers and the records so far, step by step.
struct TileRun {
    std::vector<std::unique_ptr<RangeCollapser>> collapsers;
    std::vector<CollapseRecord> records; ///< step by step: the tiles in order, then across
    bool overshot = false; ///< a step went beyond the target: start again below `ceiling`
    double ceiling = 0;
    TileTimes times;

    // An edge i–j joins two tiles (or not): both ends are border nodes of their tiles.
    void mark_border(const Tiles& tiles, std::uint32_t i, std::uint32_t j) {
        const std::uint32_t ti = tiles.tile_of(i), tj = tiles.tile_of(j);
        if (ti == tj) return;
        collapsers[ti]->mark_border(i);
        collapsers[tj]->mark_border(j);
    }
};

// After the tiles' part of a step: the edges they changed in other tiles, in tile order.
void apply_relinks(CollapseGraph& g, const Tiles& tiles, TileRun& run) {
    for (auto& collapser : run.collapsers) {
        for (const Relink& r : collapser->relinks) {
            const std::uint32_t node = g.survivor(r.node), into = g.survivor(r.into);
            g.relink(node, r.dead, into);
            run.mark_border(tiles, node, into);
        }
        std::vector<Relink>().swap(collapser->relinks);
    }
}

// The edges across tile borders whose cost is at most `bound`. Only the tiles' border nodes are
// looked at; the queue they go to orders them, so the order found in does not matter.
std::vector<EdgeKey> edges_across(const CollapseGraph& g, const Tiles& tiles, const TileRun& run,
                                  double bound, const Execution& exec) {
    std::vector<std::vector<EdgeKey>> found(tiles.count);
    parallel_for(
        exec, tiles.count,
        [&](std::size_t t) {
            for (std::uint32_t i : run.collapsers[t]->border()) {
                if (!g.alive[i]) continue;
                for (std::uint32_t j : g.neighbours[i])
                    if (j > i && tiles.tile_of(j) != t) {
                        const EdgeKey key = g.edge_key(i, j);
                        if (key.cost <= bound) found[t].push_back(key);
                    }
            }
        },
        1);
    std::vector<EdgeKey> all;
    for (const auto& keys : found) all.insert(all.end(), keys.begin(), keys.end());
    return all;
}

// The step's collapses across tile borders, in cost order, while their cost is at most `bound`
// and the target is not reached: each merge updates both tiles' queues (no tile runs now).
void collapse_across(CollapseGraph& g, const Tiles& tiles, TileRun& run, double bound,
                     std::size_t target, const Execution& exec) {
    auto later = [](const EdgeKey& p, const EdgeKey& q) { return q < p; };
    std::priority_queue<EdgeKey, std::vector<EdgeKey>, decltype(later)> queue(
        later, edges_across(g, tiles, run, bound, exec));
    auto collapser = [&](std::uint32_t i) -> RangeCollapser& {
        return *run.collapsers[tiles.tile_of(i)];
    };
    while (!queue.empty() && run.records.size() < target) {
        const EdgeKey e = queue.top();
        queue.pop();
        if (!g.alive[e.lo] || !g.alive[e.hi]) continue;
        const EdgeKey now = g.edge_key(e.lo, e.hi);
        if (now.cost != e.cost) { // moved since: queued again at its cost
            if (now.cost <= bound) queue.push(now);
            continue;
        }
        const std::uint32_t a = e.lo, b = e.hi;
        g.merge(a, b, run.records);
        g.move_edges(
            a, b, [](std::uint32_t) { return true; }, [](std::uint32_t) {});
        collapser(b).erase(b);
        collapser(a).refresh(a);
        for (std::uint32_t c : g.neighbours[a]) {
            collapser(c).refresh(c);
            run.mark_border(tiles, a, c);
            if (tiles.tile_of(c) != tiles.tile_of(a)) {
                const EdgeKey key = g.edge_key(a, c);
                if (key.cost <= bound) queue.push(key);
            }
        }
    }
}

// The first bound: where a quarter of the target would be spent if the nodes' first costs were
// all. False when no node has an edge inside its tile.
bool first_bound(const TileRun& run, std::size_t target, double ceiling, double& bound) {
    std::vector<float> costs;
    for (const auto& collapser : run.collapsers) collapser->add_costs(costs);
    if (costs.empty()) return false;
    const std::size_t rank = std::min(costs.size() - 1, target / 4);
    std::nth_element(costs.begin(), costs.begin() + std::ptrdiff_t(rank), costs.end());
    bound = std::min(ceiling, double(costs[rank]));
    return true;
}

// D-42: the tiles collapse in parallel, each on its own edges, in steps under a cost bound common
// to all tiles; after each step's tiles the edges across their borders up to the same bound are
// collapsed in cost order, so that a node at a border is merged when the global order would
// merge it (not later, and not only with its own tile's nodes). The bound starts at
// first_bound() and is raised from step to step (1/kTileAim of what is left, at the last step's
// cost per collapse) until less than 1/kTileRest of the target is left. A step that goes beyond
// the target is not undone: the caller starts again with the bound held below it (`ceiling`).
// The records go step by step, the tiles in tile order, whatever the thread count.
TileRun collapse_tiles(CollapseGraph& g, const Tiles& tiles, std::size_t target, double ceiling,
                       const Execution& exec) {
    const std::size_t n = g.x.size();
    TileRun run;
    run.collapsers.resize(tiles.count);
    parallel_for(
        exec, tiles.count,
        [&](std::size_t t) {
            run.collapsers[t] =
                std::make_unique<RangeCollapser>(g, tiles.begin(t), tiles.end(t, n), nullptr);
        },
        1);
    double bound = 0, last_bound = 0;
    if (!first_bound(run, target, ceiling, bound)) return run;
    std::vector<std::vector<CollapseRecord>> step_records(tiles.count);
    std::vector<double> seconds(tiles.count);
    run.times.tiles = tiles.count;
    std::size_t done = 0;
    for (int step = 0; step < kTileSteps && target - done > target / kTileRest; ++step) {
        parallel_for(
            exec, tiles.count,
            [&](std::size_t t) {
                seconds[t] = TileTimes::seconds_of([&] {
                    double cost = 0;
                    while (run.collapsers[t]->next_cost(cost) && cost <= bound)
                        run.collapsers[t]->collapse_next(step_records[t]);
                });
            },
            1);
        run.times.add_stretch(seconds.data(), tiles.count);
        for (auto& records : step_records) {
            run.records.insert(run.records.end(), records.begin(), records.end());
            records.clear();
        }
        if (run.records.size() > target) {
            run.overshot = true;
            run.ceiling = (last_bound + bound) / 2;
            return run;
        }
        apply_relinks(g, tiles, run);
        collapse_across(g, tiles, run, bound, target, exec);
        // Aim at 1/kTileAim of what is left, along the last step's cost per collapse.
        const std::size_t now = run.records.size();
        const double per_collapse =
            (bound - last_bound) / double(std::max<std::size_t>(1, now - done));
        last_bound = bound;
        done = now;
        bound =
            std::min({ceiling, bound * 4, bound + per_collapse * double(target - done) / kTileAim});
        if (bound <= last_bound) break; // held at the ceiling
    }
    return run;
}

} // namespace

TiledCollapse collapse_in_tiles(CollapseGraph& g, const Tiles& tiles, std::size_t budget,
                                const std::function<CollapseGraph()>& rebuild,
                                const Execution& exec) {
    TileRun run = collapse_tiles(g, tiles, budget, std::numeric_limits<double>::infinity(), exec);
    TiledCollapse result;
    while (run.overshot) { // rare: the graph is built again, the bound held lower
        const double ceiling = run.ceiling;
        run = TileRun();
        g = rebuild();
        run = collapse_tiles(g, tiles, budget, ceiling, exec);
        ++result.restarts;
    }
    result.records = std::move(run.records);
    result.tile_times = run.times;
    return result;
}

} // namespace hrsr::collapsing
