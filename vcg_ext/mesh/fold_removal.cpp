#include "mesh/fold_removal.h"

#include "geometry.h"
#include "graph/concurrent_sets.h"
#include "mesh/fans.h"
#include "mesh/small_holes_fill.h"
#include "mesh/triangle_against_faces.h"
#include "mesh/triangle_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace hrsr {

namespace {

// Holes with more corners get the fans only: the best triangulation is cubic in the corners.
constexpr std::size_t kMaxOptimisedHole = 48;
// The most vertices a fold takes out with it before its hole is left open instead.
constexpr std::size_t kMaxRegionVertices = 8;
// How far from a face cut inside the mesh a disc that closes its hole again may reach, in the
// face's longest edges (1.5: the dragon sample's holes close as with no limit, and no point far
// from the crossing line of two planes goes; 2 took points 7 spacings away).
constexpr double kClosingReach = 1.5;
// A removed vertex goes back over a face at most this many of the face's longest sides off its
// plane (the lion's put back lie at a median of 0.13, 90 % under 0.38; a few reached 0.98).
constexpr double kMaxPutBackHeight = 0.5;
// A vertex at the border goes back as triangles that close its corner, or as one triangle across
// a border edge (D-41), only if no angle of them is smaller (a sliver hanging off the border is
// worse than a point left out).
constexpr double kMinBorderPutBackAngle = 15.0 * M_PI / 180.0;
// D-38: the gaps closed after the folds have up to six edges, one more than D-28's fill takes
// (the walk has taken six since D-38 was written; its measurements were made so). Five only left
// bunny 119 → 125, lion 3,393 → 3,425, LMS400 table 5,434 → 5,476 boundary edges
// (docs/BENCHMARKS.md, session 28).
constexpr std::size_t kMaxClosedGap = kMaxFilledLoop + 1;
// D-48: a border loop is a slit when its two sides are at most kMaxSlitWidth edges of the faces
// around it apart (medians: a gap narrower than about a spacing and a half holds no row of
// points), at most kMaxSlitRoundness as wide as a circle of its perimeter (the camel head's
// slits 0.21–0.41, round holes 0.9–1.4) and none of its edges is longer than kMaxSlitEdge such
// edges (docs/ALGORITHM.md D-48).
constexpr double kMaxSlitWidth = 1.5;
constexpr double kMaxSlitRoundness = 0.6;
constexpr double kMaxSlitEdge = 4.0;
// A walk around a vertex's fan gives up after this many faces (a fan is far smaller).
constexpr std::size_t kMaxFanWalk = 1024;
constexpr std::uint32_t kNoFace = ~0u;

/// A ball that a disc of fans stays in.
struct Reach {
    Vec3 centre;
    double radius;
};

/// The hole a vertex's fan leaves: its link, in the fan's order.
struct Hole {
    std::vector<std::uint32_t> corners;
    bool closed = false; ///< an inner vertex: each side, the last to the first too, is an edge
};

// The hole of `faces` around v (each face holds v once): its link edges chained from the one
// corner that starts no chain... or, for an inner vertex, from the first face's. Fails (nullopt)
// where the link is not one simple path or cycle: a vertex of several fans, a repeated corner.
std::optional<Hole> link_of(std::uint32_t v, const std::vector<Triangle>& faces) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const Triangle& t : faces) {
        const auto k = std::size_t(std::find(t.begin(), t.end(), v) - t.begin());
        if (k == 3 || std::count(t.begin(), t.end(), v) != 1) return std::nullopt;
        edges.emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
    }
    const auto from = [&](std::uint32_t a) {
        return std::find_if(edges.begin(), edges.end(),
                            [a](const auto& e) { return e.first == a; });
    };
    std::optional<std::uint32_t> start;
    for (const auto& e : edges) {
        const auto same_source = std::count_if(edges.begin(), edges.end(),
                                               [&](const auto& o) { return o.first == e.first; });
        const auto same_target = std::count_if(edges.begin(), edges.end(),
                                               [&](const auto& o) { return o.second == e.second; });
        if (same_source > 1 || same_target > 1) return std::nullopt;
        const bool is_target = std::any_of(edges.begin(), edges.end(),
                                           [&](const auto& o) { return o.second == e.first; });
        if (!is_target) {
            if (start) return std::nullopt; // two chains: two fans
            start = e.first;
        }
    }
    Hole hole;
    hole.closed = !start;
    std::uint32_t corner = start.value_or(edges.front().first);
    hole.corners.push_back(corner);
    for (std::size_t used = 0; used < edges.size(); ++used) {
        const auto e = from(corner);
        if (e == edges.end()) return std::nullopt;
        corner = e->second;
        if (corner == hole.corners.front()) break;
        hole.corners.push_back(corner);
    }
    // Every edge used once, and no corner twice (the chain closed only at its start).
    const std::size_t expected = hole.closed ? edges.size() : edges.size() + 1;
    std::vector<std::uint32_t> sorted = hole.corners;
    std::sort(sorted.begin(), sorted.end());
    if (hole.corners.size() != expected ||
        std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end() ||
        std::binary_search(sorted.begin(), sorted.end(), v))
        return std::nullopt;
    return hole;
}

/// The border of a disc of faces, as a hole, and the vertices inside it.
struct DiscBorder {
    Hole hole;
    std::vector<std::uint32_t> inner; ///< the vertices that go with the faces
};

class Remover {
public:
    // `search` holds the pairs left on the mesh `triangles` and the grid that found them.
    Remover(FoldSearch& search, const std::vector<Vec3>& normals,
            const std::vector<Triangle>& triangles, std::size_t pinhole_edges)
        : pinhole_edges_(std::max(pinhole_edges, kMaxFilledLoop)), positions_(search.positions),
          exec_(search.exec), normals_(normals), triangles_(triangles),
          original_faces_(triangles.size()), representative_(search.representative),
          geometry_(search.geometry), grid_(search.grid),
          at_(corners_by_vertex(positions_.size(), triangles, exec_)), alive_(triangles.size(), 1),
          touched_(positions_.size(), 0), pairs_(search.pairs) {
        index_pairs();
        for (std::uint32_t v = 0; v < representative_.size(); ++v)
            if (representative_[v] != v) copies_[representative_[v]].push_back(v);
        for (auto& [first, others] : copies_) others.push_back(first);
    }

    // Every pair, in order, while both its faces stand.
    void run(FoldRemovalStats& stats) {
        stats.pairs_before = pairs_.size();
        for (const TrianglePair& p : pairs_)
            if (alive_[p.first] && alive_[p.second]) resolve(p, stats);
        for (const Triangle& t : inner_cuts_)
            if (const std::size_t removed = close_cut(t)) {
                --stats.faces_cut;
                stats.vertices_removed += removed;
                ++stats.holes_refilled;
            }
        close_small_cut_holes(stats);
        close_small_holes_left(stats);
        put_back_the_rest();
        close_pinholes(stats);
        close_slits(stats);
        stats.vertices_reinserted = reinserted_;
        stats.points_placed = placed_;
        stats.vertices_removed -= reinserted_;
        stats.pairs_after = std::size_t(std::count_if(pairs_.begin(), pairs_.end(), [&](auto p) {
            return alive_[p.first] && alive_[p.second];
        }));
    }

    // The faces that stand (kept ones in order, then the new ones) over the vertices that
    // still have one; pinched vertices split into copies.
    FoldRemoval result(std::vector<Triangle>& triangles, FoldRemovalStats stats) const {
        triangles.clear();
        for (std::size_t f = 0; f < triangles_.size(); ++f)
            if (alive_[f]) triangles.push_back(triangles_[f]);
        // Only the corners of faces cut or added can be pinched: every vertex had one fan.
        std::vector<std::uint8_t> changed(positions_.size(), 0);
        for (std::size_t f = 0; f < triangles_.size(); ++f)
            if (!alive_[f] || f >= original_faces_)
                for (std::uint32_t v : triangles_[f]) changed[v] = 1;
        FoldRemoval out;
        out.vertex_source =
            compact_and_split_vertices(positions_.size(), triangles, &changed, exec_);
        std::vector<std::uint8_t> seen(positions_.size(), 0);
        for (std::uint32_t v : out.vertex_source) {
            stats.vertex_copies += seen[v];
            seen[v] = 1;
        }
        out.stats = stats;
        return out;
    }

private:
    // Per face, the faces it intersects (CSR), and how many of them stand.
    void index_pairs() {
        partner_start_.assign(triangles_.size() + 1, 0);
        for (const TrianglePair& p : pairs_) {
            ++partner_start_[p.first + 1];
            ++partner_start_[p.second + 1];
        }
        for (std::size_t f = 0; f < triangles_.size(); ++f)
            partner_start_[f + 1] += partner_start_[f];
        partner_.resize(partner_start_.back());
        std::vector<std::uint32_t> next(partner_start_.begin(), partner_start_.end() - 1);
        for (const TrianglePair& p : pairs_) {
            partner_[next[p.first]++] = p.second;
            partner_[next[p.second]++] = p.first;
        }
        live_pairs_.resize(triangles_.size());
        for (std::size_t f = 0; f < triangles_.size(); ++f)
            live_pairs_[f] = partner_start_[f + 1] - partner_start_[f];
    }

