#include "hrsr/reexpansion.h"

#include "hrsr/collapse_tiles.h"
#include "hrsr/crossings.h"
#include "hrsr/local_flips.h"
#include "hrsr/split_choice.h"
#include "mesh/small_holes_fill.h"
#include "mesh/split_mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hrsr {

using namespace reexpand;

namespace {

// Per node, the mesh vertices standing for it (D-16). Almost always one, so one word per node:
// the vertex itself, or (rarely: fan-split copies of a coarse vertex) a tagged index into lists
// kept aside. An aliased node shares its target's word.
class NodeVertices {
public:
    struct Span {
        const std::uint32_t* first;
        std::size_t size;
        const std::uint32_t* begin() const { return first; }
        const std::uint32_t* end() const { return first + size; }
    };

    NodeVertices(std::size_t nodes, const IndexVector<VertexIndex, PointIndex>& coarse_vertex_node)
        : word_(nodes, kNone) {
        for (std::uint32_t v = 0; v < coarse_vertex_node.size(); ++v) {
            std::uint32_t& w = word_[coarse_vertex_node[VertexIndex(v)].value()];
            if (w == kNone) {
                w = v;
                continue;
            }
            if (!(w & kListBit)) {
                lists_.push_back({w});
                w = kListBit | std::uint32_t(lists_.size() - 1);
            }
            lists_[w & ~kListBit].push_back(v);
        }
    }

    Span of(std::uint32_t node) const {
        const std::uint32_t& w = word_[node];
        if (w == kNone) return {nullptr, 0};
        if (!(w & kListBit)) return {&w, 1};
        const std::vector<std::uint32_t>& list = lists_[w & ~kListBit];
        return {list.data(), list.size()};
    }
    void set(std::uint32_t node, std::uint32_t vertex) { word_[node] = vertex; }
    void share(std::uint32_t from, std::uint32_t to) { word_[to] = word_[from]; }

private:
    static constexpr std::uint32_t kNone = ~0u, kListBit = 1u << 31;
    std::vector<std::uint32_t> word_;
    std::vector<std::vector<std::uint32_t>> lists_;
};

// D-34: RsR on the coarse cloud closes a straight border with long edges over slivers whose apex
// lies just inside (a vertex split never lengthens the border, so the input's border points
// between their ends would stay interior, and fold). Peel them first: a triangle on a border
// loop longer than D-28 closes whose angle opposite the border edge is kBorderSliverDegrees or
// more goes, if its apex is interior (so every vertex stays manifold and keeps a face); repeated,
// since the apex's new border edges may be slivers too. Returns the triangles peeled.
std::size_t peel_border_slivers(SplitMesh& mesh) {
    const double max_cos = std::cos(constants::kBorderSliverDegrees * M_PI / 180.0);
    std::size_t peeled = 0;
    for (bool changed = true; changed;) {
        changed = false;
        for (SFace* f : mesh.live_faces())
            for (int z = 0; z < 3; ++z) {
                if (f->FFp(z) != f) continue; // not a border edge
                const std::uint32_t u = mesh.vertex_of(f, z), w = mesh.vertex_of(f, (z + 1) % 3),
                                    x = mesh.vertex_of(f, (z + 2) % 3);
                const Vec3 eu = mesh.position(u) - mesh.position(x),
                           ew = mesh.position(w) - mesh.position(x);
                const double lengths = eu.Norm() * ew.Norm();
                if (lengths <= 0 || eu.dot(ew) > max_cos * lengths || mesh.star(x).boundary ||
                    mesh.border_loop_edges(u, kMaxFilledLoop) <= kMaxFilledLoop)
                    continue;
                mesh.remove_face(f);
                ++peeled;
                changed = true;
                break;
            }
    }
    return peeled;
}

// Counters summed over tiles (each tile counts its own records).
void add(ReexpansionStats& into, const ReexpansionStats& from) {
    into.replayed += from.replayed;
    into.skipped_no_vertex += from.skipped_no_vertex;
    into.failed_no_pair += from.failed_no_pair;
    into.unresolved_crossings += from.unresolved_crossings;
    into.crossing_flips += from.crossing_flips;
    into.triangles_removed += from.triangles_removed;
    into.improvement_flips += from.improvement_flips;
    into.merged_by_l_min += from.merged_by_l_min;
    into.border_splits += from.border_splits;
    into.replayed_in_tiles += from.replayed_in_tiles;
    into.deferred_at_tile_borders += from.deferred_at_tile_borders;
    into.late_replayed_in_groups += from.late_replayed_in_groups;
}

class Replayer {
public:
    /// Record k is replayed as the (records − 1 − k)-th: its new vertex and faces take the slots
    /// of that rank (D-43), so that splits in tiles never allocate and ids do not depend on which
    /// thread got there first; replayed in order, the ids are the ones a sequential replay gives.
    Replayer(const ReexpansionInput& input, const Execution& exec, ReexpansionObserver* observer)
        : points_(input.points), normals_(input.normals), records_(input.records),
          options_(input.options), l_min_(input.l_min), observer_(observer),
          mesh_(input.coarse.positions, input.coarse.triangles,
                input.coarse.positions.size() + input.records.size(),
                input.coarse.triangles.size() + 2 * input.records.size(), exec),
          vertices_of_(input.points.size(), input.coarse.vertex_node),
          vertex_node_(input.coarse.vertex_node), first_vertex_(input.coarse.positions.size()),
          first_face_(input.coarse.triangles.size()), tiles_(input.points.size()),
          waiting_(input.points.size(), 0),
          waiting_vertex_(input.coarse.positions.size() + input.records.size(), 0) {
        mesh_.add_slots(records_.size(), 2 * records_.size());
        vertex_node_.resize(first_vertex_ + records_.size(), ReexpandedMesh::kNoNode);
        alias_ = IndexVector<PointIndex, PointIndex>(input.points.size(), ReexpandedMesh::kNoNode);
        for (PointIndex node : input.coarse.vertex_node) alias_[node] = node;
        if (tiles_.count > 1) {
            std::vector<std::uint32_t> owner(mesh_.vertex_count());
            for (std::size_t v = 0; v < first_vertex_; ++v)
                owner[v] = tiles_.tile_of(vertex_node_[VertexIndex(std::uint32_t(v))].value());
            for (std::size_t rank = 0; rank < records_.size(); ++rank)
                owner[first_vertex_ + rank] = tiles_.tile_of(record(rank).latent);
            mesh_.set_owners(std::move(owner));
        }
    }

