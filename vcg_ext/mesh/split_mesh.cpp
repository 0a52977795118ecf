#include "mesh/split_mesh.h"

#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/simplex/face/topology.h>

#include <algorithm>
#include <stdexcept>

namespace hrsr {

namespace {

int corner_of(const SFace* f, const SVertex* v) {
    for (int k = 0; k < 3; ++k)
        if (f->cV(k) == v) return k;
    return -1;
}

// Re-attaches FF across edge z of f and edge w of g (g null: border).
void attach(SFace* f, int z, SFace* g, int w) {
    if (g == nullptr) {
        f->FFp(z) = f;
        f->FFi(z) = char(z);
        return;
    }
    f->FFp(z) = g;
    f->FFi(z) = char(w);
    g->FFp(w) = f;
    g->FFi(w) = char(z);
}

// attach() where either face may be missing: the other's edge is then a border.
void link(SFace* f, int z, SFace* g, int w) {
    if (f)
        attach(f, z, g, w);
    else if (g)
        attach(g, w, nullptr, -1);
}

// Edge index of {u, v} in f (either direction), or -1.
int edge_of(const SFace* f, const SVertex* u, const SVertex* v) {
    for (int z = 0; z < 3; ++z)
        if ((f->cV(z) == u && f->cV((z + 1) % 3) == v) ||
            (f->cV(z) == v && f->cV((z + 1) % 3) == u))
            return z;
    return -1;
}

bool face_consistent(const SFace* f) {
    if (f->IsD()) return false;
    for (int z = 0; z < 3; ++z) {
        const SFace* g = f->cFFp(z);
        if (g == f) continue;
        const int w = f->cFFi(z);
        if (w < 0 || w > 2 || g->IsD() || g->cFFp(w) != f || g->cFFi(w) != z) return false;
        if (g->cV(w) != f->cV((z + 1) % 3) || g->cV((w + 1) % 3) != f->cV(z)) return false;
    }
    return true;
}

} // namespace

#ifdef HRSR_EXPENSIVE_CHECKS
// Not while guarded (D-43): the check reads faces beyond what a tile may.
#define HRSR_CHECK_AROUND(v, what) (guarded_ ? (void)0 : check_around(v, what))
#else
#define HRSR_CHECK_AROUND(v, what) ((void)(v))
#endif

void SplitMesh::check_around(std::uint32_t vi, const char* after) const {
    const SVertex* v = &mesh_.vert[vi];
    auto fail = [&](const char* why) {
        throw std::logic_error(std::string("split mesh: inconsistent fan at vertex ") +
                               std::to_string(vi) + " after " + after + ": " + why);
    };
    SFace* start = face_of_[vi];
    if (!start) return;
    SFace* f = start;
    for (std::size_t g = 0; g <= mesh_.face.size(); ++g) {
        const int k = corner_of(f, v);
        if (k < 0) fail("a face around it does not hold it");
        if (!face_consistent(f)) fail("asymmetric face-face adjacency");
        if (is_border(f, k) || f->FFp(k) == start) break;
        f = f->FFp(k);
    }
    SFace* first = f;
    for (std::size_t g = 0; g <= mesh_.face.size(); ++g) {
        const int k = corner_of(f, v);
        if (k < 0) fail("a face around it does not hold it");
        if (!face_consistent(f)) fail("asymmetric face-face adjacency");
        const int z = (k + 2) % 3;
        if (is_border(f, z) || f->FFp(z) == first) return;
        f = f->FFp(z);
    }
    fail("the fan does not close");
}

SplitMesh::SplitMesh(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
                     std::size_t vertex_capacity, std::size_t face_capacity,
                     const Execution& exec) {
    // Reserved once: Allocator::Add* then never reallocates, so no pointer ever moves.
    mesh_.vert.reserve(std::max(vertex_capacity, positions.size()));
    mesh_.face.reserve(std::max(face_capacity, triangles.size()));
    auto v = vcg::tri::Allocator<SMesh>::AddVertices(mesh_, positions.size());
    for (const Vec3& p : positions) (v++)->P() = p;
    auto f = vcg::tri::Allocator<SMesh>::AddFaces(mesh_, triangles.size());
    for (const Triangle& t : triangles) {
        for (int k = 0; k < 3; ++k) f->V(k) = &mesh_.vert[t[k]];
        ++f;
    }
    // Each face writes only its own links and each vertex only its own face: by blocks, the
    // same mesh for any thread count.
    const Execution quiet = without_progress(exec);
    const VertexCorners at = corners_by_vertex(positions.size(), triangles, quiet);
    link_faces(at, quiet);
    face_of_.assign(mesh_.vert.capacity(), nullptr);
    parallel_for_blocks(quiet, positions.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (auto p = std::uint32_t(first); p < end; ++p)
                                if (at.end(p) > at.begin(p)) // the last face in slot order
                                    face_of_[p] = &mesh_.face[at.corner[at.end(p) - 1] / 3];
                        });
    // A wrongly wound or asymmetric input would corrupt every later split: refuse it (O(F)).
    parallel_for_blocks(quiet, mesh_.face.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t fi = first; fi < end; ++fi)
                                if (!face_consistent(&mesh_.face[fi])) throw_not_manifold();
                        });