    // The pair goes by the first of D-32's steps that works (ALGORITHM.md): a corner's fan
    // removed and its hole filled (corners by most pairs around them, fills facing the normals
    // first); a flap at the border cut; a disc of fans removed and filled; one face cut.
    void resolve(const TrianglePair& p, FoldRemovalStats& stats) {
        std::vector<std::pair<std::size_t, std::uint32_t>> candidates; // (-pairs, vertex)
        for (std::uint32_t f : {p.first, p.second})
            for (std::uint32_t v : triangles_[f]) {
                std::size_t pairs = 0;
                for (std::uint32_t g : faces_of(v)) pairs += live_pairs_[g];
                candidates.emplace_back(std::numeric_limits<std::size_t>::max() - pairs, v);
            }
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        for (const bool facing : {true, false})
            for (const auto& c : candidates)
                if (refill(c.second, facing)) {
                    ++stats.vertices_removed;
                    ++stats.holes_refilled;
                    return;
                }
        // A face on the border folded over (facing away from its corners' normals) is a flap
        // that no point needs: where no fan's fill fits, it goes, which only moves the border by
        // an edge (tried before the fans, it left the dragon's vertices 1,016 boundary edges
        // instead of 1,006; the fans cost 3 more points there).
        for (std::uint32_t f : {p.first, p.second})
            if (border_edges(f) == 1 && !proper(triangles_[f], true)) {
                retire(f);
                ++stats.faces_cut;
                return;
            }
        for (const auto& c : candidates)
            if (const std::size_t removed = refill_region(c.second)) {
                stats.vertices_removed += removed;
                ++stats.holes_refilled;
                return;
            }
        // The last resort: one face of the pair goes, the one that opens the mesh least (a
        // face with an edge or two on the border only moves the border), then the one in more
        // pairs.
        const auto cost = [&](std::uint32_t f) {
            return std::make_tuple(3 - 2 * border_edges(f), -std::int64_t(live_pairs_[f]), f);
        };
        const std::uint32_t cut =
            std::min(p.first, p.second, [&](auto a, auto b) { return cost(a) < cost(b); });
        if (border_edges(cut) == 0) inner_cuts_.push_back(triangles_[cut]);
        cut_corners_.insert(cut_corners_.end(), triangles_[cut].begin(), triangles_[cut].end());
        retire(cut);
        ++stats.faces_cut;
    }

    // A face cut inside the mesh leaves a triangular hole. Once every pair is gone, what stood in
    // the way of the fills may be gone too: the hole is closed as close_around() closes one.
    // Returns the vertices removed (0: still open).
    std::size_t close_cut(const Triangle& cut) {
        // The hole is still there: no standing face holds the cut face's edges.
        for (int k = 0; k < 3; ++k)
            if (has_directed_edge(cut[k], cut[(k + 1) % 3])) return 0;
        return close_around({cut[0], cut[1], cut[2]});
    }

    // The holes that cuts left inside the mesh and close_cut did not close: several cuts next
    // to each other leave one hole that is no single cut face's. A border loop through a cut
    // face's corner, of at most kMaxClosedGap edges, along a cut face and with no edge on the
    // border of the given mesh (a hole of a closed surface, as D-28 closes them), is
    // triangulated across, or else closed as close_cut closes a cut face's hole: a corner's fan
    // filled together with it, then a disc of fans near it.
    void close_small_cut_holes(FoldRemovalStats& stats) {
        std::sort(cut_corners_.begin(), cut_corners_.end());
        cut_corners_.erase(std::unique(cut_corners_.begin(), cut_corners_.end()),
                           cut_corners_.end());
        for (std::uint32_t v : cut_corners_) {
            if (faces_of(v).empty()) continue;
            const std::optional<Hole> hole = small_cut_hole(v);
            if (!hole) continue;
            std::size_t removed = 0;
            if (close_hole(*hole) || (removed = close_around(hole->corners)) > 0) {
                --stats.faces_cut;
                ++stats.holes_refilled;
                stats.vertices_removed += removed;
            }
        }
    }

    // D-38: a border loop of at most kMaxClosedGap edges is a gap of about a spacing (D-28),
    // whichever phase left it; D-28's fans cross the mesh where the faces around it fold over
    // the gap. Such a loop is closed the way close_cut closes a cut face's hole: triangulated
    // across, else a corner's fan filled with it, else a disc of fans near it; the vertices
    // those take out must all go back at once (put_back), or the closing is undone: a gap is
    // not worth a point.
    void close_small_holes_left(FoldRemovalStats& stats) {
        std::vector<std::uint8_t> tried(positions_.size(), 0);
        for (std::uint32_t v : border_candidates())
            if (!tried[v] && !faces_of(v).empty())
                stats.small_holes_closed += close_loop_at(v, kMaxClosedGap, tried, stats);
    }

    // D-45: once every other vertex is back, the loops longer than kMaxFilledLoop and no longer
    // than pinhole_edges_ of a piece whose every border loop is so short (as D-39 on the coarse
    // mesh) are closed as D-38 closes a gap, at most a vertex per kMaxFilledLoop edges left out.
    // Last, so that no vertex the earlier steps placed is kept out by their fills.
    void close_pinholes(FoldRemovalStats& stats) {
        if (pinhole_edges_ <= kMaxFilledLoop) return;
        const std::vector<std::uint32_t> starts = border_candidates();
        const std::vector<std::size_t> loop_edges = border_loops_at(starts, pinhole_edges_);
        bool any = false;
        for (std::size_t edges : loop_edges)
            any = any || (edges > kMaxFilledLoop && edges <= pinhole_edges_);
        if (!any) return; // most meshes: no pass over the faces
        const std::vector<std::uint8_t> closed_but_for_pinholes =
            pieces_closed_but_for_pinholes(starts, loop_edges);
        std::vector<std::uint8_t> tried(positions_.size(), 0);
        for (std::size_t i = 0; i < starts.size(); ++i) {
            const std::uint32_t v = starts[i];
            if (!tried[v] && loop_edges[i] > kMaxFilledLoop && loop_edges[i] <= pinhole_edges_ &&
                closed_but_for_pinholes[i] && !faces_of(v).empty())
                stats.small_holes_closed += close_loop_at(
                    v, pinhole_edges_, tried, stats, std::size_t(loop_edges[i]) / kMaxFilledLoop);
        }
    }

    // D-48: a border loop of up to kMaxOptimisedHole edges whose two sides run closer than
    // kMaxSlitWidth edges of the faces around it (a slit: where a thin part's rim or two sheets
    // closer than the spacing left the faces apart) is closed as D-38 closes a gap; every vertex
    // the closing takes out goes back, or it is undone.
    void close_slits(FoldRemovalStats& stats) {
        const std::vector<std::uint32_t> starts = border_candidates();
        const std::vector<std::size_t> loop_edges = border_loops_at(starts, kMaxOptimisedHole);
        std::vector<std::uint8_t> tried(positions_.size(), 0);
        for (std::size_t i = 0; i < starts.size(); ++i) {
            const std::uint32_t v = starts[i];
            if (tried[v] || loop_edges[i] <= kMaxClosedGap || loop_edges[i] > kMaxOptimisedHole ||
                faces_of(v).empty())
                continue;
            const std::optional<Hole> hole = small_hole(v, false, kMaxOptimisedHole);
            if (!hole) continue;
            for (std::uint32_t c : hole->corners) tried[c] = 1;
            if (is_slit(hole->corners))
                stats.slits_closed += close_loop(*hole, kMaxOptimisedHole, stats);
        }
    }