    std::size_t peel_border_slivers() { return hrsr::peel_border_slivers(mesh_); }

    std::size_t records() const { return records_.size(); }
    const CollapseRecord& record(std::size_t rank) const {
        return records_[records_.size() - 1 - rank];
    }
    bool short_record(std::size_t rank) const {
        const CollapseRecord& r = record(rank);
        return l_min_ > 0 && (r.active_before - r.latent_before).Norm() < l_min_;
    }

    // Aliasing (D-16): b is represented by a's vertices from now on.
    void alias(const CollapseRecord& r) {
        vertices_of_.share(r.active, r.latent);
        alias_[PointIndex(r.latent)] = alias_[PointIndex(r.active)];
    }

    /// Replays the records of ranks [begin, end) (l_min merges the short ones: `merge_short`),
    /// those of one tile each by one thread where the whole stretch is inside tiles (D-43).
    void replay_range(std::size_t begin, std::size_t end, bool merge_short, const Execution& exec,
                      ReexpansionStats& stats) {
        for (std::size_t rank = begin, report = begin; rank < end;) {
            if (exec.progress && rank >= report) { // often enough to cancel promptly
                exec.progress->update(double(rank) / double(records_.size()));
                report = rank + 1024;
            }
            std::size_t stretch = rank;
            while (stretch < end && inside_tile(stretch)) ++stretch;
            if (stretch - rank >= kMinTiledStretch) {
                replay_in_tiles(rank, stretch, merge_short, exec, stats);
                rank = stretch;
            } else {
                std::uint32_t made = 0, reached = 0;
                step(rank, merge_short, stats, made, reached);
                ++rank;
            }
        }
    }

    // Every vertex at its own node's input point (the last move of a node restores it anyway
    // when every record was replayed; after a stop this is the snap-to-input of §8.1).
    void snap_to_input() {
        for (VertexIndex v : vertex_node_.keys())
            if (vertex_node_[v] != ReexpandedMesh::kNoNode)
                mesh_.move(v.value(), points_[vertex_node_[v].value()]);
    }

