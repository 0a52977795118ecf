#include "rsr/small_holes.h"

#include "geometry.h"
#include "rsr/face_split.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace hrsr::rsr {

namespace {

bool edges_have_room(const RotationSystem& rs, const std::vector<std::uint32_t>& cycle) {
    for (std::size_t k = 0; k < cycle.size(); ++k)
        if (triangles_on_edge(rs, cycle[k], cycle[(k + 1) % cycle.size()]) >= 2) return false;
    return true;
}

// Closes the quad a→b→c→d with two triangles on the diagonal {a, c} or {b, d} with the larger
// smallest angle, among the diagonals that are not edges yet. When a diagonal lies inside the
// face in the rotation it is inserted there (a true face split); when the points are so nearly
// collinear that neither does, the two triangles are only recorded: this is the last phase, so
// the rotation is not needed any more, and `extra` keeps one diagonal from being used twice.
bool close_quad(Embedding& e, const std::vector<std::uint32_t>& q,
                std::set<std::pair<std::uint32_t, std::uint32_t>>& extra, bool& inside_rotation) {
    RotationSystem& rs = e.rotation;
    Faces& faces = e.faces;
    auto diagonal_free = [&](std::uint32_t a, std::uint32_t c) {
        return a != c && !rs.adjacent(a, c) && !extra.count({std::min(a, c), std::max(a, c)});
    };
    // D-52: a triangle winding against its corners' normals counts below any that does not;
    // among such triangles, as among the others, the larger smallest angle counts higher.
    auto signed_angle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const Vec3 &pa = rs.position(a), &pb = rs.position(b), &pc = rs.position(c);
        const Vec3 normals = rs.normal(a) + rs.normal(b) + rs.normal(c);
        const double angle = smallest_angle(pa, pb, pc);
        return ((pb - pa) ^ (pc - pa)).dot(normals) > 0 ? angle : angle - 2.0; // angle ≤ π/3
    };
    auto quality = [&](int k) {
        const std::uint32_t a = q[k], b = q[k + 1], c = q[k + 2], d = q[(k + 3) % 4];
        return std::min(signed_angle(a, b, c), signed_angle(a, c, d));
    };
    int best = -1;
    double best_angle = -4;
    for (int k = 0; k < 2; ++k) {
        if (!diagonal_free(q[k], q[k + 2])) continue;
        if (const double angle = quality(k); angle > best_angle) {
            best_angle = angle;
            best = k;
        }
    }
    if (best < 0) return false;
    const std::uint32_t a = q[best], b = q[best + 1], c = q[best + 2], d = q[(best + 3) % 4];
    const std::uint32_t face = rs.dart(a, rs.find(a, b)).face;
    inside_rotation = faces.face_of_wedge(a, c) == face && faces.face_of_wedge(c, a) == face;
    if (inside_rotation) {
        const auto [d1, d2] = rs.insert_edge(a, c);
        faces.split(d1, d2);
        e.record_triangle(a, b, c);
        e.record_triangle(a, c, d);
    } else {
        extra.insert({std::min(a, c), std::max(a, c)});
        faces.mark_recorded_triangle(a, b); // the quad is closed: nothing may enter it any more
        e.triangles.push_back({a, b, c});
        e.triangles.push_back({a, c, d});
    }
    return true;
}

} // namespace

SmallHoleStats close_small_holes(Embedding& e) {
    const RotationSystem& rs = e.rotation;
    const Faces& faces = e.faces;
    const std::vector<LocalTriangle>& triangles = e.triangles;
    SmallHoleStats stats;
    std::set<std::pair<std::uint32_t, std::uint32_t>> extra;
    for (std::uint32_t v = 0; v < rs.vertex_count(); ++v)
        for (std::uint32_t i = 0; i < rs.degree(v); ++i) {
            const std::uint32_t label = rs.dart(v, i).face;
            if (faces.is_recorded_triangle(label) || faces.length({v, i}) > 4) continue;
            const std::vector<std::uint32_t> cycle = faces.vertices({v, i});
            // Visit each face once, from its smallest vertex; skip cycles repeating a vertex.
            if (*std::min_element(cycle.begin(), cycle.end()) != v) continue;
            if (std::set<std::uint32_t>(cycle.begin(), cycle.end()).size() != cycle.size())
                continue;
            if (!edges_have_room(rs, cycle)) continue;
            const std::size_t before = triangles.size();
            if (cycle.size() == 3) {
                e.record_triangle(cycle[0], cycle[1], cycle[2]);
                ++stats.triangles_closed;
                e.edge_inserted(Phase::Ears, cycle[0], cycle[1], 1);
            } else if (bool inside = false;
                       cycle.size() == 4 && close_quad(e, cycle, extra, inside)) {
                ++(inside ? stats.quads_split : stats.quads_recorded_only);
                const LocalTriangle& t = triangles.back();
                if (inside) e.edge_inserted(Phase::Ears, t[0], t[1], triangles.size() - before);
            }
        }
    return stats;
}

} // namespace hrsr::rsr
