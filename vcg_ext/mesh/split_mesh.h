// The mesh re-expansion works on (ALGORITHM.md §8): a vcglib triangle mesh with face-face
// adjacency, whose capacity is reserved up front so that no vertex split ever reallocates (and
// no pointer ever moves), with the vertex split of §8.5 and the flips of §8.3/§8.6.
#pragma once

#include "mesh/triangle_mesh.h"
#include "point_set.h"

#include <vcg/complex/complex.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

namespace hrsr {

class SVertex;
class SFace;
struct SUsedTypes : vcg::UsedTypes<vcg::Use<SVertex>::AsVertexType, vcg::Use<SFace>::AsFaceType> {};
class SVertex : public vcg::Vertex<SUsedTypes, vcg::vertex::Coord3d, vcg::vertex::BitFlags> {};
class SFace
    : public vcg::Face<SUsedTypes, vcg::face::VertexRef, vcg::face::FFAdj, vcg::face::BitFlags> {};
class SMesh : public vcg::tri::TriMesh<std::vector<SVertex>, std::vector<SFace>> {};

/// Edge z of f is on the border: no face across it (vcglib's FF adjacency points back at f).
inline bool is_border(const SFace* f, int z) {
    return f->cFFp(z) == f;
}

/// The counter-clockwise neighbourhood of a vertex: neighbours q_0 … q_{d−1}; wedge k lies
/// between q_k and q_{k+1} (cyclically) and is a face, or null for the boundary gap.
struct Star {
    std::vector<std::uint32_t> neighbours;
    std::vector<SFace*> wedges;
    bool boundary = false;
};

/// D-43: what a guarded mesh throws when work for one tile reaches a vertex of another, before
/// anything is changed.
struct TileConflict {
    std::uint32_t tile; ///< the tile of the vertex reached
};

class SplitMesh {
public:
    /// A manifold, consistently oriented mesh; room for `vertex_capacity` vertices and
    /// `face_capacity` faces in total. Its links are built on `exec`'s threads.
    SplitMesh(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
              std::size_t vertex_capacity, std::size_t face_capacity,
              const Execution& exec = Execution{1, nullptr});
    SplitMesh(const SplitMesh&) = delete;
    SplitMesh& operator=(const SplitMesh&) = delete;

    std::size_t vertex_count() const { return mesh_.vert.size(); }
    std::size_t face_count() const { return std::size_t(mesh_.fn); }
    Vec3 position(std::uint32_t v) const {
        claim(v);
        return mesh_.vert[v].P();
    }
    void move(std::uint32_t v, const Vec3& p) {
        claim(v);
        mesh_.vert[v].P() = p;
    }
    bool isolated(std::uint32_t v) const {
        claim(v);
        return face_of_[v] == nullptr;
    }

    /// D-43: work on tiles of vertices in parallel. `owner` gives every vertex slot its tile.
    /// While guarded, a thread that works for tile t (work_for) reads only t's vertices, the
    /// corners of faces around them and the links (FF) of edges with an end of t, and changes
    /// only faces whose three vertices are t's, so only links of edges with both ends of t:
    /// reaching another tile's vertex throws TileConflict before anything changes. The corners of
    /// a face across tiles and the links of edges across tiles then stay as they are, so each
    /// tile's work depends on its own vertices alone, whatever the other threads do. Code that
    /// reads the link across a star's rim edge must claim the star's neighbours first.
    void set_owners(std::vector<std::uint32_t> owner) { owner_ = std::move(owner); }
    /// Between guarded stretches the caller must join its threads.
    void guard(bool on);
    bool guarded() const { return guarded_; }
    /// Work by groups of 2^shift consecutive tiles (group = tile >> shift; 0: by tiles). Set
    /// between guarded stretches only.
    void group_tiles(int shift) { group_shift_ = shift; }
    static void work_for(std::uint32_t tile) { working_tile_ = tile; }
    /// Whether the current thread may touch v (always, unguarded).
    std::uint32_t owner(std::uint32_t v) const { return owner_[v]; }
    bool owns(std::uint32_t v) const {
        return !guarded_ || (owner_[v] >> group_shift_) == working_tile_;
    }
    void claim(std::uint32_t v) const {
        if (!owns(v)) throw TileConflict{owner_[v]};
    }
    /// Claims a star's neighbours (its centre was claimed by star()).
    void claim(const Star& s) const {
        if (guarded_)
            for (std::uint32_t v : s.neighbours) claim(v);
    }

    /// D-43: `vertices` more (isolated) vertices and `faces` more face slots (unused), for
    /// split()s at given slots: concurrent splits must not allocate.
    void add_slots(std::size_t vertices, std::size_t faces);
    /// Where a split puts c' and its one or two new triangles (slots from add_slots).
    struct Slots {
        std::uint32_t vertex;
        std::size_t faces[2];
    };

    /// Neighbours in counter-clockwise order starting at the smallest id (D-10); empty if isolated.
    Star star(std::uint32_t v) const {
        Star s;
        star(v, s);
        return s;
    }
    /// The same into `out`, reusing its storage: the re-expansion calls this a few times per
    /// split, and allocating two vectors each time was a measurable part of its cost.
    void star(std::uint32_t v, Star& out) const;