    /// The mesh, its vertices renumbered without the slots of records that made none, in node
    /// order (D-46: the spatial order of D-40; a node's copies in slot order), and its faces by
    /// their smallest vertex, so that every whole-mesh pass after it walks memory in that order.
    /// Its loops report no progress (the phase's fraction is complete).
    ReexpandedMesh take_result(const Execution& exec) {
        const Execution quiet = without_progress(exec);
        std::vector<std::uint32_t> first_of_node(points_.size() + 1, 0);
        for (PointIndex node : vertex_node_)
            if (node != ReexpandedMesh::kNoNode) ++first_of_node[node.value() + 1];
        std::partial_sum(first_of_node.begin(), first_of_node.end(), first_of_node.begin());
        std::vector<std::uint32_t> renumber(vertex_node_.size(), ~0u);
        IndexVector<VertexIndex, PointIndex> vertex_node(first_of_node.back(), PointIndex(0));
        for (VertexIndex v : vertex_node_.keys()) {
            const PointIndex node = vertex_node_[v];
            if (node == ReexpandedMesh::kNoNode) continue;
            renumber[v.value()] = first_of_node[node.value()]++;
            vertex_node[VertexIndex(renumber[v.value()])] = node;
        }
        std::vector<Triangle> triangles = mesh_.triangles();
        parallel_for_blocks(quiet, triangles.size(), kCheapBlock,
                            [&](std::size_t, std::size_t first, std::size_t end) {
                                for (std::size_t t = first; t < end; ++t)
                                    for (std::uint32_t& v : triangles[t]) v = renumber[v];
                            });
        sort_by_smallest_vertex(triangles, quiet);
        std::vector<std::array<std::uint32_t, 2>> border = mesh_.border_edges();
        for (auto& e : border)
            for (std::uint32_t& v : e) v = renumber[v];
        return {std::move(vertex_node), std::move(triangles), std::move(border), std::move(alias_)};
    }

private:
    // Below this many records in a row inside tiles the threads would cost more than they save.
    static constexpr std::size_t kMinTiledStretch = 256;
    // D-49: the second parallel round's groups hold 2^kGroupShift consecutive tiles (smaller
    // groups saved nothing at 800k points: more of their records reach another group again).
    static constexpr int kGroupShift = 3;

    enum class Outcome { Done, Conflict, ImproveLater };
    struct Late {
        std::size_t rank;
        std::uint32_t c2; ///< ImproveLater: the vertex the split made; Conflict: unused
        Outcome outcome;
        std::uint32_t reached; ///< the tile whose vertex stopped it (its own: it waited)
    };
    struct TileLate {
        std::vector<Late> records;
        std::vector<std::uint32_t> vertices; ///< marked waiting
    };

    bool inside_tile(std::size_t rank) const {
        const CollapseRecord& r = record(rank);
        return tiles_.count > 1 && tiles_.tile_of(r.active) == tiles_.tile_of(r.latent);
    }

    // One record as a sequential replay takes it.
    // `made`: the vertex a split made (for flips that wait); `reached`: the tile whose vertex
    // stopped it (guarded).
    Outcome step(std::size_t rank, bool merge_short, ReexpansionStats& stats, std::uint32_t& made,
                 std::uint32_t& reached) {
        if (merge_short && short_record(rank)) {
            alias(record(rank));
            ++stats.merged_by_l_min;
            return Outcome::Done;
        }
        return replay(rank, stats, made, reached);
    }