#ifdef HRSR_EXPENSIVE_CHECKS
    for (std::uint32_t p = 0; p < positions.size(); ++p) check_around(p, "building the mesh");
#endif
}

// Face-face adjacency from per-vertex face lists: a few times faster and several times leaner
// than vcglib's UpdateTopology::FaceFace, which sorts every edge. An edge with more than two
// faces, or two faces running along it the same way, is refused.
void SplitMesh::link_faces(const VertexCorners& at, const Execution& exec) {
    parallel_for_blocks(
        exec, mesh_.face.size(), kCheapBlock, [&](std::size_t, std::size_t first, std::size_t end) {
            for (std::size_t fi = first; fi < end; ++fi) {
                SFace& f = mesh_.face[fi];
                for (int z = 0; z < 3; ++z) {
                    const SVertex *a = f.cV(z), *b = f.cV((z + 1) % 3);
                    f.FFp(z) = &f; // a border unless a face across is found
                    f.FFi(z) = char(z);
                    int found = 0;
                    for (std::uint32_t e = at.begin(index(a)); e < at.end(index(a)); ++e) {
                        SFace& g = mesh_.face[at.corner[e] / 3];
                        if (&g == &f) continue;
                        const int j = corner_of(&g, b);
                        if (j < 0) continue;
                        if (++found > 1 || g.cV((j + 1) % 3) != a) throw_not_manifold();
                        f.FFp(z) = &g;
                        f.FFi(z) = char(j);
                    }
                }
            }
        });
}

void SplitMesh::throw_not_manifold() {
    throw std::logic_error("split mesh: the coarse mesh is not a consistently oriented manifold");
}

void SplitMesh::set_face_of(SFace* f) {
    for (int k = 0; k < 3; ++k) face_of_[index(f->V(k))] = f;
}

void SplitMesh::star(std::uint32_t vi, Star& s) const {
    s.neighbours.clear();
    s.wedges.clear();
    s.boundary = false;
    claim(vi);
    SFace* start = face_of_[vi];
    if (start == nullptr) return;
    const SVertex* v = &mesh_.vert[vi];
    // Walk clockwise to the boundary (or all the way round).
    SFace* f = start;
    for (std::size_t guard = 0;; ++guard) {
        const int k = corner_of(f, v);
        if (is_border(f, k)) {
            s.boundary = true;
            break;
        }
        SFace* g = f->FFp(k); // across edge (v, V(k+1)): the face clockwise of f
        if (g == start || guard > mesh_.face.size()) break;
        f = g;
    }
    // Then counter-clockwise, collecting q_k = V(k+1) of each face and the face as wedge k.
    SFace* first = f;
    for (std::size_t guard = 0;; ++guard) {
        const int k = corner_of(f, v);
        s.neighbours.push_back(index(f->cV((k + 1) % 3)));
        s.wedges.push_back(f);
        const int z = (k + 2) % 3; // edge (V(k+2), v)
        if (is_border(f, z)) {
            s.neighbours.push_back(index(f->cV(z)));
            s.wedges.push_back(nullptr); // the gap closes the cycle
            break;
        }
        f = f->FFp(z);
        if (f == first) break;
        if (guard > mesh_.face.size())
            throw std::logic_error("split mesh: a vertex star does not close");
    }
    // Start at the smallest neighbour id (D-10).
    const auto smallest =
        std::min_element(s.neighbours.begin(), s.neighbours.end()) - s.neighbours.begin();
    std::rotate(s.neighbours.begin(), s.neighbours.begin() + smallest, s.neighbours.end());
    std::rotate(s.wedges.begin(), s.wedges.begin() + smallest, s.wedges.end());
}