    // A slit: the loop's median width (each corner's distance to the nearest corner at least a
    // quarter of the loop away along it) is at most kMaxSlitWidth spacings, where the spacing is
    // the median edge of the faces around its corners; it is long for its width (at most
    // kMaxSlitRoundness of a circle's of its perimeter: a round hole that narrow is D-38's); and
    // no loop edge is longer than kMaxSlitEdge spacings (a loop with such edges is what is left
    // of a real hole that faces already bridge: the shark's bored holes at p = 1/4).
    bool is_slit(const std::vector<std::uint32_t>& loop) const {
        const std::size_t m = loop.size();
        std::vector<double> edges;
        for (std::uint32_t c : loop)
            any_face(c, [&](const Triangle& t) {
                for (int k = 0; k < 3; ++k)
                    edges.push_back((positions_[t[k]] - positions_[t[(k + 1) % 3]]).Norm());
                return false;
            });
        if (edges.empty()) return false;
        std::nth_element(edges.begin(), edges.begin() + std::ptrdiff_t(edges.size() / 2),
                         edges.end());
        const double spacing = edges[edges.size() / 2];
        double perimeter = 0;
        for (std::size_t i = 0; i < m; ++i) {
            const double edge = (positions_[loop[i]] - positions_[loop[(i + 1) % m]]).Norm();
            if (edge > kMaxSlitEdge * spacing) return false;
            perimeter += edge;
        }
        const std::size_t apart = std::max<std::size_t>(2, m / 4);
        std::vector<double> width(m, std::numeric_limits<double>::infinity());
        for (std::size_t i = 0; i < m; ++i)
            for (std::size_t j = 0; j < m; ++j) {
                const std::size_t steps = std::min((i + m - j) % m, (j + m - i) % m);
                if (steps >= apart)
                    width[i] =
                        std::min(width[i], (positions_[loop[i]] - positions_[loop[j]]).Norm());
            }
        std::nth_element(width.begin(), width.begin() + std::ptrdiff_t(m / 2), width.end());
        const double median_width = width[m / 2];
        return median_width <= kMaxSlitWidth * spacing &&
               median_width <= kMaxSlitRoundness * perimeter / (2 * M_PI);
    }

    // The vertices a border loop may start at: those on the border of the given mesh, and the
    // corners of faces ever added or cut (the quick tests first: most vertices are neither; a
    // vertex whose cut faces all stand again has its given faces, and its given border).
    std::vector<std::uint32_t> border_candidates() {
        if (given_border_.empty()) {
            const std::vector<std::int64_t> open_fan = given_fan_ends();
            given_border_.resize(open_fan.size());
            for (std::size_t v = 0; v < open_fan.size(); ++v) given_border_[v] = open_fan[v] != 0;
        }
        std::vector<std::uint32_t> out;
        for (std::uint32_t v = 0; v < positions_.size(); ++v)
            if (touched_[v] || given_border_[v]) out.push_back(v);
        return out;
    }

    // Closes the loop through v of at most `limit` edges, if there is one, as D-38 does; at
    // most `may_lose` of the vertices it takes out may stay out. Whether it closed.
    bool close_loop_at(std::uint32_t v, std::size_t limit, std::vector<std::uint8_t>& tried,
                       FoldRemovalStats& stats, std::size_t may_lose = 0) {
        const std::optional<Hole> hole = small_hole(v, false, limit);
        if (!hole) return false;
        for (std::uint32_t c : hole->corners) tried[c] = 1;
        return close_loop(*hole, limit, stats, may_lose);
    }

    // close_loop_at() on the loop found.
    bool close_loop(const Hole& hole, std::size_t limit, FoldRemovalStats& stats,
                    std::size_t may_lose = 0) {
        // A lone triangle's outline: the fill would repeat the triangle.
        if (hole.corners.size() == 3 &&
            repeats_a_face({hole.corners[2], hole.corners[1], hole.corners[0]}))
            return false;
        const Undo undo = begin_undo();
        std::size_t lost = 0;
        bool closed = close_small_hole(hole, limit);
        if (closed && may_lose == 0) {
            closed = put_back_taken_out();
        } else if (closed) {
            for (std::uint32_t r : taken_out()) lost += !put_back(r);
            closed = lost <= may_lose;
        }
        if (closed) {
            stats.vertices_removed += lost;
        } else {
            rewind(undo);
        }
        retired_log_.reset();
        // Every vertex it took out is back (or lost, counted as removed): none counts as put back.
        reinserted_ = undo.reinserted;
        return closed;
    }

    // Per start, whether its piece (connected by standing faces) is closed but for loops of at
    // most pinhole_edges_: every border loop of it that short, none through a vertex with two
    // border edges out, and more interior than border vertices (D-39's test of a closed coarse
    // piece). `loop_edges` are those of border_loops_at() at the `starts`. The pieces are joined
    // by parallel blocks of faces (a piece's root is its smallest vertex for any thread count),
    // and only the starts' pieces have their vertices counted.
    std::vector<std::uint8_t>
    pieces_closed_but_for_pinholes(const std::vector<std::uint32_t>& starts,
                                   const std::vector<std::size_t>& loop_edges) const {
        const std::size_t n = positions_.size();
        ConcurrentSets pieces(n, exec_);
        parallel_for_blocks(exec_, triangles_.size(), kCheapBlock,
                            [&](std::size_t, std::size_t first, std::size_t end) {
                                for (std::size_t f = first; f < end; ++f)
                                    if (alive_[f]) {
                                        const Triangle& t = triangles_[f];
                                        pieces.unite(t[0], t[1]);
                                        pieces.unite(t[1], t[2]);
                                    }
                            });
        constexpr std::int32_t kNotAsked = -1;
        std::vector<std::int32_t> slot_of_root(n, kNotAsked);
        std::vector<std::int32_t> start_slot(starts.size());
        std::int32_t slots = 0;
        for (std::size_t i = 0; i < starts.size(); ++i) {
            std::int32_t& slot = slot_of_root[pieces.find(starts[i])];
            if (slot == kNotAsked) slot = slots++;
            start_slot[i] = slot;
        }
        // Per slot: the piece's vertices with a standing face, less two per border start.
        std::vector<std::vector<std::int64_t>> used(block_count(n, kCheapBlock));
        parallel_for_blocks(exec_, n, kCheapBlock,
                            [&](std::size_t b, std::size_t first, std::size_t end) {
                                used[b].assign(std::size_t(slots), 0);
                                for (auto v = std::uint32_t(first); v < end; ++v) {
                                    const std::int32_t slot = slot_of_root[pieces.find(v)];
                                    if (slot != kNotAsked && has_standing_face(v))
                                        ++used[b][std::size_t(slot)];
                                }
                            });
        std::vector<std::int64_t> interior_minus_border(std::size_t(slots), 0);
        for (const std::vector<std::int64_t>& block : used)
            for (std::size_t s = 0; s < block.size(); ++s) interior_minus_border[s] += block[s];
        std::vector<std::uint8_t> long_loop(std::size_t(slots), 0);
        for (std::size_t i = 0; i < starts.size(); ++i) {
            if (loop_edges[i] == 0) continue; // not on the border (any more)
            const auto slot = std::size_t(start_slot[i]);
            interior_minus_border[slot] -= 2; // counted as interior above
            if (loop_edges[i] > pinhole_edges_) long_loop[slot] = 1;
        }
        std::vector<std::uint8_t> closed(starts.size(), 0);
        for (std::size_t i = 0; i < starts.size(); ++i) {
            const auto slot = std::size_t(start_slot[i]);
            closed[i] = !long_loop[slot] && interior_minus_border[slot] > 0;
        }
        return closed;
    }

    // Per start v: the edges of the border loop through v when it closes within `limit` edges;
    // limit + 1 for a longer loop or one through a vertex with two border edges out; 0 when v
    // has no border edge out. Each walk gives its outcome to every vertex it passes: a vertex
    // with one border edge in has one out (its fans' ends pair up), so the walks from them
    // follow the same chain and end alike (a chain that met itself elsewhere than at its start
    // would pass a vertex with two edges in, hence two out, where every walk stops).
    std::vector<std::size_t> border_loops_at(const std::vector<std::uint32_t>& starts,
                                             std::size_t limit) const {
        constexpr std::size_t kUnknown = ~std::size_t(0);
        std::unordered_map<std::uint32_t, std::size_t> known;
        std::vector<std::size_t> edges_at(starts.size());
        std::vector<std::uint32_t> path;
        for (std::size_t i = 0; i < starts.size(); ++i) {
            const std::uint32_t v = starts[i];
            if (const auto it = known.find(v); it != known.end()) {
                edges_at[i] = it->second;
                continue;
            }
            path.assign(1, v);
            std::size_t outcome = kUnknown;
            for (std::uint32_t a = v; outcome == kUnknown;) {
                std::size_t out = 0;
                const std::optional<std::uint32_t> next = border_successor(a, &out);
                if (out == 0 && a == v)
                    outcome = 0;
                else if (!next || path.size() > limit)
                    outcome = limit + 1;
                else if (*next == v)
                    outcome = path.size();
                else
                    path.push_back(a = *next);
            }
            for (std::uint32_t w : path) known[w] = outcome;
            edges_at[i] = outcome;
        }
        return edges_at;
    }