    // D-43: ranks [begin, end) all inside tiles; each tile's records in order by one thread,
    // the mesh guarded. A record whose work reaches another tile's vertex stops before it changes
    // anything there and waits, with every later record of its nodes or of their vertices, until
    // the threads are done; then the waiting records are replayed in order.
    void replay_in_tiles(std::size_t begin, std::size_t end, bool merge_short,
                         const Execution& exec, ReexpansionStats& stats) {
        std::vector<std::vector<std::uint32_t>> by_tile(tiles_.count);
        for (std::size_t rank = begin; rank < end; ++rank)
            by_tile[tiles_.tile_of(record(rank).active)].push_back(std::uint32_t(rank));
        std::vector<std::uint32_t> busy;
        for (std::uint32_t t = 0; t < by_tile.size(); ++t)
            if (!by_tile[t].empty()) busy.push_back(t);
        std::vector<ReexpansionStats> tile_stats(busy.size());
        std::vector<TileLate> late(busy.size());
        std::vector<double> seconds(busy.size());
        // Progress of the stretch as progress of the phase, from the calling thread; a cancel
        // stops the loop.
        Progress stretch([&](const std::string&, double fraction) {
            exec.progress->update((double(begin) + fraction * double(end - begin)) /
                                  double(records_.size()));
            return true;
        });
        const Execution threads{exec.threads, exec.progress ? &stretch : nullptr};
        {
            const GuardedScope guarded(mesh_, 0);
            parallel_for(
                threads, busy.size(),
                [&](std::size_t i) {
                    seconds[i] = TileTimes::seconds_of([&] {
                        replay_tile(by_tile[busy[i]], busy[i], merge_short, tile_stats[i], late[i]);
                    });
                },
                1);
        }
        stats.tile_times.add_stretch(seconds.data(), busy.size());
        std::vector<Late> all =
            replay_late_in_groups(gathered(tile_stats, late, stats), merge_short, exec, stats);
        for (const Late& l : all) {
            if (l.outcome == Outcome::Conflict) {
                ++stats.deferred_at_tile_borders;
                std::uint32_t made = 0, reached = 0;
                step(l.rank, merge_short, stats, made, reached);
            } else {
                stats.improvement_flips += improve_around(mesh_, l.c2, options_);
            }
        }
    }

    // D-49: what waited at the tiles' borders (in rank order) is replayed again in parallel by
    // groups of consecutive tiles, where most of those borders are inside a group, each group's
    // records in rank order by one thread under the same guard; what reaches another group waits
    // again and is returned, in rank order, for one thread.
    std::vector<Late> replay_late_in_groups(std::vector<Late> late, bool merge_short,
                                            const Execution& exec, ReexpansionStats& stats) {
        const std::size_t groups = ((tiles_.count - 1) >> kGroupShift) + 1;
        if (groups < 2 || late.empty()) return late;
        std::vector<std::vector<Late>> by_group(groups);
        for (const Late& l : late)
            by_group[tiles_.tile_of(record(l.rank).active) >> kGroupShift].push_back(l);
        std::vector<std::uint32_t> busy;
        for (std::uint32_t g = 0; g < groups; ++g)
            if (!by_group[g].empty()) busy.push_back(g);
        std::vector<ReexpansionStats> group_stats(busy.size());
        std::vector<TileLate> still(busy.size());
        {
            const GuardedScope guarded(mesh_, kGroupShift);
            parallel_for(
                without_progress(exec), busy.size(),
                [&](std::size_t i) {
                    replay_group(by_group[busy[i]], busy[i], merge_short, group_stats[i], still[i]);
                },
                1);
        }
        return gathered(group_stats, still, stats);
    }

    // The mesh guarded for one parallel round, a thread's share being its tile (shift 0) or its
    // group of 2^shift tiles; unguarded again however the round ends.
    class GuardedScope {
    public:
        GuardedScope(SplitMesh& mesh, int shift) : mesh_(mesh) {
            mesh_.group_tiles(shift);
            mesh_.guard(true);
        }
        ~GuardedScope() {
            mesh_.guard(false);
            mesh_.group_tiles(0);
        }
        GuardedScope(const GuardedScope&) = delete;
        GuardedScope& operator=(const GuardedScope&) = delete;

    private:
        SplitMesh& mesh_;
    };

    // After a parallel round: the workers' stats added to `stats`, their waiting marks cleared,
    // and what waited, in rank order.
    std::vector<Late> gathered(const std::vector<ReexpansionStats>& worker_stats,
                               const std::vector<TileLate>& late, ReexpansionStats& stats) {
        std::vector<Late> all;
        for (std::size_t i = 0; i < worker_stats.size(); ++i) {
            add(stats, worker_stats[i]);
            all.insert(all.end(), late[i].records.begin(), late[i].records.end());
        }
        release(late);
        std::sort(all.begin(), all.end(),
                  [](const Late& a, const Late& b) { return a.rank < b.rank; });
        return all;
    }