    /// §8.5: splits c; the faces from spoke b counter-clockwise to spoke a go to the new vertex,
    /// placed at `position`, and triangles (c', c, b), (c, c', a) are added. a ≠ b must be
    /// neighbours of c. Returns c'. (V, E, F) change by (+1, +3, +2).
    std::uint32_t split(std::uint32_t c, std::uint32_t a, std::uint32_t b, const Vec3& position) {
        return split(c, star(c), a, b, position);
    }
    /// The same with c's star given: `s` must be star(c), the mesh unchanged since.
    std::uint32_t split(std::uint32_t c, const Star& s, std::uint32_t a, std::uint32_t b,
                        const Vec3& position) {
        return split(c, s, a, b, position, BorderSplit::None);
    }

    /// D-34: a split at the border may leave out the new triangle that lies next to c's
    /// boundary gap, (c', c, b) when the wedge before b is the gap (`Out`) or (c, c', a) when the
    /// wedge after a is (`In`): c' then lies on the border between c and that spoke, and the
    /// border gains an edge. (V, E, F) change by (+1, +2, +1).
    enum class BorderSplit { None, Out, In };
    std::uint32_t split(std::uint32_t c, const Star& s, std::uint32_t a, std::uint32_t b,
                        const Vec3& position, BorderSplit omit);
    /// The same into given slots (c' is slots.vertex, the triangles take the face slots in order).
    std::uint32_t split(std::uint32_t c, const Star& s, std::uint32_t a, std::uint32_t b,
                        const Vec3& position, BorderSplit omit, const Slots& slots);

    /// The number of edges of the border loop through v (a border vertex with one gap), when
    /// it is at most `limit`; limit + 1 otherwise (also for a vertex on several loops).
    std::size_t border_loop_edges(std::uint32_t v, std::size_t limit) const;

    /// Whether u and w share an edge (a boundary-safe walk around u).
    bool adjacent(std::uint32_t u, std::uint32_t w) const;

    /// The edge {u, w} in either direction, preferring the face with u→w (one walk around u).
    bool find_undirected_edge(std::uint32_t u, std::uint32_t w, SFace*& face, int& z) const;

    /// Whether edge z of f can be flipped: interior, both sides triangles, the new diagonal
    /// absent, and no interior endpoint of the edge left with fewer than 3 edges.
    bool can_flip(SFace* f, int z) const;
    /// Flips edge z of f (can_flip must hold).
    void flip(SFace* f, int z);
    /// Removes a face (the boundary then runs along its edges).
    void remove_face(SFace* f);

    /// Throws std::logic_error if the faces around v are not a consistent fan (FF symmetric,
    /// every face holding v, no deleted face). Called after every change when the library is
    /// built with HRSR_EXPENSIVE_CHECKS.
    void check_around(std::uint32_t v, const char* after) const;

    std::uint32_t index(const SVertex* v) const { return std::uint32_t(v - mesh_.vert.data()); }
    std::uint32_t vertex_of(const SFace* f, int k) const { return index(f->cV(k)); }
    /// The live triangles, in face order.
    std::vector<Triangle> triangles() const;
    /// The border edges a → b as the faces holding them run (no face has b → a), in face order.
    std::vector<std::array<std::uint32_t, 2>> border_edges() const;
    /// The live faces, in the same order as triangles().
    std::vector<SFace*> live_faces();
    /// A face's position in the face storage (stable: faces never move).
    std::size_t slot(const SFace* f) const { return std::size_t(f - mesh_.face.data()); }
    std::size_t face_slots() const { return mesh_.face.size(); }
    const SMesh& vcg_mesh() const { return mesh_; }

private:
    void link_faces(const VertexCorners& at, const Execution& exec);
    [[noreturn]] static void throw_not_manifold();
    void set_face_of(SFace* f);
    /// c' and the faces for (c', c, b) and (c, c', a): the same face when one is made.
    struct Made {
        SVertex* c2;
        SFace *first, *second;
    };
    std::uint32_t split_into(std::uint32_t c, const Star& s, std::uint32_t a, std::uint32_t b,
                             BorderSplit omit, const Made& made);
    /// Faces added (+) or removed (−): vcglib's count directly when unguarded, else summed
    /// atomically and added when the guard ends.
    void count_faces(int change);
    void claim_face(const SFace* f) const {
        for (int k = 0; k < 3; ++k) claim(vertex_of(f, k));
    }
    /// Whether v is an interior vertex with at most three edges, walking no more than four of
    /// its faces (most vertices have more).
    bool interior_with_three_edges(std::uint32_t v) const;
    /// Calls visit(face, corner) for the faces around v, in no particular order, until it
    /// returns true.
    template <class Visit>
    void for_each_face_any_order(std::uint32_t v, Visit&& visit) const;

    SMesh mesh_;
    std::vector<SFace*> face_of_;      ///< per vertex: one incident face (null if isolated)
    std::vector<std::uint32_t> owner_; ///< per vertex slot: its tile (D-43)
    bool guarded_ = false;
    int group_shift_ = 0; ///< working_tile_ names a group of 2^group_shift_ tiles
    std::atomic<long> guarded_face_change_{0};
    inline static thread_local std::uint32_t working_tile_ = 0;
};

} // namespace hrsr
