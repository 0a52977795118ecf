// D-51: one tile's candidates of a face-split step, taken one by one by one thread while other
// threads take other tiles. Nothing here reads a rotation outside the tile or changes anything
// another tile reads: an insertion changes the rotations of its ends, the triangle counts of the
// triangles it closes, and the labels of the smaller side of the face it splits; each is checked
// to lie in the tile before it happens. The larger side keeps its label, so wedges elsewhere keep
// their answers to "same face?".
#include "rsr/face_split_parts.h"

#include <stdexcept>

namespace hrsr::rsr {

namespace {

// The geometry check's nearby points are sorted: the first and last tell whether all are inside.
bool near_points_inside(const GeometryQuery& query, Region region) {
    return query.near.empty() ||
           (region.holds(query.near.front()) && region.holds(query.near.back()));
}

} // namespace

void split_in_tile(Embedding& e, VertexSummary& summary,
                   const std::vector<CandidateEdge>& candidates, TileSplit& work, bool observe) {
    RotationSystem& rs = e.rotation;
    const Region region{work.tile};
    const auto inside = [&](std::uint32_t v) { return region.holds(v); };
    std::vector<LocalTriangle>& triangles = observe ? e.triangles : work.triangles;
    GeometryQuery query;
    Faces::SplitWalks walks;
    std::vector<LocalTriangle> closed;
    FaceSplitStats& stats = work.stats;
    for (std::size_t k = work.first; k < work.last; ++k) {
        const CandidateEdge& c = candidates[k];
        const std::uint32_t v1 = c.i, v2 = c.j;
        if (summary.surrounded(v1) || summary.surrounded(v2)) {
            // No edge was inserted at a surrounded end, and none before for this pair.
            if (!summary.adjacent_before_the_phase(v1, v2)) ++stats.rejected_topology;
            continue;
        }
        if (rs.adjacent(v1, v2)) continue; // MST edges
        if (e.faces.face_of_wedge(v1, v2) != e.faces.face_of_wedge(v2, v1)) {
            ++stats.rejected_topology;
            continue;
        }
        e.geometry.gather(v1, v2, query);
        if (!near_points_inside(query, region)) {
            work.deferred.push_back(c);
            continue;
        }
        if (!e.geometry.passes_gathered(v1, v2, query)) {
            ++stats.rejected_geometry;
            continue;
        }
        const Closing closing = register_triangles(rs, v1, v2, closed, region);
        if (closing == Closing::Outside) {
            work.deferred.push_back(c);
            continue;
        }
        if (closing == Closing::Invalid) {
            ++stats.rejected_triangles;
            continue;
        }
        if (work.labels == 0) throw std::logic_error("face split: a tile ran out of labels");
        const auto darts = rs.insert_darts(v1, v2);
        if (!e.faces.split_inside(darts.first, darts.second, work.next_label, walks, inside)) {
            rs.erase_darts(darts);
            work.deferred.push_back(c);
            continue;
        }
        ++work.next_label;
        --work.labels;
        summary.edge_inserted(v1, v2);
        for (const LocalTriangle& t : closed) {
            e.record_triangle(t, triangles);
            summary.triangle_recorded(rs, t);
        }
        ++stats.inserted;
        if (observe) {
            rs.count_edges(1);
            e.faces.count_splits(1);
            e.edge_inserted(Phase::FaceSplit, v1, v2, closed.size());
        }
    }
}

} // namespace hrsr::rsr