    // A record that reached a tile of another group in the first round goes straight to the
    // last one (it would stop there again), waiting as it would.
    void replay_group(const std::vector<Late>& records, std::uint32_t group, bool merge_short,
                      ReexpansionStats& stats, TileLate& late) {
        SplitMesh::work_for(group);
        for (const Late& l : records) {
            const bool elsewhere = (l.reached >> kGroupShift) != group;
            if (l.outcome == Outcome::ImproveLater) {
                if (elsewhere || !improved_around(l.c2, stats)) late.records.push_back(l);
                continue;
            }
            const CollapseRecord& r = record(l.rank);
            Outcome outcome = Outcome::Conflict;
            std::uint32_t made = 0, reached = l.reached;
            if (!elsewhere && !must_wait(r, reached))
                outcome = step(l.rank, merge_short, stats, made, reached);
            if (outcome == Outcome::Conflict) {
                wait(r, late);
                late.records.push_back({l.rank, made, outcome, reached});
                continue;
            }
            ++stats.deferred_at_tile_borders;
            ++stats.late_replayed_in_groups;
            if (outcome == Outcome::ImproveLater)
                late.records.push_back({l.rank, made, outcome, reached});
        }
    }

    // The local flips around c2 that waited, made; false if they reach another group.
    bool improved_around(std::uint32_t c2, ReexpansionStats& stats) {
        try {
            stats.improvement_flips += improve_around(mesh_, c2, options_);
            return true;
        } catch (const TileConflict&) {
            return false;
        }
    }

    // Record r waits: so does every later record of its nodes or of their vertices.
    void wait(const CollapseRecord& r, TileLate& late) {
        waiting_[r.active] = waiting_[r.latent] = 1;
        for (std::uint32_t v : vertices_of_.of(r.active))
            if (mesh_.owns(v)) {
                waiting_vertex_[v] = 1;
                late.vertices.push_back(v);
            }
    }

    // The marks of the records that waited, cleared.
    void release(const std::vector<TileLate>& late) {
        for (const TileLate& l : late) {
            for (std::uint32_t v : l.vertices) waiting_vertex_[v] = 0;
            for (const Late& w : l.records)
                waiting_[record(w.rank).active] = waiting_[record(w.rank).latent] = 0;
        }
    }

    // Whether record r must wait: a record of its nodes or of their vertices waits, or its
    // vertices are another tile's (it would stop there anyway: `reached` says whose).
    bool must_wait(const CollapseRecord& r, std::uint32_t& reached) const {
        if (waiting_[r.active] || waiting_[r.latent]) return true;
        for (std::uint32_t v : vertices_of_.of(r.active)) {
            if (!mesh_.owns(v)) {
                reached = mesh_.owner(v);
                return true;
            }
            if (waiting_vertex_[v]) return true;
        }
        return false;
    }

    void replay_tile(const std::vector<std::uint32_t>& ranks, std::uint32_t tile, bool merge_short,
                     ReexpansionStats& stats, TileLate& late) {
        SplitMesh::work_for(tile);
        for (std::uint32_t rank : ranks) {
            const CollapseRecord& r = record(rank);
            Outcome outcome = Outcome::Conflict;
            std::uint32_t made = 0, reached = tile;
            if (!must_wait(r, reached)) outcome = step(rank, merge_short, stats, made, reached);
            if (outcome == Outcome::Done) {
                ++stats.replayed_in_tiles;
                continue;
            }
            if (outcome == Outcome::Conflict) wait(r, late);
            late.records.push_back({rank, made, outcome, reached});
        }
    }