std::uint32_t SplitMesh::split(std::uint32_t ci, const Star& s, std::uint32_t ai, std::uint32_t bi,
                               const Vec3& position, BorderSplit omit) {
    if (mesh_.vert.size() == mesh_.vert.capacity() || mesh_.face.size() + 2 > mesh_.face.capacity())
        throw std::logic_error("split mesh: capacity exhausted");
    claim(ci);
    claim(s);
    SVertex* c2 = &*vcg::tri::Allocator<SMesh>::AddVertices(mesh_, 1);
    c2->P() = position;
    auto fn = vcg::tri::Allocator<SMesh>::AddFaces(mesh_, omit == BorderSplit::None ? 2 : 1);
    mesh_.fn -= omit == BorderSplit::None ? 2 : 1; // counted by split_into
    SFace* first = &*fn;
    return split_into(ci, s, ai, bi, omit,
                      {c2, first, omit == BorderSplit::None ? first + 1 : first});
}

std::uint32_t SplitMesh::split(std::uint32_t ci, const Star& s, std::uint32_t ai, std::uint32_t bi,
                               const Vec3& position, BorderSplit omit, const Slots& slots) {
    claim(ci);
    claim(s);
    if (slots.vertex >= mesh_.vert.size() || slots.faces[0] >= mesh_.face.size() ||
        slots.faces[1] >= mesh_.face.size() || !isolated(slots.vertex))
        throw std::logic_error("split mesh: a split into slots that are not free");
    SVertex* c2 = &mesh_.vert[slots.vertex];
    c2->P() = position;
    SFace* first = &mesh_.face[slots.faces[0]];
    SFace* second = &mesh_.face[slots.faces[1]];
    for (SFace* f : {first, second}) f->ClearD();
    if (omit != BorderSplit::None) second->SetD(); // one triangle: the second slot stays unused
    return split_into(ci, s, ai, bi, omit, {c2, first, omit == BorderSplit::None ? second : first});
}

// The split itself, with c' and the faces for (c', c, b) and (c, c', a) given (the same face
// when only one of them is made). Everything it touches was claimed by the caller.
std::uint32_t SplitMesh::split_into(std::uint32_t ci, const Star& s, std::uint32_t ai,
                                    std::uint32_t bi, BorderSplit omit, const Made& made) {
    SVertex* c2 = made.c2;
    const std::size_t d = s.neighbours.size();
    const std::size_t i =
        std::find(s.neighbours.begin(), s.neighbours.end(), ai) - s.neighbours.begin();
    const std::size_t j =
        std::find(s.neighbours.begin(), s.neighbours.end(), bi) - s.neighbours.begin();
    if (i == d || j == d || i == j)
        throw std::logic_error("split mesh: a and b must be distinct neighbours");

    SVertex* c = &mesh_.vert[ci];
    // Faces in the sweep b → a (wedges j … i−1) move to c'. The faces next to the spokes:
    SFace* keep_b = s.wedges[(j + d - 1) % d]; // wedge before b: stays with c
    SFace* move_b = s.wedges[j];               // wedge after b: moves
    SFace* move_a = s.wedges[(i + d - 1) % d]; // wedge before a: moves
    SFace* keep_a = s.wedges[i];               // wedge after a: stays
    if ((omit == BorderSplit::Out && keep_b) || (omit == BorderSplit::In && keep_a))
        throw std::logic_error("split mesh: a border split leaves out a triangle next to the gap");
    const std::uint32_t c2i = index(c2);
    const int keep_b_edge = keep_b ? edge_of(keep_b, c, &mesh_.vert[bi]) : -1;
    const int move_b_edge = move_b ? edge_of(move_b, c, &mesh_.vert[bi]) : -1;
    const int move_a_edge = move_a ? edge_of(move_a, c, &mesh_.vert[ai]) : -1;
    const int keep_a_edge = keep_a ? edge_of(keep_a, c, &mesh_.vert[ai]) : -1;
    for (std::size_t w = j; w != i; w = (w + 1) % d)
        if (SFace* f = s.wedges[w]) f->V(corner_of(f, c)) = c2;

    SFace* t_out = omit == BorderSplit::Out ? nullptr : made.first; // (c', c, b)
    SFace* t_in =
        omit == BorderSplit::In ? nullptr : (t_out ? made.second : made.first); // (c, c', a)
    if (t_out) {
        t_out->V(0) = c2, t_out->V(1) = c, t_out->V(2) = &mesh_.vert[bi];
        attach(t_out, 1, keep_b, keep_b_edge); // {c, b}
    }
    if (t_in) {
        t_in->V(0) = c, t_in->V(1) = c2, t_in->V(2) = &mesh_.vert[ai];
        attach(t_in, 2, keep_a, keep_a_edge); // {a, c}
    }
    link(t_out, 0, t_in, 0);             // {c', c}
    link(t_out, 2, move_b, move_b_edge); // {b, c'}
    link(t_in, 1, move_a, move_a_edge);  // {c', a}
    if (t_out) set_face_of(t_out);
    if (t_in) set_face_of(t_in);
    count_faces(omit == BorderSplit::None ? 2 : 1);
    for (std::uint32_t x : {ci, c2i, ai, bi}) HRSR_CHECK_AROUND(x, "a split");
    return c2i;
}

