#include "rsr/face_split.h"

#include "geometry.h"
#include "options.h"
#include "parallel.h"

#include <algorithm>
#include <limits>

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

bool has_common_neighbour(const RotationSystem& rs, std::uint32_t v1, std::uint32_t v2) {
    for (const Dart& d : rs.darts(v1))
        if (rs.adjacent(v2, d.to)) return true;
    return false;
}

// The neighbour after `from` (counter-clockwise) in the rotation of v.
std::uint32_t successor(const RotationSystem& rs, std::uint32_t v, std::uint32_t from) {
    return rs.dart(v, rs.next(v, rs.find(v, from))).to;
}

// A triangle (v1, apex, v2) or (v1, v2, apex) closed by the new edge is valid when it is not a
// sliver, its two old edges have room for another triangle, and it is a face of the rotation.
bool triangle_is_valid(const RotationSystem& rs, std::uint32_t a, std::uint32_t b,
                       std::uint32_t apex) {
    const double max_angle = constants::kMaxTriangleAngleDegrees * M_PI / 180.0;
    if (largest_angle(rs.position(a), rs.position(b), rs.position(apex)) > max_angle) return false;
    if (triangles_on_edge(rs, a, apex) >= 2 || triangles_on_edge(rs, b, apex) >= 2) return false;
    return true;
}

// §5.5.2 step 4, with the rotation as it is *before* inserting {v1, v2}. Returns false to reject.
bool register_triangles(const RotationSystem& rs, std::uint32_t v1, std::uint32_t v2,
                        std::vector<LocalTriangle>& found) {
    found.clear();
    if (!has_common_neighbour(rs, v1, v2)) return true;
    // r1 is just clockwise of v2 at v1; r2 just clockwise of v1 at v2.
    const std::uint32_t r1 = rs.dart(v1, rs.wedge(v1, v2)).to;
    const std::uint32_t r2 = rs.dart(v2, rs.wedge(v2, v1)).to;
    if (rs.adjacent(v2, r1) && ccw_angle(rs.angle(r1, v2), rs.angle(r1, v1)) < M_PI) {
        // Triangle (v1, r1, v2): a face iff r1 follows v1 at v2 and v1 follows v2 at r1.
        if (!triangle_is_valid(rs, v1, v2, r1) || rs.successor_as_if_inserted(v2, v1) != r1 ||
            successor(rs, r1, v2) != v1)
            return false;
        found.push_back({v1, r1, v2});
    }
    if (rs.adjacent(v1, r2) && ccw_angle(rs.angle(r2, v1), rs.angle(r2, v2)) < M_PI) {
        if (!triangle_is_valid(rs, v1, v2, r2) || rs.successor_as_if_inserted(v1, v2) != r2 ||
            successor(rs, r2, v1) != v2)
            return false;
        found.push_back({v1, v2, r2});
    }
    return !found.empty(); // common neighbours but no triangle: the edge would cut across
}

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

// What the look-ahead reads of a vertex before its rotation, in arrays small enough to stay in
// the cache: the candidates come in length order from all over the cloud, and from about 400k
// points (the 3.2M sample's coarse cloud) a rotation read is a miss to memory. Most candidates
// end at a vertex surrounded by triangles (1.8M of 2.1M at 800k points); their answer needs only
// whether the pair was an edge before the phase, since no candidate pair comes twice (the
// candidates are the pairs i < j of a graph's rows).
class VertexSummary {
public:
    VertexSummary(const RotationSystem& rs, const Execution& exec)
        : surrounded_(rs.vertex_count(), 0), first_(rs.vertex_count() + 1, 0) {
        const std::size_t n = rs.vertex_count();
        for (std::uint32_t v = 0; v < n; ++v) first_[v + 1] = first_[v] + rs.degree(v);
        initial_.resize(first_[n]);
        parallel_for(exec, n, [&](std::size_t v) {
            std::uint32_t at = first_[v];
            for (const Dart& d : rs.darts(std::uint32_t(v))) initial_[at++] = d.to;
            surrounded_[v] = surrounded_by_triangles(rs, std::uint32_t(v));
        });
    }

