#include "hrsr/local_flips.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace hrsr::reexpand {

namespace {

// An edge {first, second} with a hint: a face and index where first→second was last seen.
struct Edge {
    std::uint32_t first, second;
    SFace* face = nullptr;
    int z = -1;
};

// The face and edge index of {first, second}, preferring first→second; false if it is not an
// edge. A hint that still holds first→second is the answer the walk would give (in a manifold
// mesh one face holds a directed edge), so the walk is only needed for stale hints.
bool locate(const SplitMesh& m, const Edge& e, SFace*& face, int& z) {
    if (e.face && m.vertex_of(e.face, e.z) == e.first &&
        m.vertex_of(e.face, (e.z + 1) % 3) == e.second) {
        face = e.face;
        z = e.z;
        return true;
    }
    return m.find_undirected_edge(e.first, e.second, face, z);
}

// The cosine of the angle between sides u and v of lengths nu and nv.
double cosine(const Vec3& u, double nu, const Vec3& v, double nv) {
    return (nu > 0 && nv > 0) ? u.dot(v) / (nu * nv) : 1.0;
}

// Angles at the edge's endpoints in both triangles, in the cosine domain (no acos). The five
// sides are measured once (a − b is −(b − a) exactly, and of the same length); any angle over
// 90° decides, whichever is found first.
bool worth_flipping(const SplitMesh& m, SFace* f, int z, double small_cos) {
    SFace* g = f->FFp(z);
    const int w = f->FFi(z);
    const Vec3 a = m.position(m.vertex_of(f, z)), b = m.position(m.vertex_of(f, (z + 1) % 3));
    const Vec3 c = m.position(m.vertex_of(f, (z + 2) % 3)),
               d = m.position(m.vertex_of(g, (w + 2) % 3));
    const Vec3 ab = b - a, ba = a - b, ac = c - a, bc = c - b, ad = d - a, bd = d - b;
    const double n_ab = ab.Norm(), n_ac = ac.Norm(), n_bc = bc.Norm(), n_ad = ad.Norm(),
                 n_bd = bd.Norm();
    bool small = false;
    for (const double k : {cosine(ab, n_ab, ac, n_ac), cosine(bc, n_bc, ba, n_ab),
                           cosine(ad, n_ad, ab, n_ab), cosine(ba, n_ab, bd, n_bd)}) {
        if (k < 0) return false; // an angle over 90°
        small = small || k > small_cos;
    }
    return small;
}

void pass(SplitMesh& m, std::vector<Edge>& edges, double small_cos, std::size_t& flips) {
    // Stable sort by length: lengths computed once, ties kept in list order. Scratch reused
    // from call to call (three calls per split).
    thread_local std::vector<std::pair<double, std::uint32_t>> order;
    thread_local std::vector<Edge> sorted;
    order.clear();
    for (std::uint32_t k = 0; k < edges.size(); ++k)
        order.emplace_back((m.position(edges[k].first) - m.position(edges[k].second)).Norm(), k);
    std::sort(order.begin(), order.end());
    sorted.clear();
    for (const auto& entry : order) sorted.push_back(edges[entry.second]);
    edges.swap(sorted);
    for (auto it = edges.rbegin(); it != edges.rend(); ++it) {
        SFace* f = nullptr;
        int z = -1;
        // The cheap geometric test before the topological walks of can_flip.
        if (!locate(m, *it, f, z) || f->FFp(z) == f || !worth_flipping(m, f, z, small_cos) ||
            !m.can_flip(f, z))
            continue;
        SFace* g = f->FFp(z);
        const Edge diagonal{m.vertex_of(f, (z + 2) % 3), m.vertex_of(g, (f->FFi(z) + 2) % 3)};
        m.flip(f, z);
        *it = diagonal; // the edge keeps its identity, with new endpoints (and no hint)
        ++flips;
    }
}

} // namespace

std::size_t improve_around(SplitMesh& m, std::uint32_t v, const ReexpandOptions& o) {
    thread_local std::vector<Edge> one_ring, circle, two_ring; // reused: one call per split
    thread_local Star s;
    one_ring.clear();
    circle.clear();
    two_ring.clear();
    m.star(v, s);
    m.claim(s); // D-43: the faces across the rim are read below
    const std::size_t d = s.neighbours.size();
    for (std::size_t k = 0; k < d; ++k) {
        SFace* f = s.wedges[k]; // (v, q_k, q_k+1): holds v→q_k and q_k→q_k+1
        if (!f) {
            one_ring.push_back({v, s.neighbours[k]});
            continue;
        }
        int corner = 0;
        while (m.vertex_of(f, corner) != v) ++corner;
        one_ring.push_back({v, s.neighbours[k], f, corner});
        const int link = (corner + 1) % 3;
        circle.push_back({s.neighbours[k], s.neighbours[(k + 1) % d], f, link});
        if (f->FFp(link) == f) continue;
        SFace* far = f->FFp(link);
        const int w = f->FFi(link);
        two_ring.push_back(
            {m.vertex_of(far, (w + 1) % 3), m.vertex_of(far, (w + 2) % 3), far, (w + 1) % 3});
        two_ring.push_back({m.vertex_of(far, (w + 2) % 3), m.vertex_of(far, w), far, (w + 2) % 3});
    }
    const double small_cos = std::cos(constants::kRefinementAngleDegrees * M_PI / 180.0);
    std::size_t flips = 0;
    for (int iteration = 0; iteration < o.refinement_iterations; ++iteration)
        for (std::vector<Edge>* list : {&one_ring, &circle, &two_ring})
            pass(m, *list, small_cos, flips);
    return flips;
}

} // namespace hrsr::reexpand
