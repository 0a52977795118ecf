#include "rsr/face_split.h"

#include "rsr/face_split_parts.h"

#include "geometry.h"
#include "options.h"
#include "parallel.h"

#include <algorithm>
#include <stdexcept>

namespace hrsr::rsr {

void count_triangle_edge(RotationSystem& rs, std::uint32_t u, std::uint32_t w) {
    ++rs.dart(u, rs.find(u, w)).triangles;
    ++rs.dart(w, rs.find(w, u)).triangles;
}

std::uint8_t triangles_on_edge(const RotationSystem& rs, std::uint32_t u, std::uint32_t w) {
    return rs.dart(u, rs.find(u, w)).triangles;
}

// Every wedge at v is then a recorded triangle, which stays a face (the face split only splits
// faces, and a triangle cannot be split). An edge from v to a vertex not adjacent would start in
// such a triangle, whose face the other end does not reach: the ends' wedges lie in different
// faces, known without their angles (most candidates end so: 1.8M of 2.1M at 800k points).
bool surrounded_by_triangles(const RotationSystem& rs, std::uint32_t v) {
    if (rs.degree(v) < 3) return false;
    for (const Dart& d : rs.darts(v))
        if (d.triangles < 2) return false;
    return true;
}

namespace {

// What a batch's parallel look-ahead learnt about a candidate from the rotation as it was before
// the batch. The face split only inserts edges and splits faces, so two answers cannot change:
// an edge once there stays, and wedges once in different faces stay in different faces (each
// later face descends from one earlier face). Neither can a crossing found by the geometry
// check; its pass holds unless an edge was inserted since at one of the nearby points it read.
enum class Outlook : std::uint8_t { Adjacent, DifferentFaces, Open };

struct Foresight {
    std::vector<Outlook> outlook;
    std::vector<std::uint8_t> geometry_passed;
    std::vector<std::vector<std::uint32_t>> near; ///< the geometry check's nearby points
};

void work_out_ahead(const Embedding& e, const VertexSummary& summary,
                    const std::vector<CandidateEdge>& candidates, std::size_t first,
                    std::size_t count, const Execution& exec, Foresight& f) {
    parallel_for(exec, count, [&](std::size_t k) {
        const std::uint32_t v1 = candidates[first + k].i, v2 = candidates[first + k].j;
        if (summary.surrounded(v1) || summary.surrounded(v2)) {
            // No edge was inserted at a surrounded end after it was surrounded, and none before
            // for this pair (it comes once): adjacent now iff adjacent before the phase.
            f.outlook[k] = summary.adjacent_before_the_phase(v1, v2) ? Outlook::Adjacent
                                                                     : Outlook::DifferentFaces;
        } else if (e.rotation.adjacent(v1, v2)) {
            f.outlook[k] = Outlook::Adjacent;
        } else if (e.faces.face_of_wedge(v1, v2) != e.faces.face_of_wedge(v2, v1)) {
            f.outlook[k] = Outlook::DifferentFaces;
        } else {
            f.outlook[k] = Outlook::Open;
            thread_local GeometryQuery query;
            f.geometry_passed[k] = e.geometry.passes(v1, v2, query);
            f.near[k].assign(query.near.begin(), query.near.end());
        }
    });
}

// The geometry check's answer now, from its answer before the batch: a pass is tested again
// only against the edges of nearby points that gained an edge in this batch.
bool geometry_still_passes(const Embedding& e, const Foresight& f, std::size_t k, std::uint32_t v1,
                           std::uint32_t v2, const std::vector<std::uint32_t>& changed_in,
                           std::uint32_t batch) {
    if (!f.geometry_passed[k]) return false;
    for (std::uint32_t a : f.near[k])
        if (changed_in[a] == batch && e.geometry.crossed_at(v1, v2, a)) return false;
    return true;
}

} // namespace

// D-50: in the length order the candidates come from all over the cloud, and each geometry check
// and insertion reads rotations, positions and normals that miss the cache once the cloud
// outgrows it (the phase grew × 5.4–6.2 from the 800k to the 3.2M dragon sample's coarse cloud);
// tile by tile, a step's reads stay in a few tiles' data. 95 % of the 3.2M sample's insertions
// have their ends, ball and face walks in one tile (docs/BENCHMARKS.md, session 39).
std::vector<CandidateEdge> in_tile_order(std::vector<CandidateEdge> by_length,
                                         const Execution& exec) {
    const std::size_t n = by_length.size();
    parallel_for(
        exec, kFaceSplitSteps,
        [&](std::size_t step) {
            const auto first = by_length.begin() + std::ptrdiff_t(n * step / kFaceSplitSteps);
            const auto last = by_length.begin() + std::ptrdiff_t(n * (step + 1) / kFaceSplitSteps);
            std::stable_sort(first, last, [&](const CandidateEdge& a, const CandidateEdge& b) {
                return candidate_tile(a) < candidate_tile(b);
            });
        },
        1);
    return by_length;
}

namespace {

// The length order with the look-ahead: threads work out the next batch's answers from the
// rotation before it, then one thread takes the batch's candidates in order.
class LengthOrderSplit {
public:
    LengthOrderSplit(Embedding& e, VertexSummary& summary, std::size_t look_ahead)
        : e_(e), summary_(summary), batch_size_(std::max<std::size_t>(look_ahead, 1)),
          ahead_{std::vector<Outlook>(batch_size_), std::vector<std::uint8_t>(batch_size_),
                 std::vector<std::vector<std::uint32_t>>(batch_size_)},
          changed_in_(e.rotation.vertex_count(), 0) {}