    bool surrounded(std::uint32_t v) const { return surrounded_[v] != 0; }
    /// Kept as the rotation changes (the look-ahead reads it between batches only). A vertex
    /// once surrounded gains no edge (no face at it splits); the update on insertion says so.
    void triangle_recorded(const RotationSystem& rs, const LocalTriangle& t) {
        for (std::uint32_t v : t) surrounded_[v] = surrounded_by_triangles(rs, v);
    }
    void edge_inserted(std::uint32_t v, std::uint32_t w) { surrounded_[v] = surrounded_[w] = 0; }
    bool adjacent_before_the_phase(std::uint32_t v, std::uint32_t w) const {
        return std::find(initial_.begin() + first_[v], initial_.begin() + first_[v + 1], w) !=
               initial_.begin() + first_[v + 1];
    }

private:
    std::vector<std::uint8_t> surrounded_;
    std::vector<std::uint32_t> first_;   ///< offsets into initial_
    std::vector<std::uint32_t> initial_; ///< each vertex's neighbours before the phase
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
    const auto tile = [](const CandidateEdge& e) {
        const std::uint32_t t = e.i >> kFaceSplitTileBits;
        return t == e.j >> kFaceSplitTileBits ? t : std::numeric_limits<std::uint32_t>::max();
    };
    parallel_for(
        exec, kFaceSplitSteps,
        [&](std::size_t step) {
            const auto first = by_length.begin() + std::ptrdiff_t(n * step / kFaceSplitSteps);
            const auto last = by_length.begin() + std::ptrdiff_t(n * (step + 1) / kFaceSplitSteps);
            std::stable_sort(first, last, [&](const CandidateEdge& a, const CandidateEdge& b) {
                return tile(a) < tile(b);
            });
        },
        1);
    return by_length;
}

// kFaceSplitLookAhead: enough for every thread to have work, few enough that the nearby points
// of a geometry check rarely gained an edge before the candidate's turn.
FaceSplitStats split_faces(Embedding& e, const std::vector<CandidateEdge>& candidates,
                           const Execution& exec, std::size_t look_ahead) {
    const std::size_t batch_size = std::max<std::size_t>(look_ahead, 1);
    RotationSystem& rs = e.rotation;
    FaceSplitStats stats;
    std::vector<LocalTriangle> closed;
    Foresight ahead{std::vector<Outlook>(batch_size), std::vector<std::uint8_t>(batch_size),
                    std::vector<std::vector<std::uint32_t>>(batch_size)};
    std::vector<std::uint32_t> changed_in(rs.vertex_count(), 0); ///< last batch (from 1) inserting
    std::uint32_t batch = 0;
    VertexSummary summary(rs, exec);
    for (std::size_t first = 0; first < candidates.size(); first += batch_size) {
        if (exec.progress) exec.progress->update(double(first) / double(candidates.size()));
        const std::size_t count = std::min(batch_size, candidates.size() - first);
        work_out_ahead(e, summary, candidates, first, count, exec, ahead);
        ++batch;
        for (std::size_t k = 0; k < count; ++k) {
            const Outlook outlook = ahead.outlook[k];
            if (outlook == Outlook::Adjacent) continue; // MST edges
            if (outlook == Outlook::DifferentFaces) {
                ++stats.rejected_topology;
                continue;
            }
            const std::uint32_t v1 = candidates[first + k].i, v2 = candidates[first + k].j;
            if (rs.adjacent(v1, v2)) continue;
            if (e.faces.face_of_wedge(v1, v2) != e.faces.face_of_wedge(v2, v1)) {
                ++stats.rejected_topology;
                continue;
            }
            if (!geometry_still_passes(e, ahead, k, v1, v2, changed_in, batch)) {
                ++stats.rejected_geometry;
                continue;
            }
            if (!register_triangles(rs, v1, v2, closed)) {
                ++stats.rejected_triangles;
                continue;
            }
            const auto [d1, d2] = rs.insert_edge(v1, v2);
            e.faces.split(d1, d2);
            changed_in[v1] = changed_in[v2] = batch;
            summary.edge_inserted(v1, v2);
            for (const LocalTriangle& t : closed) {
                e.record_triangle(t[0], t[1], t[2]);
                summary.triangle_recorded(rs, t);
            }
            ++stats.inserted;
            e.edge_inserted(Phase::FaceSplit, v1, v2, closed.size());
        }
    }
    return stats;
}

} // namespace hrsr::rsr
