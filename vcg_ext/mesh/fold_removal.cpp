#include "mesh/fold_removal.h"

#include "mesh/fold_remover.h"

#include <algorithm>
#include <limits>
#include <tuple>

namespace hrsr {

namespace folds {

Remover::Remover(FoldSearch& search, const std::vector<Vec3>& normals,
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

void Remover::run(FoldRemovalStats& stats) {
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
    put_back_the_rest(PutBack::or_turned);
    absorb_small_pieces(stats);
    close_pinholes(stats);
    close_slits(stats);
    // D-60 last: a point placed on a small piece would keep it from joining the surface (a
    // piece that took points stays; the RsR lion kept 8 pieces more).
    put_back_the_rest(PutBack::or_flat_against);
    // D-64 after every point is placed: a flip changes no vertex, piece or border; D-65 then
    // refills around a corner what no flip turned (the corner back in the fill).
    refill_faces_against_normals(turn_faces_against_normals(stats), stats);
    stats.vertices_reinserted = reinserted_;
    stats.points_placed = placed_;
    stats.points_joined_border = joined_border_;
    stats.vertices_removed -= reinserted_;
    stats.pairs_after = std::size_t(std::count_if(
        pairs_.begin(), pairs_.end(), [&](auto p) { return alive_[p.first] && alive_[p.second]; }));
}

FoldRemoval Remover::result(std::vector<Triangle>& triangles, FoldRemovalStats stats) const {
    triangles.clear();
    for (std::size_t f = 0; f < triangles_.size(); ++f)
        if (alive_[f]) triangles.push_back(triangles_[f]);
    // Only the corners of faces cut or added can be pinched: every vertex had one fan.
    std::vector<std::uint8_t> changed(positions_.size(), 0);
    for (std::size_t f = 0; f < triangles_.size(); ++f)
        if (!alive_[f] || f >= original_faces_)
            for (std::uint32_t v : triangles_[f]) changed[v] = 1;
    FoldRemoval out;
    out.vertex_source = compact_and_split_vertices(positions_.size(), triangles, &changed, exec_);
    std::vector<std::uint8_t> seen(positions_.size(), 0);
    for (std::uint32_t v : out.vertex_source) {
        stats.vertex_copies += seen[v];
        seen[v] = 1;
    }
    out.stats = stats;
    return out;
}

void Remover::index_pairs() {
    partner_start_.assign(triangles_.size() + 1, 0);
    for (const TrianglePair& p : pairs_) {
        ++partner_start_[p.first + 1];
        ++partner_start_[p.second + 1];
    }
    for (std::size_t f = 0; f < triangles_.size(); ++f) partner_start_[f + 1] += partner_start_[f];
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

void Remover::resolve(const TrianglePair& p, FoldRemovalStats& stats) {
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

std::size_t Remover::close_cut(const Triangle& cut) {
    // The hole is still there: no standing face holds the cut face's edges.
    for (int k = 0; k < 3; ++k)
        if (has_directed_edge(cut[k], cut[(k + 1) % 3])) return 0;
    return close_around({cut[0], cut[1], cut[2]});
}

void Remover::close_small_cut_holes(FoldRemovalStats& stats) {
    std::sort(cut_corners_.begin(), cut_corners_.end());
    cut_corners_.erase(std::unique(cut_corners_.begin(), cut_corners_.end()), cut_corners_.end());
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

int Remover::border_edges(std::uint32_t f) {
    alive_[f] = 0;
    int count = 0;
    for (int k = 0; k < 3; ++k) count += !has_edge(triangles_[f][k], triangles_[f][(k + 1) % 3]);
    alive_[f] = 1;
    return count;
}

void Remover::retire(std::uint32_t f) {
    ++mesh_version_;
    alive_[f] = 0;
    for (std::uint32_t v : triangles_[f]) touched_[v] = 1;
    if (retired_log_) retired_log_->push_back(f);
    if (f + 1 >= partner_start_.size()) return; // a new face is in no pair
    for (std::uint32_t e = partner_start_[f]; e < partner_start_[f + 1]; ++e)
        if (alive_[partner_[e]]) --live_pairs_[partner_[e]];
}

void Remover::add(const Triangle& t) {
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

} // namespace folds

FoldRemoval remove_folds(FoldSearch& search, const std::vector<Vec3>& normals,
                         std::vector<Triangle>& triangles, std::size_t pinhole_edges) {
    folds::Remover remover(search, normals, triangles, pinhole_edges);
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