    Outcome replay(std::size_t rank, ReexpansionStats& stats, std::uint32_t& made,
                   std::uint32_t& reached) {
        const CollapseRecord& r = record(rank);
        // Stays valid while r.latent's entry changes: that is another word or list.
        const NodeVertices::Span candidates = vertices_of_.of(r.active);
        if (candidates.size == 0) { // the node never reached the mesh: its subtree is dropped
            ++stats.skipped_no_vertex;
            return Outcome::Done;
        }
        bool unresolved = false;
        const std::size_t removed_before = stats.triangles_removed;
        thread_local Star star; // reused: no allocation per split
        std::uint32_t c = 0, c2 = 0;
        SplitChoice choice;
        try {
            for (std::uint32_t copy : candidates) {
                if (mesh_.isolated(copy)) continue;
                const CrossingStats cs = resolve_crossings(mesh_, copy, r.active_before,
                                                           r.latent_before, normals_[r.active]);
                stats.crossing_flips += cs.flips;
                stats.triangles_removed += cs.triangles_removed;
                unresolved = unresolved || cs.unresolved > 0 || cs.round_limit;
                mesh_.move(copy, r.active_before);
            }
            for (std::uint32_t copy : candidates) { // the first copy (in id order) with a pair
                if (mesh_.isolated(copy)) continue;
                mesh_.star(copy, star);
                choice = choose_split(mesh_, copy, star, r.active_before, r.latent_before);
                if (!choice.found) continue;
                c = copy;
                const std::size_t face = first_face_ + 2 * rank;
                c2 = mesh_.split(c, star, choice.a, choice.b, r.latent_before, choice.omit,
                                 {std::uint32_t(first_vertex_ + rank), {face, face + 1}});
                break;
            }
        } catch (const TileConflict& conflict) {
            reached = conflict.tile;
            return Outcome::Conflict;
        }
        if (!choice.found) {
            ++stats.failed_no_pair;
            alias(r);
            return Outcome::Done;
        }
        made = c2;
        vertex_node_[VertexIndex(c2)] = PointIndex(r.latent);
        vertices_of_.set(r.latent, c2);
        alias_[PointIndex(r.latent)] = PointIndex(r.latent);
        ++stats.replayed;
        stats.border_splits += choice.omit != SplitMesh::BorderSplit::None;
        if (unresolved) ++stats.unresolved_crossings;
        Outcome outcome = Outcome::Done;
        try {
            stats.improvement_flips += improve_around(mesh_, c2, options_);
        } catch (const TileConflict& conflict) {
            reached = conflict.tile;
            outcome = Outcome::ImproveLater; // the split stands; its flips wait
        }
        if (observer_) { // one thread (replay_collapses): the observer may read the whole mesh
            const bool guarded = mesh_.guarded();
            mesh_.guard(false);
            observer_->split_done(mesh_, c, c2, r.active_before, r.latent_before,
                                  stats.triangles_removed - removed_before, unresolved);
            mesh_.guard(guarded);
        }
        return outcome;
    }

    const std::vector<Vec3>& points_;
    const std::vector<Vec3>& normals_;
    const std::vector<CollapseRecord>& records_;
    const ReexpandOptions& options_;
    double l_min_;
    ReexpansionObserver* observer_;
    SplitMesh mesh_;
    NodeVertices vertices_of_;
    IndexVector<VertexIndex, PointIndex> vertex_node_; ///< per vertex slot (kNoNode: unused)
    IndexVector<PointIndex, PointIndex> alias_;
    std::size_t first_vertex_, first_face_;    ///< the slots of rank 0
    collapsing::Tiles tiles_;                  ///< D-42's tiles of the spatial order
    std::vector<std::uint8_t> waiting_;        ///< per node: a record of it waits (D-43)
    std::vector<std::uint8_t> waiting_vertex_; ///< per vertex slot: a record of it waits
};

} // namespace

ReexpandedMesh replay_collapses(ReexpansionInput input, const Execution& exec,
                                ReexpansionStats& stats, ReexpansionObserver* observer) {
    const ReexpandOptions& options = input.options;
    validate(options);
    stats.records = input.records.size();
    Replayer replayer(input, without_progress(exec), observer);
    stats.border_slivers_peeled = replayer.peel_border_slivers();
    stats.tiles = collapsing::Tiles(input.points.size()).count;
    stats.tile_times.tiles = stats.tiles;
    // An observer reads the whole mesh after each split: one thread, the same tiles.
    const Execution replay_exec{observer ? 1 : exec.threads, exec.progress};
    if (exec.progress) exec.progress->begin("re-expansion");
    const std::size_t n = replayer.records();
    std::size_t end = n;
    if (options.l_min_mode == LMinMode::Stop)
        for (std::size_t rank = 0; rank < n; ++rank)
            if (replayer.short_record(rank)) {
                end = rank;
                break;
            }
    replayer.replay_range(0, end, options.l_min_mode != LMinMode::Stop, replay_exec, stats);
    if (end < n) { // everything not yet replayed stays merged into its surviving node
        stats.stopped_at_l_min = true;
        for (std::size_t rank = end; rank < n; ++rank) {
            replayer.alias(replayer.record(rank));
            ++stats.merged_by_l_min;
        }
    }
    replayer.snap_to_input();
    std::vector<CollapseRecord>().swap(input.records); // spent: free them before the export
    ReexpandedMesh result = replayer.take_result(exec);
    if (observer) observer->finished(result);
    return result;
}

} // namespace hrsr
