// Short border loops closed after D-32's pairs (fold_remover.h): the gaps of D-38, the pinholes
// of D-45 and the slits of D-48, each closing undone unless the vertices it takes out go back.
#include "mesh/fold_remover.h"

#include "graph/concurrent_sets.h"

#include <cmath>
#include <limits>

namespace hrsr::folds {

namespace {

// D-48: a border loop is a slit when its two sides are at most kMaxSlitWidth edges of the faces
// around it apart (medians: a gap narrower than about a spacing and a half holds no row of
// points), at most kMaxSlitRoundness as wide as a circle of its perimeter (the camel head's
// slits 0.21–0.41, round holes 0.9–1.4) and none of its edges is longer than kMaxSlitEdge such
// edges (docs/ALGORITHM.md D-48).
constexpr double kMaxSlitWidth = 1.5;
constexpr double kMaxSlitRoundness = 0.6;
constexpr double kMaxSlitEdge = 4.0;

} // namespace

void Remover::close_small_holes_left(FoldRemovalStats& stats) {
    std::vector<std::uint8_t> tried(positions_.size(), 0);
    for (std::uint32_t v : border_candidates())
        if (!tried[v] && !faces_of(v).empty())
            stats.small_holes_closed += close_loop_at(v, kMaxClosedGap, tried, stats);
}

void Remover::close_pinholes(FoldRemovalStats& stats) {
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
            stats.small_holes_closed += close_loop_at(v, pinhole_edges_, tried, stats,
                                                      std::size_t(loop_edges[i]) / kMaxFilledLoop);
    }
}

void Remover::close_slits(FoldRemovalStats& stats) {
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

double Remover::spacing_around(const std::vector<std::uint32_t>& loop) const {
    std::vector<double> edges;
    for (std::uint32_t c : loop)
        any_face(c, [&](const Triangle& t) {
            for (int k = 0; k < 3; ++k)
                edges.push_back((positions_[t[k]] - positions_[t[(k + 1) % 3]]).Norm());
            return false;
        });
    if (edges.empty()) return 0;
    std::nth_element(edges.begin(), edges.begin() + std::ptrdiff_t(edges.size() / 2), edges.end());
    return edges[edges.size() / 2];
}

bool Remover::is_slit(const std::vector<std::uint32_t>& loop) const {
    const std::size_t m = loop.size();
    const double spacing = spacing_around(loop);
    if (spacing == 0) return false;
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
                width[i] = std::min(width[i], (positions_[loop[i]] - positions_[loop[j]]).Norm());
        }
    std::nth_element(width.begin(), width.begin() + std::ptrdiff_t(m / 2), width.end());
    const double median_width = width[m / 2];
    return median_width <= kMaxSlitWidth * spacing &&
           median_width <= kMaxSlitRoundness * perimeter / (2 * M_PI);
}

std::vector<std::uint32_t> Remover::border_candidates() {
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

bool Remover::close_loop_at(std::uint32_t v, std::size_t limit, std::vector<std::uint8_t>& tried,
                            FoldRemovalStats& stats, std::size_t may_lose) {
    const std::optional<Hole> hole = small_hole(v, false, limit);
    if (!hole) return false;
    for (std::uint32_t c : hole->corners) tried[c] = 1;
    return close_loop(*hole, limit, stats, may_lose);
}

bool Remover::close_loop(const Hole& hole, std::size_t limit, FoldRemovalStats& stats,
                         std::size_t may_lose) {
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
        for (std::uint32_t r : taken_out()) lost += !put_back(r, PutBack::or_turned);
        closed = lost <= may_lose;
    }
    if (closed) stats.vertices_removed += lost;
    end_undo(undo, closed);
    return closed;
}

std::vector<std::uint8_t>
Remover::pieces_closed_but_for_pinholes(const std::vector<std::uint32_t>& starts,
                                        const std::vector<std::size_t>& loop_edges) const {
    const std::size_t n = positions_.size();
    ConcurrentSets pieces = standing_pieces();
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

std::vector<std::size_t> Remover::border_loops_at(const std::vector<std::uint32_t>& starts,
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

std::vector<std::int64_t> Remover::given_fan_ends() const {
    std::vector<std::int64_t> ends(positions_.size(), 0);
    for (std::size_t f = 0; f < original_faces_; ++f) {
        const Triangle& t = triangles_[f];
        for (int k = 0; k < 3; ++k)
            ends[t[k]] += std::int64_t(t[(k + 1) % 3]) - std::int64_t(t[(k + 2) % 3]);
    }
    return ends;
}

bool Remover::close_small_hole(Hole hole, std::size_t limit) {
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

Remover::Undo Remover::begin_undo() {
    retired_log_.emplace();
    return {triangles_.size(), reinserted_, joined_border_};
}

bool Remover::put_back_taken_out() {
    const std::vector<std::uint32_t> out = taken_out();
    // D-61: as D-57's put-back takes them, turning as their face where none faces the normals.
    return std::all_of(out.begin(), out.end(),
                       [&](std::uint32_t v) { return put_back(v, PutBack::or_turned); });
}

std::vector<std::uint32_t> Remover::taken_out() const {
    // One vertex per point that no copy holds in a face any more: a copy that lost its faces
    // after the point's other copies had lost theirs (D-55 leaves a pinched copy out while
    // another stands) takes the point with it otherwise.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out; // (representative, vertex)
    for (std::uint32_t f : *retired_log_)
        for (std::uint32_t v : triangles_[f])
            if (!point_has_standing_face(v)) out.emplace_back(representative_[v], v);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end(),
                          [](const auto& a, const auto& b) { return a.first == b.first; }),
              out.end());
    std::vector<std::uint32_t> vertices;
    for (const auto& [representative, v] : out) vertices.push_back(v);
    return vertices;
}

void Remover::end_undo(const Undo& undo, bool keep) {
    if (!keep) {
        rewind(undo);
        joined_border_ = undo.joined_border;
    }
    retired_log_.reset();
    // Every vertex it took out is back (or lost, counted as removed): none counts as put back.
    reinserted_ = undo.reinserted;
}

void Remover::rewind(const Undo& undo) {
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

std::optional<Hole> Remover::small_cut_hole(std::uint32_t v) const {
    return small_hole(v, true, kMaxClosedGap);
}

std::optional<Hole> Remover::small_hole(std::uint32_t v, bool cut_only, std::size_t limit) const {
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

std::optional<std::uint32_t> Remover::border_successor(std::uint32_t a, std::size_t* out) const {
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

} // namespace hrsr::folds
