#include "hrsr/crossings.h"

#include "geometry.h"
#include "options.h"

#include <algorithm>
#include <utility>

namespace hrsr::reexpand {

namespace {

struct Link {
    SFace* face; ///< the fan triangle (c, v1, v2)
    int edge;    ///< index of the link edge {v1, v2} in it
    std::uint32_t v1, v2;
};

// The plane the test runs in: c's area-weighted mesh normal, or the given one if degenerate.
TangentFrame plane_at(const SplitMesh& m, std::uint32_t c, const Star& s, const Vec3& fallback) {
    Vec3 n(0, 0, 0);
    const Vec3 pc = m.position(c);
    for (std::size_t k = 0; k < s.wedges.size(); ++k)
        if (s.wedges[k])
            n += (m.position(s.neighbours[k]) - pc) ^
                 (m.position(s.neighbours[(k + 1) % s.wedges.size()]) - pc);
    const double length = n.Norm();
    return tangent_frame(length > 1e-300 ? n / length : fallback);
}

double orient(const TangentFrame& f, const Vec3& a, const Vec3& b, const Vec3& p) {
    const double bx = (b - a).dot(f.t1), by = (b - a).dot(f.t2);
    const double px = (p - a).dot(f.t1), py = (p - a).dot(f.t2);
    return bx * py - by * px;
}

// Segment s→e (e pushed 11 % further) against edge v1v2, in the plane; touching counts.
bool crosses(const TangentFrame& f, const Vec3& s, const Vec3& e, const Vec3& v1, const Vec3& v2) {
    const Vec3 far = s + (e - s) * constants::kCrossingExtension;
    const double o1 = orient(f, s, far, v1), o2 = orient(f, s, far, v2);
    const double o3 = orient(f, v1, v2, s), o4 = orient(f, v1, v2, far);
    return o1 * o2 <= 0 && o3 * o4 <= 0 && !(o1 == 0 && o2 == 0); // collinear overlap is not a wall
}

void links(const SplitMesh& m, std::uint32_t c, const Star& s, std::vector<Link>& out) {
    out.clear();
    for (SFace* f : s.wedges) {
        if (!f) continue;
        for (int k = 0; k < 3; ++k)
            if (m.vertex_of(f, k) == c) {
                const int edge = (k + 1) % 3;
                out.push_back({f, edge, m.vertex_of(f, edge), m.vertex_of(f, (edge + 1) % 3)});
            }
    }
}

bool link_is_border(const Link& l) {
    return l.face->FFp(l.edge) == l.face;
}

// Removing the fan triangle keeps c manifold if c is interior, or the triangle touches c's gap.
bool removal_keeps_manifold(const Star& s, const Link& l) {
    if (!s.boundary) return true;
    const std::size_t d = s.wedges.size();
    for (std::size_t k = 0; k < d; ++k)
        if (s.wedges[k] == l.face) return !s.wedges[(k + 1) % d] || !s.wedges[(k + d - 1) % d];
    return false;
}

} // namespace

bool has_crossing(const SplitMesh& m, std::uint32_t c, const Vec3& x_a, const Vec3& x_b,
                  const Vec3& normal) {
    // Scratch reused from call to call (a few calls per split): no allocation on this path.
    thread_local Star s;
    thread_local std::vector<Link> fan;
    m.star(c, s);
    m.claim(s); // D-43: the links of the rim edges are read below
    const TangentFrame f = plane_at(m, c, s, normal);
    links(m, c, s, fan);
    for (const Link& l : fan)
        if (crosses(f, x_a, x_b, m.position(l.v1), m.position(l.v2)) ||
            crosses(f, x_b, x_a, m.position(l.v1), m.position(l.v2)))
            return true;
    return false;
}

CrossingStats resolve_crossings(SplitMesh& m, std::uint32_t c, const Vec3& x_a, const Vec3& x_b,
                                const Vec3& normal) {
    CrossingStats stats;
    // Crossings we cannot resolve: a handful at most, so a vector searched linearly.
    thread_local std::vector<std::pair<std::uint32_t, std::uint32_t>> given_up;
    given_up.clear();
    thread_local Star s;
    thread_local std::vector<Link> fan;
    for (int round = 0;; ++round) {
        if (round == constants::kCrossingRounds) {
            stats.round_limit = true;
            break;
        }
        m.star(c, s);
        m.claim(s); // D-43: the links of the rim edges are read below
        const TangentFrame f = plane_at(m, c, s, normal);
        links(m, c, s, fan);
        bool changed = false;
        // x_a → x_b, then x_b → x_a; interior crossings first (flips), then boundary ones
        // (removal), as in the paper. One change per round, then look again.
        for (int direction = 0; direction < 2 && !changed; ++direction)
            for (int pass = 0; pass < 2 && !changed; ++pass)
                for (const Link& l : fan) {
                    const std::pair<std::uint32_t, std::uint32_t> key = std::minmax(l.v1, l.v2);
                    if (std::find(given_up.begin(), given_up.end(), key) != given_up.end() ||
                        link_is_border(l) != (pass == 1))
                        continue;
                    const Vec3& from = direction == 0 ? x_a : x_b;
                    const Vec3& to = direction == 0 ? x_b : x_a;
                    if (!crosses(f, from, to, m.position(l.v1), m.position(l.v2))) continue;
                    if (pass == 0 && m.can_flip(l.face, l.edge)) {
                        m.flip(l.face, l.edge);
                        ++stats.flips;
                    } else if (pass == 1 && removal_keeps_manifold(s, l)) {
                        m.remove_face(l.face);
                        ++stats.triangles_removed;
                    } else {
                        given_up.push_back(key);
                        ++stats.unresolved;
                        continue;
                    }
                    changed = true;
                    break;
                }
        if (!changed) break;
    }
    // Crossings given up on but later removed by other flips do not count.
    if (stats.unresolved > 0 && !has_crossing(m, c, x_a, x_b, normal)) stats.unresolved = 0;
    return stats;
}

} // namespace hrsr::reexpand
