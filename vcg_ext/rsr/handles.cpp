#include "rsr/handles.h"

#include "geometry.h"
#include "preprocess/components.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace hrsr::rsr {

namespace {

struct HandleCandidate {
    std::uint32_t v, w;
};

// D-22: v lies on a hole, i.e. one of its wedges belongs to a face that is not a recorded
// triangle. GEL asks for a reflex corner (two consecutive neighbours more than π apart), which
// misses both sides of a straight or convex crack in regularly sampled data (gaps of exactly π).
bool is_open(const RotationSystem& rs, const Faces& faces, std::uint32_t v) {
    if (rs.degree(v) < 2) return false;
    for (const Dart& d : rs.darts(v))
        if (!faces.is_recorded_triangle(d.face)) return true;
    return false;
}

using FacePair = std::pair<std::uint32_t, std::uint32_t>;

// D-31: on HRsR's coarse cloud a handle edge must not be overlong in D-30's sense (longer than
// twice RsR's candidate reach among the input points at either end): such an edge spans a gap
// between parts that the input points never join (the feline's tail and body at p = 0.125).
bool overlong(const RotationSystem& rs, const std::vector<double>& reach, std::uint32_t v,
              std::uint32_t w) {
    const double l = (rs.position(v) - rs.position(w)).Norm();
    return l > constants::kOverlongFactor * std::min(reach[v], reach[w]);
}

// D-27: a handle edge is an edge of the surface, so it obeys the normal filter θ of every other
// edge (§3.3). Without it, the sides of a thin part (normals opposed) were grouped as handles.
std::map<FacePair, std::vector<HandleCandidate>>
collect_candidates(const Embedding& e, const KnnIndex& index, const PreprocessOptions& options,
                   const std::vector<double>* reach, HandleStats& stats) {
    const RotationSystem& rs = e.rotation;
    const Faces& faces = e.faces;
    const double min_cos = normal_filter_cosine(options);
    std::map<FacePair, std::vector<HandleCandidate>> groups;
    std::vector<Neighbour> found;
    for (std::uint32_t v = 0; v < rs.vertex_count(); ++v) {
        if (!is_open(rs, faces, v)) continue;
        ++stats.open_vertices;
        index.neighbours_of(v, options.k, found);
        for (const Neighbour& nb : found) {
            const std::uint32_t w = nb.index;
            if (rs.degree(w) == 0 || rs.adjacent(v, w) || rs.normal(v).dot(rs.normal(w)) < min_cos)
                continue;
            if (reach && !reach->empty() && overlong(rs, *reach, v, w)) continue;
            const std::uint32_t fa = faces.face_of_wedge(v, w), fb = faces.face_of_wedge(w, v);
            // A handle joins two holes; entering a recorded triangle would unmake it.
            if (fa == fb || faces.is_recorded_triangle(fa) || faces.is_recorded_triangle(fb) ||
                !e.geometry.passes(v, w))
                continue;
            groups[{std::min(fa, fb), std::max(fa, fb)}].push_back({v, w});
            ++stats.candidates;
            break; // at most one candidate per open vertex
        }
    }
    return groups;
}

} // namespace

std::size_t handle_hop_limit(double loop_spacings, std::size_t points,
                             std::size_t represented_points) {
    const double density = represented_points > points && points > 0
                               ? double(points) / double(represented_points)
                               : 1.0;
    // D-29: on a small surface a loop of n spacings may be longer than the surface allows (the
    // 315-point "eight": tubes 12 spacings around), so the loop asked for is capped at a fraction
    // of the surface's size in spacings, sqrt(represented points).
    const double surface_loop = constants::kSmallSurfaceLoopFraction *
                                std::sqrt(double(std::max(points, represented_points)));
    const double hops = std::round(std::min(loop_spacings, surface_loop) * std::sqrt(density));
    return std::max(constants::kMinHandleHops, std::size_t(hops));
}

std::size_t BoundedBfs::distance(const RotationSystem& rs, std::uint32_t a, std::uint32_t b,
                                 std::size_t limit) {
    if (a == b) return 0;
    if (++epoch_ == 0) {
        std::fill(stamp_.begin(), stamp_.end(), 0);
        epoch_ = 1;
    }
    frontier_.assign(1, a);
    stamp_[a] = epoch_;
    for (std::size_t depth = 1; depth <= limit && !frontier_.empty(); ++depth) {
        next_.clear();
        for (std::uint32_t x : frontier_)
            for (const Dart& d : rs.darts(x)) {
                if (d.to == b) return depth;
                if (stamp_[d.to] == epoch_) continue;
                stamp_[d.to] = epoch_;
                next_.push_back(d.to);
            }
        std::swap(frontier_, next_);
    }
    return limit + 1;
}

HandleStats insert_handles(Embedding& e, const KnnIndex& index, const RsrOptions& options,
                           const HandleLimits& limits, std::vector<std::uint32_t>& roots) {
    RotationSystem& rs = e.rotation;
    Faces& faces = e.faces;
    HandleStats stats;
    const std::size_t hop_limit = limits.hop_limit;
    stats.hop_limit = hop_limit;
    BoundedBfs bfs(rs.vertex_count());
    const auto by_pair = collect_candidates(e, index, options.preprocess, limits.reach, stats);
    // Largest groups first; ties by the face pair (D-10).
    std::vector<std::pair<FacePair, const std::vector<HandleCandidate>*>> groups;
    for (const auto& [pair, list] : by_pair) groups.emplace_back(pair, &list);
    std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) {
        return a.second->size() > b.second->size();
    });

    for (const auto& [pair, list] : groups) {
        if (list->size() <= constants::kMinHandleGroupSize) break;
        if (options.handles >= 0 && stats.handles >= std::size_t(options.handles)) {
            stats.limited = true;
            break;
        }
        ++stats.groups;
        bool merged = false;
        for (const HandleCandidate& c : *list) {
            if (rs.adjacent(c.v, c.w)) continue;
            // Face labels are current (D-11): the first edge of a group merges its two faces,
            // later ones split the merged face. Recorded triangles are never entered.
            const std::uint32_t fa = faces.face_of_wedge(c.v, c.w),
                                fb = faces.face_of_wedge(c.w, c.v);
            if (faces.is_recorded_triangle(fa) || faces.is_recorded_triangle(fb)) continue;
            if (bfs.distance(rs, c.v, c.w, hop_limit) <= hop_limit || !e.geometry.passes(c.v, c.w))
                continue;
            const bool joins = fa != fb;
            const auto [d1, d2] = rs.insert_edge(c.v, c.w);
            if (joins)
                faces.merge(d1, d2);
            else
                faces.split(d1, d2);
            merged = merged || joins;
            ++stats.edges_inserted;
            roots.push_back(c.v);
            roots.push_back(c.w);
            e.edge_inserted(Phase::Handles, c.v, c.w, 0);
        }
        if (merged) ++stats.handles;
    }
    return stats;
}

} // namespace hrsr::rsr