    /// Takes candidates[first, last); progress runs from `done` to `done + share` of the phase.
    void run(const std::vector<CandidateEdge>& candidates, std::size_t first, std::size_t last,
             const Execution& exec, FaceSplitStats& stats, double done, double share);

private:
    Embedding& e_;
    VertexSummary& summary_;
    std::size_t batch_size_;
    Foresight ahead_;
    std::vector<std::uint32_t> changed_in_; ///< last batch (from 1) inserting at each vertex
    std::uint32_t batch_ = 0;
    std::vector<LocalTriangle> closed_;
};

void LengthOrderSplit::run(const std::vector<CandidateEdge>& candidates, std::size_t begin,
                           std::size_t end, const Execution& exec, FaceSplitStats& stats,
                           double done, double share) {
    RotationSystem& rs = e_.rotation;
    for (std::size_t first = begin; first < end; first += batch_size_) {
        if (exec.progress)
            exec.progress->update(done + share * double(first - begin) / double(end - begin));
        const std::size_t count = std::min(batch_size_, end - first);
        work_out_ahead(e_, summary_, candidates, first, count, exec, ahead_);
        ++batch_;
        for (std::size_t k = 0; k < count; ++k) {
            const Outlook outlook = ahead_.outlook[k];
            if (outlook == Outlook::Adjacent) continue; // MST edges
            if (outlook == Outlook::DifferentFaces) {
                ++stats.rejected_topology;
                continue;
            }
            const std::uint32_t v1 = candidates[first + k].i, v2 = candidates[first + k].j;
            if (rs.adjacent(v1, v2)) continue;
            if (e_.faces.face_of_wedge(v1, v2) != e_.faces.face_of_wedge(v2, v1)) {
                ++stats.rejected_topology;
                continue;
            }
            if (!geometry_still_passes(e_, ahead_, k, v1, v2, changed_in_, batch_)) {
                ++stats.rejected_geometry;
                continue;
            }
            if (register_triangles(rs, v1, v2, closed_) != Closing::Valid) {
                ++stats.rejected_triangles;
                continue;
            }
            const auto [d1, d2] = rs.insert_edge(v1, v2);
            e_.faces.split(d1, d2);
            changed_in_[v1] = changed_in_[v2] = batch_;
            summary_.edge_inserted(v1, v2);
            for (const LocalTriangle& t : closed_) {
                e_.record_triangle(t[0], t[1], t[2]);
                summary_.triangle_recorded(rs, t);
            }
            ++stats.inserted;
            e_.edge_inserted(Phase::FaceSplit, v1, v2, closed_.size());
        }
    }
}

void add(FaceSplitStats& sum, const TileSplit& tile) {
    const FaceSplitStats& part = tile.stats;
    sum.inserted += part.inserted;
    sum.rejected_topology += part.rejected_topology;
    sum.rejected_geometry += part.rejected_geometry;
    sum.rejected_triangles += part.rejected_triangles;
    sum.deferred += tile.deferred.size();
}

// One step's tiles (in in_tile_order's order: runs of one tile, those across tiles last), with
// the labels each may give: one for each of its candidates that may still be inserted. A vertex
// surrounded by triangles stays so and gains no edge, so a candidate at one never is.
std::vector<TileSplit> tiles_of_step(const std::vector<CandidateEdge>& candidates,
                                     std::size_t first, std::size_t last,
                                     const VertexSummary& summary, Faces& faces,
                                     std::size_t& across_from) {
    std::vector<TileSplit> tiles;
    std::size_t k = first, open = 0;
    while (k < last && candidate_tile(candidates[k]) != Region::kEverywhere) {
        TileSplit t;
        t.tile = candidate_tile(candidates[k]);
        t.first = k;
        for (; k < last && candidate_tile(candidates[k]) == t.tile; ++k)
            t.labels +=
                !summary.surrounded(candidates[k].i) && !summary.surrounded(candidates[k].j);
        open += t.labels;
        t.last = k;
        if (!tiles.empty() && tiles.back().tile >= t.tile)
            throw std::logic_error("face split: candidates not in in_tile_order()'s order");
        tiles.push_back(std::move(t));
    }
    across_from = k;
    for (std::size_t c = k; c < last; ++c)
        if (candidate_tile(candidates[c]) != Region::kEverywhere)
            throw std::logic_error("face split: candidates not in in_tile_order()'s order");
    std::uint32_t label = faces.reserve_labels(open);
    for (TileSplit& t : tiles) {
        t.next_label = label;
        label += std::uint32_t(t.labels);
    }
    return tiles;
}

} // namespace

// D-51: a cloud of more than one tile takes each step's tiles at once, one thread a tile, then,
// in the length order with the look-ahead, what the tiles deferred (tile by tile) and the
// candidates across tiles. Whatever the thread count the tiles do what they would one after
// another: none reads what another changes.
FaceSplitStats split_faces(Embedding& e, const std::vector<CandidateEdge>& candidates,
                           const Execution& exec, std::size_t look_ahead) {
    FaceSplitStats stats;
    VertexSummary summary(e.rotation, exec);
    LengthOrderSplit in_length_order(e, summary, look_ahead);
    const std::size_t n = candidates.size();
    if (e.rotation.vertex_count() <= (std::size_t(1) << kFaceSplitTileBits)) {
        in_length_order.run(candidates, 0, n, exec, stats, 0.0, 1.0);
        return stats;
    }
    for (std::size_t step = 0; step < kFaceSplitSteps; ++step) {
        const std::size_t first = n * step / kFaceSplitSteps;
        const std::size_t last = n * (step + 1) / kFaceSplitSteps;
        const double done = double(step) / double(kFaceSplitSteps);
        if (exec.progress) exec.progress->update(done);
        std::size_t across_from = last;
        std::vector<TileSplit> tiles =
            tiles_of_step(candidates, first, last, summary, e.faces, across_from);
        if (e.observer) {
            for (TileSplit& t : tiles) split_in_tile(e, summary, candidates, t, true);
        } else {
            parallel_for(
                without_progress(exec), tiles.size(),
                [&](std::size_t t) { split_in_tile(e, summary, candidates, tiles[t], false); }, 1);
        }
        std::vector<CandidateEdge> rest;
        for (TileSplit& t : tiles) {
            add(stats, t);
            if (!e.observer) {
                e.rotation.count_edges(t.stats.inserted);
                e.faces.count_splits(t.stats.inserted);
                e.triangles.insert(e.triangles.end(), t.triangles.begin(), t.triangles.end());
            }
            rest.insert(rest.end(), t.deferred.begin(), t.deferred.end());
        }
        rest.insert(rest.end(), candidates.begin() + std::ptrdiff_t(across_from),
                    candidates.begin() + std::ptrdiff_t(last));
        in_length_order.run(rest, 0, rest.size(), exec, stats, done, 0.5 / double(kFaceSplitSteps));
    }
    return stats;
}

} // namespace hrsr::rsr