void SplitMesh::add_slots(std::size_t vertices, std::size_t faces) {
    if (mesh_.vert.size() + vertices > mesh_.vert.capacity() ||
        mesh_.face.size() + faces > mesh_.face.capacity())
        throw std::logic_error("split mesh: capacity exhausted");
    if (vertices > 0) vcg::tri::Allocator<SMesh>::AddVertices(mesh_, vertices);
    if (faces == 0) return;
    auto f = vcg::tri::Allocator<SMesh>::AddFaces(mesh_, faces);
    for (std::size_t k = 0; k < faces; ++k, ++f) f->SetD();
    mesh_.fn -= int(faces);
}

void SplitMesh::guard(bool on) {
    if (on && owner_.size() < mesh_.vert.size())
        throw std::logic_error("split mesh: a guard without an owner for every vertex");
    guarded_ = on;
    if (!on) mesh_.fn += int(guarded_face_change_.exchange(0));
}

void SplitMesh::count_faces(int change) {
    if (guarded_)
        guarded_face_change_.fetch_add(change, std::memory_order_relaxed);
    else
        mesh_.fn += change;
}

std::size_t SplitMesh::border_loop_edges(std::uint32_t v, std::size_t limit) const {
    // The border neighbour after the gap of x (the spoke counter-clockwise after the null wedge).
    Star s; // reused along the loop
    const auto next = [&](std::uint32_t x, std::uint32_t& after) {
        star(x, s);
        std::size_t gaps = 0, gap = 0;
        for (std::size_t k = 0; k < s.wedges.size(); ++k)
            if (!s.wedges[k]) ++gaps, gap = k;
        if (gaps != 1) return false;
        after = s.neighbours[(gap + 1) % s.neighbours.size()];
        return true;
    };
    std::uint32_t x = v;
    for (std::size_t edges = 1; edges <= limit; ++edges) {
        if (!next(x, x)) return limit + 1;
        if (x == v) return edges;
    }
    return limit + 1;
}

template <class Visit>
void SplitMesh::for_each_face_any_order(std::uint32_t vi, Visit&& visit) const {
    claim(vi);
    SFace* start = face_of_[vi];
    if (start == nullptr) return;
    const SVertex* v = &mesh_.vert[vi];
    // Counter-clockwise from `start`; only if that meets the boundary, clockwise from `start`
    // for the rest. For interior vertices (almost all) this is one walk instead of two.
    SFace* f = start;
    for (std::size_t guard = 0; guard <= mesh_.face.size(); ++guard) {
        const int k = corner_of(f, v);
        if (visit(f, k)) return;
        const int z = (k + 2) % 3;
        if (is_border(f, z)) break;
        f = f->FFp(z);
        if (f == start) return;
    }
    f = start;
    for (std::size_t guard = 0; guard <= mesh_.face.size(); ++guard) {
        const int k = corner_of(f, v);
        if (is_border(f, k)) return;
        f = f->FFp(k);
        if (visit(f, corner_of(f, v))) return;
    }
    throw std::logic_error("split mesh: a vertex star does not close");
}

bool SplitMesh::interior_with_three_edges(std::uint32_t v) const {
    std::size_t faces = 0;
    bool boundary = false;
    for_each_face_any_order(v, [&](SFace* f, int k) {
        boundary = is_border(f, (k + 2) % 3) || is_border(f, k);
        return boundary || ++faces > 3;
    });
    return !boundary && faces <= 3;
}

