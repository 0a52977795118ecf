#include "rsr/face_split_parts.h"

#include "geometry.h"
#include "options.h"
#include "parallel.h"

#include <algorithm>

namespace hrsr::rsr {

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

} // namespace

Closing register_triangles(const RotationSystem& rs, std::uint32_t v1, std::uint32_t v2,
                           std::vector<LocalTriangle>& found, Region region) {
    found.clear();
    if (!has_common_neighbour(rs, v1, v2)) return Closing::Valid;
    // The triangle (a, apex, b) closed on the side where apex is just clockwise of b at a: a face
    // iff apex follows a at b and a follows b at apex. apex's rotation is read last, and recording
    // the triangle changes it. Valid: no triangle there, or `t` found.
    const auto close = [&](std::uint32_t a, std::uint32_t b, std::uint32_t apex,
                           const LocalTriangle& t) {
        if (!rs.adjacent(b, apex) || ccw_angle(rs.angle(apex, b), rs.angle(apex, a)) >= M_PI)
            return Closing::Valid;
        if (!triangle_is_valid(rs, v1, v2, apex) || rs.successor_as_if_inserted(b, a) != apex)
            return Closing::Invalid;
        if (!region.holds(apex)) return Closing::Outside;
        if (successor(rs, apex, b) != a) return Closing::Invalid;
        found.push_back(t);
        return Closing::Valid;
    };
    const std::uint32_t r1 = rs.dart(v1, rs.wedge(v1, v2)).to;
    const std::uint32_t r2 = rs.dart(v2, rs.wedge(v2, v1)).to;
    if (const Closing c = close(v1, v2, r1, {v1, r1, v2}); c != Closing::Valid) return c;
    if (const Closing c = close(v2, v1, r2, {v1, v2, r2}); c != Closing::Valid) return c;
    // Common neighbours but no triangle: the edge would cut across.
    return found.empty() ? Closing::Invalid : Closing::Valid;
}

VertexSummary::VertexSummary(const RotationSystem& rs, const Execution& exec)
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

bool VertexSummary::adjacent_before_the_phase(std::uint32_t v, std::uint32_t w) const {
    return std::find(initial_.begin() + first_[v], initial_.begin() + first_[v + 1], w) !=
           initial_.begin() + first_[v + 1];
}

} // namespace hrsr::rsr