    // Per vertex of the given mesh (one fan each): the sum of its faces' next corners minus the
    // sum of their previous ones, i.e. the last spoke minus the first of an open fan and 0 for
    // a closed one (each next corner is another face's previous). Nonzero: on the border. One
    // pass over the faces in order, instead of a walk around every vertex.
    std::vector<std::int64_t> given_fan_ends() const {
        std::vector<std::int64_t> ends(positions_.size(), 0);
        for (std::size_t f = 0; f < original_faces_; ++f) {
            const Triangle& t = triangles_[f];
            for (int k = 0; k < 3; ++k)
                ends[t[k]] += std::int64_t(t[(k + 1) % 3]) - std::int64_t(t[(k + 2) % 3]);
        }
        return ends;
    }

    // Closes a short loop; a corner's fan filled with it may only shrink it (the fill joins the
    // corner's neighbours on the loop), so what is left is tried again.
    bool close_small_hole(Hole hole, std::size_t limit) {
        for (std::size_t step = 0; step < limit; ++step) {
            if (close_hole(hole)) return true;
            if (close_around(hole.corners) == 0) return false;
            std::optional<Hole> rest;
            for (std::uint32_t c : hole.corners)
                if (!rest && !faces_of(c).empty()) rest = small_hole(c, false, limit);
            if (!rest || rest->corners.size() >= hole.corners.size()) return !rest;
            hole = *rest;
        }
        return false;
    }

    // Where an undo goes back to (the faces retired since are in retired_log_): the faces there
    // were, and the count of vertices put back.
    struct Undo {
        std::size_t faces, reinserted;
    };
    Undo begin_undo() {
        retired_log_.emplace();
        return {triangles_.size(), reinserted_};
    }

    // Every vertex the faces retired since begin_undo() left without a face goes back over a
    // face near it, or false.
    bool put_back_taken_out() {
        const std::vector<std::uint32_t> out = taken_out();
        return std::all_of(out.begin(), out.end(), [&](std::uint32_t v) { return put_back(v); });
    }

    // The vertices the faces retired since begin_undo() left without a face.
    std::vector<std::uint32_t> taken_out() const {
        std::vector<std::uint32_t> out;
        for (std::uint32_t f : *retired_log_)
            for (std::uint32_t v : triangles_[f])
                if (representative_[v] == v && faces_of(v).empty()) out.push_back(v);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }

    // The faces stand as they did at `undo`.
    void rewind(const Undo& undo) {
        ++mesh_version_;
        for (std::size_t f = undo.faces; f < triangles_.size(); ++f) alive_[f] = 0;
        for (std::size_t i = retired_log_->size(); i-- > 0;) {
            const std::uint32_t f = (*retired_log_)[i];
            if (f >= undo.faces) continue;
            alive_[f] = 1;
            if (f + 1 < partner_start_.size())
                for (std::uint32_t e = partner_start_[f]; e < partner_start_[f + 1]; ++e)
                    if (alive_[partner_[e]]) ++live_pairs_[partner_[e]];
        }
    }

    // The fills that close a hole with `corners` in fill order (a cut face's, or a short loop's):
    // a corner whose fan, open at the hole, is triangulated again across it (the notch of an
    // open hole); else a disc of fans around a corner within kClosingReach of the hole's longest
    // side from its centre (a hole is not worth points taken from further away). Returns the
    // vertices removed (0: the hole is still open).
    std::size_t close_around(const std::vector<std::uint32_t>& corners) {
        const std::size_t m = corners.size();
        for (const bool facing : {true, false})
            for (std::size_t k = 0; k < m; ++k) {
                const std::uint32_t v = corners[k], next = corners[(k + 1) % m],
                                    last = corners[(k + m - 1) % m];
                std::vector<Triangle> fan;
                for (std::uint32_t f : faces_of(v)) fan.push_back(triangles_[f]);
                if (fan.empty()) continue; // v went with another fill
                const std::optional<Hole> link = link_of(v, fan);
                // Two corners: the fill would have no triangle, v's one face would just go.
                if (link && !link->closed && link->corners.size() >= 3 &&
                    link->corners.front() == last && link->corners.back() == next &&
                    refill(v, facing))
                    return 1;
            }
        Vec3 sum(0, 0, 0);
        double longest = 0;
        for (std::size_t k = 0; k < m; ++k) {
            sum += positions_[corners[k]];
            longest = std::max(longest,
                               (positions_[corners[k]] - positions_[corners[(k + 1) % m]]).Norm());
        }
        const Reach reach{sum / double(m), kClosingReach * longest};
        for (std::uint32_t v : corners)
            if (!faces_of(v).empty())
                if (const std::size_t removed = refill_region(v, &reach)) return removed;
        return 0;
    }

    // The border loop that leaves v along a border edge, as the hole a fill closes (corners in
    // the order of the faces that would fill it), if it is short, runs along a cut face (an edge
    // whose other face in the given mesh has gone) and has no edge that was on the border of the
    // given mesh (fills make edges the given mesh did not have).
    std::optional<Hole> small_cut_hole(std::uint32_t v) const {
        return small_hole(v, true, kMaxClosedGap);
    }

    // The border loop of at most `limit` edges that leaves v, as the hole a fill closes; with
    // `cut_only`, only a loop as small_cut_hole() takes it.
    std::optional<Hole> small_hole(std::uint32_t v, bool cut_only, std::size_t limit) const {
        std::vector<std::uint32_t> loop{v};
        bool along_a_cut = false;
        for (std::size_t step = 0; step < limit; ++step) { // step k adds the (k + 1)-th edge
            const std::uint32_t a = loop.back();
            const std::optional<std::uint32_t> next = border_successor(a);
            if (!next || (cut_only && given_edge(a, *next) && !given_edge(*next, a)))
                return std::nullopt;
            along_a_cut = along_a_cut || given_edge(*next, a);
            if (*next == v) {
                if (loop.size() < 3 || (cut_only && !along_a_cut)) return std::nullopt;
                Hole hole;
                hole.closed = true;
                hole.corners.assign(loop.rbegin(), loop.rend()); // the fill runs the other way
                return hole;
            }
            if (std::find(loop.begin(), loop.end(), *next) != loop.end()) return std::nullopt;
            loop.push_back(*next);
        }
        return std::nullopt;
    }

    // The one border edge a→b leaving a (a standing face holds a→b, none b→a), if exactly one;
    // `out`, if given, gets how many leave a.
    std::optional<std::uint32_t> border_successor(std::uint32_t a,
                                                  std::size_t* out = nullptr) const {
        std::optional<std::uint32_t> found;
        std::size_t count = 0;
        any_face(a, [&](const Triangle& t) {
            const auto k = std::size_t(std::find(t.begin(), t.end(), a) - t.begin());
            const std::uint32_t b = t[(k + 1) % 3];
            if (!has_directed_edge(b, a)) {
                ++count;
                found = b;
            }
            return false;
        });
        if (out) *out = count;
        if (count > 1) return std::nullopt;
        return found;
    }

    // A face of the given mesh held a→b.
    bool given_edge(std::uint32_t a, std::uint32_t b) const {
        for (std::uint32_t e = at_.begin(a); e < at_.end(a); ++e)
            if (triangles_[at_.corner[e] / 3][(at_.corner[e] % 3 + 1) % 3] == b) return true;
        return false;
    }

    // Fills a closed hole with the first triangulation that fits (facing the normals first).
    bool close_hole(const Hole& hole) {
        blocker_ = kNoFace;
        for (const bool facing : {true, false})
            if (const std::optional<std::vector<Triangle>> fill =
                    first_fitting_fill(hole, facing)) {
                for (const Triangle& t : *fill) add(t);
                return true;
            }
        return false;
    }

    // Edges of face f in no other standing face.
    int border_edges(std::uint32_t f) {
        alive_[f] = 0;
        int count = 0;
        for (int k = 0; k < 3; ++k)
            count += !has_edge(triangles_[f][k], triangles_[f][(k + 1) % 3]);
        alive_[f] = 1;
        return count;
    }