bool SplitMesh::find_undirected_edge(std::uint32_t u, std::uint32_t w, SFace*& face, int& z) const {
    const SVertex* target = &mesh_.vert[w];
    SFace* reverse = nullptr;
    int reverse_z = -1;
    bool found = false;
    for_each_face_any_order(u, [&](SFace* f, int k) {
        if (f->cV((k + 1) % 3) == target) {
            face = f;
            z = k;
            found = true;
            return true;
        }
        if (!reverse && f->cV((k + 2) % 3) == target) {
            reverse = f;
            reverse_z = (k + 2) % 3;
        }
        return false;
    });
    if (found || !reverse) return found;
    face = reverse;
    z = reverse_z;
    return true;
}

bool SplitMesh::adjacent(std::uint32_t u, std::uint32_t w) const {
    bool found = false;
    const SVertex* target = &mesh_.vert[w];
    for_each_face_any_order(u, [&](SFace* f, int k) {
        found = f->cV((k + 1) % 3) == target || f->cV((k + 2) % 3) == target;
        return found;
    });
    return found;
}

bool SplitMesh::can_flip(SFace* f, int z) const {
    claim_face(f);
    if (is_border(f, z)) return false;
    claim(vertex_of(f->FFp(z), (f->FFi(z) + 2) % 3));
    if (!vcg::face::CheckFlipEdge(*f, z)) return false;
    // The new diagonal must not exist yet. vcg's CheckFlipEdge looks for it by circulating with
    // Pos::NextE, which on a boundary vertex bounces at the border and comes back before seeing
    // the faces on the far side of its start: it can miss the edge (seen on the bunny scans).
    if (adjacent(vertex_of(f, (z + 2) % 3), vertex_of(f->FFp(z), (f->FFi(z) + 2) % 3)))
        return false;
    // An interior endpoint with 3 edges would drop to 2 (ALGORITHM.md §8.6).
    return !interior_with_three_edges(vertex_of(f, z)) &&
           !interior_with_three_edges(vertex_of(f, (z + 1) % 3));
}

void SplitMesh::flip(SFace* f, int z) {
    claim_face(f);
    SFace* g = f->FFp(z);
    claim_face(g);
    vcg::face::FlipEdge(*f, z);
    set_face_of(f);
    set_face_of(g);
    for (int k = 0; k < 3; ++k) {
        HRSR_CHECK_AROUND(vertex_of(f, k), "a flip");
        HRSR_CHECK_AROUND(vertex_of(g, k), "a flip");
    }
}

void SplitMesh::remove_face(SFace* f) {
    claim_face(f);
    SFace* across[3];
    for (int z = 0; z < 3; ++z) across[z] = is_border(f, z) ? nullptr : f->FFp(z);
    for (int z = 0; z < 3; ++z)
        if (across[z]) attach(across[z], f->FFi(z), nullptr, 0);
    // Each corner keeps a face across one of its two edges in f; with neither, it is left
    // isolated (in a manifold mesh it has no other face).
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = index(f->V(k));
        if (face_of_[v] == f) face_of_[v] = across[k] ? across[k] : across[(k + 2) % 3];
    }
    f->SetD();
    count_faces(-1);
    for (int k = 0; k < 3; ++k) HRSR_CHECK_AROUND(index(f->V(k)), "a face removal");
}

std::vector<Triangle> SplitMesh::triangles() const {
    std::vector<Triangle> out;
    out.reserve(std::size_t(mesh_.fn));
    for (const SFace& f : mesh_.face)
        if (!f.IsD()) out.push_back({vertex_of(&f, 0), vertex_of(&f, 1), vertex_of(&f, 2)});
    return out;
}

std::vector<std::array<std::uint32_t, 2>> SplitMesh::border_edges() const {
    std::vector<std::array<std::uint32_t, 2>> out;
    for (const SFace& f : mesh_.face)
        if (!f.IsD())
            for (int z = 0; z < 3; ++z)
                if (is_border(&f, z)) out.push_back({vertex_of(&f, z), vertex_of(&f, (z + 1) % 3)});
    return out;
}

std::vector<SFace*> SplitMesh::live_faces() {
    std::vector<SFace*> out;
    out.reserve(std::size_t(mesh_.fn));
    for (SFace& f : mesh_.face)
        if (!f.IsD()) out.push_back(&f);
    return out;
}

} // namespace hrsr