    // Where no single fan's hole can be filled: a disc of fans around v, grown one vertex at a
    // time towards the face that stood in the way of the last fill, until its hole can be
    // filled (rather than left open). Returns the vertices removed (0: none, nothing changed).
    // With a `reach`, the disc grows only by corners within it.
    std::size_t refill_region(std::uint32_t v, const Reach* reach = nullptr) {
        std::vector<std::uint32_t> region{v};
        for (std::size_t size = 1; size <= kMaxRegionVertices; ++size) {
            std::vector<std::uint32_t> faces;
            for (std::uint32_t r : region)
                for (std::uint32_t f : faces_of(r)) faces.push_back(f);
            std::sort(faces.begin(), faces.end());
            faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
            for (std::uint32_t f : faces) alive_[f] = 0; // while the fills are tested
            set_faces_out(faces);
            const std::optional<DiscBorder> border = disc_border(faces);
            std::optional<std::vector<Triangle>> fill;
            blocker_ = kNoFace;
            for (const bool facing : {true, false})
                if (border && !fill) fill = first_fitting_fill(border->hole, facing);
            // Closing a hole (a reach is given), a fill without a triangle closes nothing.
            if (reach && fill && fill->empty()) fill.reset();
            for (std::uint32_t f : faces) alive_[f] = 1;
            set_faces_out({});
            if (!border) return 0;
            if (fill) {
                replace(faces, *fill, border->inner, border->hole.corners);
                return border->inner.size();
            }
            const std::uint32_t next = nearest_corner(border->hole.corners, region);
            if (reach && (positions_[next] - reach->centre).Norm() > reach->radius) return 0;
            region.push_back(next);
        }
        return 0;
    }

    // The hole `faces` (already marked dead) leave, when they form a disc: the border edges
    // they share with standing faces, wound as the faces are, as one simple loop (an inner
    // disc) or one simple path whose ends the fill will join (a disc on the mesh's border,
    // whose border edges there go with it).
    std::optional<DiscBorder> disc_border(const std::vector<std::uint32_t>& faces) const {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> directed;
        for (std::uint32_t f : faces)
            for (int k = 0; k < 3; ++k)
                directed.emplace_back(triangles_[f][k], triangles_[f][(k + 1) % 3]);
        std::sort(directed.begin(), directed.end());
        std::vector<std::pair<std::uint32_t, std::uint32_t>> shared; // sorted by source
        std::vector<std::uint32_t> vertices;
        std::size_t inner_edges_twice = 0, mesh_border = 0;
        for (const auto& [a, b] : directed) {
            vertices.push_back(a);
            if (std::binary_search(directed.begin(), directed.end(), std::make_pair(b, a)))
                ++inner_edges_twice;
            else if (has_edge(a, b))
                shared.emplace_back(a, b);
            else
                ++mesh_border;
        }
        std::sort(vertices.begin(), vertices.end());
        vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
        // A disc: V − E + F = 1.
        const std::size_t edges = shared.size() + mesh_border + inner_edges_twice / 2;
        if (shared.empty() || vertices.size() + faces.size() != edges + 1) return std::nullopt;
        DiscBorder d;
        d.hole.closed = mesh_border == 0;
        if (!chain(shared, d.hole)) return std::nullopt;
        // The vertices that go: those with no standing face (a corner of the border keeps its
        // standing faces; so does a vertex where the disc touches the rest at one point).
        for (std::uint32_t v : vertices)
            if (faces_of(v).empty()) d.inner.push_back(v);
        return d;
    }

    // Chains `edges` (sorted by source) into hole.corners: a loop if hole.closed, else a path
    // from the one source that is no target. False unless every edge is used once and no
    // corner repeats.
    static bool chain(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
                      Hole& hole) {
        const auto from = [&](std::uint32_t a) {
            const auto e = std::lower_bound(edges.begin(), edges.end(), std::make_pair(a, 0u));
            return e != edges.end() && e->first == a ? e : edges.end();
        };
        std::uint32_t corner = edges.front().first;
        if (!hole.closed) {
            std::vector<std::uint32_t> targets;
            for (const auto& e : edges) targets.push_back(e.second);
            std::sort(targets.begin(), targets.end());
            std::size_t starts = 0;
            for (const auto& e : edges)
                if (!std::binary_search(targets.begin(), targets.end(), e.first)) {
                    corner = e.first;
                    ++starts;
                }
            if (starts != 1) return false;
        }
        hole.corners.push_back(corner);
        for (std::size_t used = 0; used < edges.size(); ++used) {
            const auto e = from(corner);
            if (e == edges.end() || (e + 1 != edges.end() && (e + 1)->first == corner))
                return false;
            corner = e->second;
            hole.corners.push_back(corner);
        }
        if (hole.closed) {
            if (hole.corners.back() != hole.corners.front()) return false;
            hole.corners.pop_back();
        }
        std::vector<std::uint32_t> sorted = hole.corners;
        std::sort(sorted.begin(), sorted.end());
        return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    }

    // The corner of the hole nearest to the face that stood in the way of the last fill (or to
    // the region's first vertex), not yet in the region.
    std::uint32_t nearest_corner(const std::vector<std::uint32_t>& corners,
                                 const std::vector<std::uint32_t>& region) const {
        Vec3 target = positions_[region.front()];
        if (blocker_ != kNoFace) {
            const Triangle& b = triangles_[blocker_];
            target = (positions_[b[0]] + positions_[b[1]] + positions_[b[2]]) / 3.0;
        }
        std::uint32_t best = corners.front();
        double best_distance = std::numeric_limits<double>::infinity();
        for (std::uint32_t c : corners) {
            const double d = (positions_[c] - target).SquaredNorm();
            if (d < best_distance) {
                best_distance = d;
                best = c;
            }
        }
        return best;
    }

    // Removes v's fan and fills its hole, if a triangulation fits.
    bool refill(std::uint32_t v, bool facing) {
        const std::vector<std::uint32_t> fan = faces_of(v);
        std::vector<Triangle> fan_triangles;
        for (std::uint32_t f : fan) fan_triangles.push_back(triangles_[f]);
        const std::optional<Hole> hole = link_of(v, fan_triangles);
        if (!hole || (hole->closed && hole->corners.size() < 3)) return false;
        for (std::uint32_t f : fan) alive_[f] = 0; // while the fills are tested
        set_faces_out(fan);
        const std::optional<std::vector<Triangle>> fill = first_fitting_fill(*hole, facing);
        for (std::uint32_t f : fan) alive_[f] = 1;
        set_faces_out({});
        if (!fill) return false;
        replace(fan, *fill, {v}, hole->corners);
        return true;
    }

    // `fill` stands instead of `faces`; the `removed` vertices go back where they fit around
    // the hole's `corners`.
    void replace(const std::vector<std::uint32_t>& faces, const std::vector<Triangle>& fill,
                 const std::vector<std::uint32_t>& removed,
                 const std::vector<std::uint32_t>& corners) {
        for (std::uint32_t f : faces) retire(f);
        for (const Triangle& t : fill) add(t);
        reinserted_ += reinsert(removed, corners);
    }

    // Puts removed vertices back where they fit into a face around the hole's `corners` (the
    // fill's, or one next to it): a face split into three around the vertex, proper triangles
    // facing their normals that cross no standing face, the split with the largest smallest
    // angle. Returns how many went back.
    std::size_t reinsert(const std::vector<std::uint32_t>& removed,
                         const std::vector<std::uint32_t>& corners) {
        std::size_t back = 0;
        for (std::uint32_t r : removed) {
            if (!faces_of(r).empty()) continue; // not removed after all
            std::vector<std::uint32_t> faces;
            for (std::uint32_t w : corners)
                for (std::uint32_t f : faces_of(w)) faces.push_back(f);
            std::sort(faces.begin(), faces.end());
            faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
            std::vector<std::pair<double, std::uint32_t>> candidates; // (−angle, face)
            for (std::uint32_t f : faces) {
                double smallest = 4;
                bool proper_split = true;
                for (const Triangle& t : split_around(triangles_[f], r)) {
                    proper_split = proper_split && proper(t, true) && !repeats_a_face(t);
                    smallest = std::min(smallest, angle(t));
                }
                if (proper_split) candidates.emplace_back(-smallest, f);
            }
            std::sort(candidates.begin(), candidates.end());
            for (const auto& [negative_angle, f] : candidates) {
                const std::array<Triangle, 3> split = split_around(triangles_[f], r);
                alive_[f] = 0;
                bool fits = true;
                for (std::size_t k = 0; k < 3 && fits; ++k) {
                    fits = !intersects_standing(welded(split[k]));
                    for (std::size_t l = 0; l < k && fits; ++l)
                        fits = !geometry_.intersect(welded(split[k]), welded(split[l]));
                }
                alive_[f] = 1;
                if (!fits) continue;
                retire(f);
                for (const Triangle& t : split) add(t);
                ++back;
                break;
            }
        }
        return back;
    }

    // Removed vertices that no hole took back, once every fold is resolved: each over a
    // standing face near it, splitting that face into three or, over one of its edges, the
    // edge's two faces into four, or beyond a border vertex as two triangles closing its corner
    // (D-37). Every new triangle is proper, faces its corners' normals, turns the way the face
    // it replaces (or borders) does and crosses no standing face; of those that fit, the split
    // with the largest smallest angle.
    // D-37: vertices that never had a face (points in no triangle, given as such) go the same
    // way, within a grid cell of where they are.
    void put_back_the_rest() {
        for (std::uint32_t v = 0; v + 1 < at_.start.size(); ++v) {
            if (representative_[v] != v) continue;
            if (lost_all_faces(v)) {
                reinserted_ += put_back(v);
            } else if (never_had_a_face(v)) {
                placed_ += put_back(v);
            }
        }
    }

    bool never_had_a_face(std::uint32_t v) const {
        return at_.begin(v) == at_.end(v) && !has_standing_face(v);
    }

    // v had faces and has none now (the original ones are looked at first: no map lookup for
    // the many vertices that kept one).
    bool lost_all_faces(std::uint32_t v) const {
        if (at_.begin(v) == at_.end(v)) return false;
        for (std::uint32_t e = at_.begin(v); e < at_.end(v); ++e)
            if (alive_[at_.corner[e] / 3]) return false;
        return !has_standing_face(v);
    }

    struct Split {
        std::vector<std::uint32_t> faces;  ///< replaced (none for a triangle beyond the border)
        std::vector<Triangle> triangles;   ///< instead
        std::vector<std::uint32_t> source; ///< per triangle: the face it lies over (or beside)
        bool lengthens_border = false;     ///< D-41: v joins a border edge
    };

    // v's old fan's mean edge: how far from v a face may be to take it back (a vertex that had
    // no fan: a cell of the grid, about two mean face sizes).
    double fan_reach(std::uint32_t v) const {
        if (at_.begin(v) == at_.end(v)) return grid_.cell_size();
        double sum = 0;
        std::size_t edges = 0;
        for (std::uint32_t e = at_.begin(v); e < at_.end(v); ++e)
            for (std::uint32_t w : triangles_[at_.corner[e] / 3])
                if (w != v) {
                    sum += (positions_[w] - positions_[v]).Norm();
                    ++edges;
                }
        return edges ? sum / double(edges) : 0;
    }

    // The standing face across f's edge k (from corner k to k + 1), or none.
    std::optional<std::uint32_t> across(std::uint32_t f, int k) const {
        const std::uint32_t a = triangles_[f][k], b = triangles_[f][(k + 1) % 3];
        std::optional<std::uint32_t> found;
        any_face_index(b, [&](std::uint32_t g) {
            const Triangle& t = triangles_[g];
            for (int j = 0; j < 3; ++j)
                if (g != f && t[j] == b && t[(j + 1) % 3] == a) found = g;
            return found.has_value();
        });
        return found;
    }

    std::vector<Split> splits_near(std::uint32_t v) {
        const double r = fan_reach(v);
        gather_standing(Box{positions_[v] - Vec3(r, r, r), positions_[v] + Vec3(r, r, r)});
        std::vector<std::uint32_t> faces;
        for (const auto& [f, b] : near_.found()) faces.push_back(f);
        std::sort(faces.begin(), faces.end());
        std::vector<Split> splits;
        for (std::uint32_t f : faces) {
            // Every split below goes over f: none is taken where f is not (put_back's test).
            if (!goes_over(v, f)) continue;
            const Triangle t = triangles_[f];
            const std::array<Triangle, 3> three = split_around(t, v);
            splits.push_back({{f}, {three.begin(), three.end()}, {f, f, f}});
            for (int k = 0; k < 3; ++k) {
                const std::optional<std::uint32_t> g = across(f, k);
                const std::uint32_t a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
                if (!g) {
                    // D-41: next to the border edge a → b (beyond it, on it, or over f near it),
                    // one triangle across the edge (not a sliver) or f split in two at v; the
                    // border then runs a → v → b.
                    const Triangle ear{b, a, v};
                    if (angle(ear) >= kMinBorderPutBackAngle)
                        splits.push_back({{}, {ear}, {f}, true});
                    splits.push_back({{f}, {{a, v, c}, {v, b, c}}, {f, f}, true});
                    add_corner_fill(f, k, v, splits);
                    continue;
                }
                if (*g < f) continue; // each edge once
                std::uint32_t d = a;
                for (std::uint32_t w : triangles_[*g])
                    if (w != a && w != b) d = w;
                splits.push_back(
                    {{f, *g}, {{a, v, c}, {v, b, c}, {b, v, d}, {v, a, d}}, {f, f, *g, *g}});
            }
        }
        return splits;
    }

    // v beyond the border at b, between the border edges a → b (of face f) and b → c: the
    // triangles (b, a, v) and (c, b, v) close b's corner, and the border runs a → v → c, as long
    // as before (a point left out is worth less than no sliver along the border). The edge
    // b → c is found by walking b's fan from f, so that it is f's own fan's other side (b may
    // still be pinched between D-32's cuts).
    void add_corner_fill(std::uint32_t f, int k, std::uint32_t v,
                         std::vector<Split>& splits) const {
        const std::uint32_t a = triangles_[f][k], b = triangles_[f][(k + 1) % 3];
        std::uint32_t g = f;
        int j = (k + 1) % 3; // g's edge b → next
        for (std::size_t steps = 0;; ++steps) {
            const std::optional<std::uint32_t> next = across(g, j);
            if (!next) break;
            if (*next == f || steps > kMaxFanWalk) return; // a closed fan: no corner here
            g = *next;
            j = int(std::find(triangles_[g].begin(), triangles_[g].end(), b) -
                    triangles_[g].begin());
        }
        const std::uint32_t c = triangles_[g][(j + 1) % 3];
        const Triangle first{b, a, v}, second{c, b, v};
        if (c != a && std::min(angle(first), angle(second)) >= kMinBorderPutBackAngle)
            splits.push_back({{}, {first, second}, {f, g}});
    }

    // v may go over face f: f faces v's normal and v is not a spike over it.
    bool goes_over(std::uint32_t v, std::uint32_t f) const {
        return low_over(v, f) && normal_of(triangles_[f]).dot(normals_[v]) > 0;
    }

    // v is at most half face f's longest side off its plane (not a spike).
    bool low_over(std::uint32_t v, std::uint32_t f) const {
        const Triangle& t = triangles_[f];
        const Vec3 n = normal_of(t);
        double longest = 0;
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, (positions_[t[k]] - positions_[t[(k + 1) % 3]]).Norm());
        return std::abs((positions_[v] - positions_[t[0]]).dot(n)) <=
               kMaxPutBackHeight * longest * n.Norm();
    }

    // D-41: every face v goes over must face v's own normal, not only the sum of the new
    // triangles' corners' normals: two sheets closer than a spacing with opposed normals would
    // otherwise trade points (a point of one went into a face of the other).
    bool put_back(std::uint32_t v) {
        std::vector<Split> splits = splits_near(v);
        // (lengthens the border, −smallest angle, split): a longer border only where nothing else
        // fits
        std::vector<std::tuple<bool, double, std::size_t>> candidates;
        Box reach{positions_[v], positions_[v]}; // of every candidate's triangles
        for (std::size_t i = 0; i < splits.size(); ++i) {
            const Split& split = splits[i];
            double smallest = 4;
            bool proper_split = std::all_of(split.source.begin(), split.source.end(),
                                            [&](std::uint32_t f) { return goes_over(v, f); });
            for (std::size_t k = 0; k < split.triangles.size() && proper_split; ++k) {
                const Triangle& t = split.triangles[k];
                proper_split = normal_of(t).dot(normal_of(triangles_[split.source[k]])) > 0 &&
                               proper(t, true) && !repeats_a_face(t);
                smallest = std::min(smallest, angle(t));
            }
            if (!proper_split) continue;
            candidates.emplace_back(split.lengthens_border, -smallest, i);
            for (const Triangle& t : split.triangles)
                for (std::uint32_t w : t) reach.add(positions_[w]);
        }
        if (candidates.empty()) return false;
        std::sort(candidates.begin(), candidates.end());
        gather_standing(reach); // one search for all candidates
        for (const auto& [lengthens, negative_angle, i] : candidates) {
            const Split& split = splits[i];
            for (std::uint32_t f : split.faces) alive_[f] = 0;
            bool fits = true;
            for (std::size_t k = 0; k < split.triangles.size() && fits; ++k) {
                fits = !intersects_gathered_standing(welded(split.triangles[k]));
                for (std::size_t l = 0; l < k && fits; ++l)
                    fits = !geometry_.intersect(welded(split.triangles[k]),
                                                welded(split.triangles[l]));
            }
            for (std::uint32_t f : split.faces) alive_[f] = 1;
            if (!fits) continue;
            for (std::uint32_t f : split.faces) retire(f);
            for (const Triangle& t : split.triangles) add(t);
            return true;
        }
        return false;
    }

    // intersects_gathered() among the gathered faces that still stand.
    bool intersects_gathered_standing(const Triangle& t) const {
        const Box box = geometry_.box(t);
        const TriangleAgainstFaces against(geometry_, t);
        for (const auto& [f, b] : near_.found())
            if (alive_[f] && box.overlaps(b) && against.intersects(geometry_.triangle(f)))
                return true;
        return false;
    }

    Vec3 normal_of(const Triangle& t) const {
        return (positions_[t[1]] - positions_[t[0]]) ^ (positions_[t[2]] - positions_[t[0]]);
    }

    static std::array<Triangle, 3> split_around(const Triangle& t, std::uint32_t r) {
        return {{{t[0], t[1], r}, {t[1], t[2], r}, {t[2], t[0], r}}};
    }

    std::optional<std::vector<Triangle>> first_fitting_fill(const Hole& hole, bool facing) {
        const std::size_t m = hole.corners.size();
        if (m == 2) return std::vector<Triangle>(); // one face at a border vertex: it just goes
        // An open hole's last side is new, or a border edge whose face lies on its other side
        // (the fill then closes the notch).
        const std::uint32_t first = hole.corners.front(), last = hole.corners.back();
        if (!hole.closed && has_edge(last, first) &&
            (!has_directed_edge(first, last) || has_directed_edge(last, first)))
            return std::nullopt;
        if (m <= kMaxOptimisedHole) {
            // The best by angle alone first (cheap), then the best among triangles that cross
            // no standing face.
            for (const bool avoid_crossings : {false, true}) {
                std::vector<Triangle> best = best_fill(hole, facing, avoid_crossings);
                if (!best.empty() && fits(hole, best, facing)) return best;
            }
            return std::nullopt;
        }
        for (std::size_t apex = 0; apex < m; ++apex) {
            std::vector<Triangle> fan;
            for (std::size_t i = 1; i + 1 < m; ++i)
                fan.push_back({hole.corners[apex], hole.corners[(apex + i) % m],
                               hole.corners[(apex + i + 1) % m]});
            if (fits(hole, fan, facing)) return fan;
        }
        return std::nullopt;
    }

    // The triangulation of the hole with the largest smallest angle (dynamic programming over
    // its corners in order, which keeps the fan's orientation), whose diagonals are not edges
    // yet, of proper triangles that (if asked) cross no standing face; empty when there is none.
    std::vector<Triangle> best_fill(const Hole& hole, bool facing, bool avoid_crossings) {
        const std::vector<std::uint32_t>& c = hole.corners;
        const std::size_t m = c.size();
        const auto diagonal_free = [&](std::size_t i, std::size_t j) {
            return j == i + 1 || (i == 0 && j == m - 1) || !has_edge(c[i], c[j]);
        };
        if (avoid_crossings) gather_standing(corners_box(hole.corners));
        std::vector<double> best(m * m, -1);
        std::vector<std::size_t> apex(m * m, 0);
        for (std::size_t i = 0; i + 1 < m; ++i) best[i * m + i + 1] = 4; // above any angle
        for (std::size_t span = 2; span < m; ++span)
            for (std::size_t i = 0; i + span < m; ++i) {
                const std::size_t j = i + span;
                if (!diagonal_free(i, j)) continue;
                for (std::size_t k = i + 1; k < j; ++k) {
                    const Triangle t{c[i], c[k], c[j]};
                    const double sub = std::min(best[i * m + k], best[k * m + j]);
                    if (sub <= best[i * m + j] || sub <= 0) continue; // cannot do better
                    // The angle first: the tests, the intersection one above all, only for a
                    // triangle that would improve the fill.
                    const double q = std::min(sub, angle(t));
                    if (q <= best[i * m + j]) continue;
                    if (proper(t, facing) && !repeats_a_face(t) &&
                        (!avoid_crossings || !crosses_gathered(welded(t)))) {
                        best[i * m + j] = q;
                        apex[i * m + j] = k;
                    }
                }
            }
        std::vector<Triangle> fill;
        if (best[m - 1] <= 0) return fill;
        std::vector<std::pair<std::size_t, std::size_t>> todo{{0, m - 1}};
        while (!todo.empty()) {
            const auto [i, j] = todo.back();
            todo.pop_back();
            if (j < i + 2) continue;
            const std::size_t k = apex[i * m + j];
            fill.push_back({c[i], c[k], c[j]});
            todo.emplace_back(i, k);
            todo.emplace_back(k, j);
        }
        return fill;
    }

    double angle(const Triangle& t) const {
        return smallest_angle(positions_[t[0]], positions_[t[1]], positions_[t[2]]);
    }

    // Not degenerate for the pair test and, if asked, facing the way its corners' normals do.
    bool proper(const Triangle& t, bool facing) const {
        if (geometry_.degenerate(welded(t))) return false;
        if (!facing) return true;
        const Vec3& a = positions_[t[0]];
        const Vec3 n = (positions_[t[1]] - a) ^ (positions_[t[2]] - a);
        return n.dot(normals_[t[0]] + normals_[t[1]] + normals_[t[2]]) > 0;
    }

    // A fill fits: proper triangles, no diagonal that is an edge already, no intersection
    // among its triangles or with any standing face.
    bool fits(const Hole& hole, const std::vector<Triangle>& fill, bool facing) {
        const std::size_t m = hole.corners.size();
        const auto side = [&](std::uint32_t a, std::uint32_t b) {
            const auto i = std::size_t(std::find(hole.corners.begin(), hole.corners.end(), a) -
                                       hole.corners.begin());
            const auto j = std::size_t(std::find(hole.corners.begin(), hole.corners.end(), b) -
                                       hole.corners.begin());
            const std::size_t d = i > j ? i - j : j - i;
            return d == 1 || d == m - 1;
        };
        for (std::size_t i = 0; i < fill.size(); ++i) {
            const Triangle& t = fill[i];
            if (!proper(t, facing) || repeats_a_face(t)) return false;
            for (int k = 0; k < 3; ++k)
                if (!side(t[k], t[(k + 1) % 3]) && has_edge(t[k], t[(k + 1) % 3])) return false;
            // Two corners of a hole may be copies of one point: no two new faces on the same
            // positions either.
            for (std::size_t j = 0; j < i; ++j)
                if (same_positions(t, fill[j]) || geometry_.intersect(welded(t), welded(fill[j])))
                    return false;
            if (intersects_standing(welded(t))) return false; // blocker_ is set
        }
        return true;
    }

    // Whether t crosses a standing face (the first one met is the blocker).
    bool intersects_standing(const Triangle& t) {
        gather_standing(geometry_.box(t));
        return intersects_gathered(t);
    }

    // The standing faces whose boxes meet `box`, each once with its box. A fill's triangles lie
    // in the box of the hole's corners: one search there serves all its tests.
    void gather_standing(const Box& box) {
        gathered_box_ = box;
        crossing_answers_ = nullptr;
        near_.gather(grid_, geometry_, box, [&](std::uint32_t f) { return alive_[f] != 0; });
    }

    // The faces taken out while fills are tested (sorted): with the mesh's version, what
    // crosses_gathered()'s answers hold for.
    void set_faces_out(std::vector<std::uint32_t> faces) {
        std::sort(faces.begin(), faces.end());
        faces_out_ = std::move(faces);
        crossing_answers_ = nullptr;
    }

    // intersects_gathered() for the triangulations of a hole (best_fill), remembered while the
    // mesh and the faces taken out stay the same: the fills facing the normals and then the
    // others, and the corners tried one after the other, test many of the same triangles
    // against the same faces. The blocker is remembered with the answer, so that it is the face
    // the test would find again (the same gathered faces in the same order).
    bool crosses_gathered(const Triangle& t) {
        if (crossing_memo_version_ != mesh_version_) {
            crossing_memo_.clear();
            crossing_memo_version_ = mesh_version_;
            crossing_answers_ = nullptr;
        }
        if (!crossing_answers_) { // the faces out or the box changed: look up their answers once
            const Box& b = gathered_box_;
            crossing_answers_ = &crossing_memo_[{
                faces_out_, {b.lo[0], b.lo[1], b.lo[2], b.hi[0], b.hi[1], b.hi[2]}}];
        }
        const auto [it, inserted] = crossing_answers_->try_emplace(t, kNoFace);
        if (!inserted) {
            if (it->second != kNoFace) blocker_ = it->second;
            return it->second != kNoFace;
        }
        if (!intersects_gathered(t)) return false;
        it->second = blocker_;
        return true;
    }

    // intersects_standing() among the gathered faces (t within the box they were gathered for).
    bool intersects_gathered(const Triangle& t) {
        const Box box = geometry_.box(t);
        const TriangleAgainstFaces against(geometry_, t);
        for (const auto& [f, b] : near_.found())
            if (box.overlaps(b) && against.intersects(geometry_.triangle(f))) {
                blocker_ = f;
                return true;
            }
        return false;
    }

    Box corners_box(const std::vector<std::uint32_t>& corners) const {
        Box box{positions_[corners.front()], positions_[corners.front()]};
        for (std::uint32_t c : corners) box.add(positions_[c]);
        return box;
    }

    Triangle welded(const Triangle& t) const {
        return {representative_[t[0]], representative_[t[1]], representative_[t[2]]};
    }

    std::vector<std::uint32_t> faces_of(std::uint32_t v) const {
        std::vector<std::uint32_t> faces;
        any_face_index(v, [&](std::uint32_t f) {
            faces.push_back(f);
            return false;
        });
        return faces;
    }

    // Whether `test` holds for a standing face of v (faces_of without the list: the edge and
    // duplicate tests run inside the fills' search).
    template <class Test>
    bool any_face(std::uint32_t v, Test&& test) const {
        return any_face_index(v, [&](std::uint32_t f) { return test(triangles_[f]); });
    }

    // any_face() with the face's number: the given faces first, then those added.
    template <class Test>
    bool any_face_index(std::uint32_t v, Test&& test) const {
        for (std::uint32_t e = at_.begin(v); e < at_.end(v); ++e)
            if (alive_[at_.corner[e] / 3] && test(at_.corner[e] / 3)) return true;
        if (!touched_[v]) return false; // no face was ever added at v
        const auto it = added_at_.find(v);
        if (it == added_at_.end()) return false;
        return std::any_of(it->second.begin(), it->second.end(),
                           [&](std::uint32_t f) { return alive_[f] && test(f); });
    }

    bool has_standing_face(std::uint32_t v) const {
        return any_face(v, [](const Triangle&) { return true; });
    }

    // Whether a and b are the same triangle of positions.
    bool same_positions(const Triangle& a, const Triangle& b) const {
        return sorted_positions(a) == sorted_positions(b);
    }

    // t's corners welded, in increasing order.
    Triangle sorted_positions(const Triangle& t) const {
        std::uint32_t a = representative_[t[0]], b = representative_[t[1]],
                      c = representative_[t[2]];
        if (a > b) std::swap(a, b);
        if (b > c) std::swap(b, c);
        if (a > b) std::swap(a, b);
        return {a, b, c};
    }

    // A standing face has t's three corners (the fill would make a duplicate). Positions
    // count, as in `hrsr check`: the faces around every copy of t's first corner.
    bool repeats_a_face(const Triangle& t) const {
        const Triangle corners = sorted_positions(t);
        const auto repeats = [&](std::uint32_t corner) {
            return any_face(
                corner, [&](const Triangle& other) { return sorted_positions(other) == corners; });
        };
        const auto copies = copies_.find(representative_[t[0]]);
        if (copies == copies_.end()) return repeats(t[0]);
        return std::any_of(copies->second.begin(), copies->second.end(), repeats);
    }

    // A standing face holds a followed by b.
    bool has_directed_edge(std::uint32_t a, std::uint32_t b) const {
        return any_face(a, [&](const Triangle& t) {
            for (int k = 0; k < 3; ++k)
                if (t[k] == a && t[(k + 1) % 3] == b) return true;
            return false;
        });
    }

    bool has_edge(std::uint32_t a, std::uint32_t b) const {
        return any_face(
            a, [&](const Triangle& t) { return std::find(t.begin(), t.end(), b) != t.end(); });
    }

    // A face leaves the mesh: the pairs it was in are gone.
    void retire(std::uint32_t f) {
        ++mesh_version_;
        alive_[f] = 0;
        for (std::uint32_t v : triangles_[f]) touched_[v] = 1;
        if (retired_log_) retired_log_->push_back(f);
        if (f + 1 >= partner_start_.size()) return; // a new face is in no pair
        for (std::uint32_t e = partner_start_[f]; e < partner_start_[f + 1]; ++e)
            if (alive_[partner_[e]]) --live_pairs_[partner_[e]];
    }

    void add(const Triangle& t) {
        const auto f = std::uint32_t(triangles_.size());
        ++mesh_version_;
        triangles_.push_back(t);
        geometry_.add(welded(t));
        alive_.push_back(1);
        live_pairs_.push_back(0);
        for (std::uint32_t v : t) {
            added_at_[v].push_back(f);
            touched_[v] = 1;
        }
        grid_.file_again(geometry_.box(welded(t)), f);
    }

    const std::size_t pinhole_edges_; ///< D-45's loops on pieces closed but for them
    const std::vector<Vec3>& positions_;
    const Execution exec_; ///< for the passes over the whole mesh
    const std::vector<Vec3>& normals_;
    std::vector<Triangle> triangles_;  ///< by vertex; faces added at the end
    const std::size_t original_faces_; ///< the faces given; later ones were added
    const std::vector<std::uint32_t>& representative_;
    /// Vertices at one position, by their representative (only where there are several).
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> copies_;
    TriangleGeometry& geometry_; ///< the same faces, welded; new ones appended
    TriangleGrid& grid_;         ///< new faces are filed again
    const VertexCorners at_;     ///< the given faces around each vertex
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> added_at_;
    std::vector<std::uint8_t> alive_;
    std::vector<std::uint8_t> touched_;      ///< per vertex: a corner of a face cut or added
    std::vector<std::uint8_t> given_border_; ///< per vertex: on the given mesh's border (lazy)
    const std::vector<TrianglePair>& pairs_;
    std::vector<std::uint32_t> partner_start_, partner_, live_pairs_;
    FacesNearBox near_;                    ///< gather_standing()'s faces
    std::uint32_t blocker_ = kNoFace;      ///< the standing face that the last fill crossed
    std::size_t mesh_version_ = 0;         ///< changes whenever a face goes or comes
    std::vector<std::uint32_t> faces_out_; ///< taken out while fills are tested (sorted)
    /// crosses_gathered()'s answers (the face crossed, or kNoFace) for the mesh's version,
    /// by the faces out and the box the faces were gathered in (their order decides the blocker)
    std::map<std::pair<std::vector<std::uint32_t>, std::array<double, 6>>,
             std::map<Triangle, std::uint32_t>>
        crossing_memo_;
    std::size_t crossing_memo_version_ = ~std::size_t(0);
    /// crossing_memo_'s entry for the current faces out and gathered box (null: look it up)
    std::map<Triangle, std::uint32_t>* crossing_answers_ = nullptr;
    Box gathered_box_{};                     ///< of the last gather_standing()
    std::size_t reinserted_ = 0;             ///< removed vertices put back (reinsert)
    std::size_t placed_ = 0;                 ///< vertices without a face given, placed (D-37)
    std::vector<Triangle> inner_cuts_;       ///< faces cut with no edge on the border
    std::vector<std::uint32_t> cut_corners_; ///< the corners of every face cut
    std::optional<std::vector<std::uint32_t>> retired_log_; ///< while a D-38 closing may be undone
};

} // namespace

FoldRemoval remove_folds(FoldSearch& search, const std::vector<Vec3>& normals,
                         std::vector<Triangle>& triangles, std::size_t pinhole_edges) {
    Remover remover(search, normals, triangles, pinhole_edges);
    FoldRemovalStats stats;
    remover.run(stats);
    return remover.result(triangles, stats);
}

FoldRemoval remove_folds(const std::vector<Vec3>& positions, const std::vector<Vec3>& normals,
                         std::vector<Triangle>& triangles, const Execution& exec,
                         std::size_t pinhole_edges) {
    FoldRemoval out;
    if (triangles.size() < 2) {
        for (std::uint32_t v = 0; v < positions.size(); ++v) out.vertex_source.push_back(v);
        return out;
    }
    FoldSearch search(positions, triangles, exec);
    return remove_folds(search, normals, triangles, pinhole_edges);
}

} // namespace hrsr
