// D-32's remover (fold_removal.h): the mesh as the pairs are resolved, faces retired and added,
// with the steps that change it. Internal to the fold removal; its parts are defined by job:
// fold_removal.cpp (the pairs and cuts), fold_remover_fills.cpp (fans and discs refilled),
// fold_remover_loops.cpp (short border loops, D-38, D-45, D-48), fold_remover_put_back.cpp
// (vertices put back, D-37, D-41) and fold_remover_pieces.cpp (small pieces absorbed, D-55).
#pragma once

#include "geometry.h"
#include "graph/concurrent_sets.h"
#include "mesh/fans.h"
#include "mesh/fold_removal.h"
#include "mesh/small_holes_fill.h"
#include "mesh/triangle_grid.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hrsr::folds {

// Holes with more corners get the fans only: the best triangulation is cubic in the corners.
constexpr std::size_t kMaxOptimisedHole = 48;
// D-38: the gaps closed after the folds have up to six edges, one more than D-28's fill takes
// (the walk has taken six since D-38 was written; its measurements were made so). Five only left
// bunny 119 → 125, lion 3,393 → 3,425, LMS400 table 5,434 → 5,476 boundary edges
// (docs/BENCHMARKS.md, session 28).
constexpr std::size_t kMaxClosedGap = kMaxFilledLoop + 1;
constexpr std::uint32_t kNoFace = ~0u;

/// A ball that a disc of fans stays in.
struct Reach {
    Vec3 centre;
    double radius;
};

/// The hole a vertex's fan leaves: its link, in the fan's order.
struct Hole {
    std::vector<std::uint32_t> corners;
    bool closed = false; ///< an inner vertex: each side, the last to the first too, is an edge
};

/// The border of a disc of faces, as a hole, and the vertices inside it.
struct DiscBorder {
    Hole hole;
    std::vector<std::uint32_t> inner; ///< the vertices that go with the faces
};

class Remover {
public:
    // `search` holds the pairs left on the mesh `triangles` and the grid that found them.
    Remover(FoldSearch& search, const std::vector<Vec3>& normals,
            const std::vector<Triangle>& triangles, std::size_t pinhole_edges);

    // Every pair, in order, while both its faces stand.
    void run(FoldRemovalStats& stats);

    // The faces that stand (kept ones in order, then the new ones) over the vertices that
    // still have one; pinched vertices split into copies.
    FoldRemoval result(std::vector<Triangle>& triangles, FoldRemovalStats stats) const;

private:
    // ----------------------------------------------------------------------------------------
    // The pairs, one by one, and the faces cut (fold_removal.cpp).

    // Per face, the faces it intersects (CSR), and how many of them stand.
    void index_pairs();

    // The pair goes by the first of D-32's steps that works (ALGORITHM.md): a corner's fan
    // removed and its hole filled (corners by most pairs around them, fills facing the normals
    // first); a flap at the border cut; a disc of fans removed and filled; one face cut.
    void resolve(const TrianglePair& p, FoldRemovalStats& stats);

    // A face cut inside the mesh leaves a triangular hole. Once every pair is gone, what stood in
    // the way of the fills may be gone too: the hole is closed as close_around() closes one.
    // Returns the vertices removed (0: still open).
    std::size_t close_cut(const Triangle& cut);

    // The holes that cuts left inside the mesh and close_cut did not close: several cuts next
    // to each other leave one hole that is no single cut face's. A border loop through a cut
    // face's corner, of at most kMaxClosedGap edges, along a cut face and with no edge on the
    // border of the given mesh (a hole of a closed surface, as D-28 closes them), is
    // triangulated across, or else closed as close_cut closes a cut face's hole: a corner's fan
    // filled together with it, then a disc of fans near it.
    void close_small_cut_holes(FoldRemovalStats& stats);

    // Edges of face f in no other standing face.
    int border_edges(std::uint32_t f);

    // A face leaves the mesh: the pairs it was in are gone.
    void retire(std::uint32_t f);

    void add(const Triangle& t);

    // ----------------------------------------------------------------------------------------
    // Fans and discs taken out and their holes filled (fold_remover_fills.cpp).

    // The fills that close a hole with `corners` in fill order (a cut face's, or a short loop's):
    // a corner whose fan, open at the hole, is triangulated again across it (the notch of an
    // open hole); else a disc of fans around a corner within kClosingReach of the hole's longest
    // side from its centre (a hole is not worth points taken from further away). Returns the
    // vertices removed (0: the hole is still open).
    std::size_t close_around(const std::vector<std::uint32_t>& corners);

    // Fills a closed hole with the first triangulation that fits (facing the normals first).
    bool close_hole(const Hole& hole);

    // Where no single fan's hole can be filled: a disc of fans around v, grown one vertex at a
    // time towards the face that stood in the way of the last fill, until its hole can be
    // filled (rather than left open). Returns the vertices removed (0: none, nothing changed).
    // With a `reach`, the disc grows only by corners within it.
    std::size_t refill_region(std::uint32_t v, const Reach* reach = nullptr);

    // The hole `faces` (already marked dead) leave, when they form a disc: the border edges
    // they share with standing faces, wound as the faces are, as one simple loop (an inner
    // disc) or one simple path whose ends the fill will join (a disc on the mesh's border,
    // whose border edges there go with it).
    std::optional<DiscBorder> disc_border(const std::vector<std::uint32_t>& faces) const;

    // Chains `edges` (sorted by source) into hole.corners: a loop if hole.closed, else a path
    // from the one source that is no target. False unless every edge is used once and no
    // corner repeats.
    static bool chain(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges,
                      Hole& hole);

    // The corner of the hole nearest to the face that stood in the way of the last fill (or to
    // the region's first vertex), not yet in the region.
    std::uint32_t nearest_corner(const std::vector<std::uint32_t>& corners,
                                 const std::vector<std::uint32_t>& region) const;

    // How far first_fitting_fill() searches: the triangulation best by its angles only, or then
    // also the best among triangles that cross no standing face (a second, costlier search).
    enum class FillSearch { by_angle, then_around_crossings };

    // Removes v's fan and fills its hole, if a triangulation fits.
    bool refill(std::uint32_t v, bool facing,
                FillSearch search = FillSearch::then_around_crossings);

    // `fill` stands instead of `faces`; the `removed` vertices go back where they fit around
    // the hole's `corners`.
    void replace(const std::vector<std::uint32_t>& faces, const std::vector<Triangle>& fill,
                 const std::vector<std::uint32_t>& removed,
                 const std::vector<std::uint32_t>& corners);

    std::optional<std::vector<Triangle>>
    first_fitting_fill(const Hole& hole, bool facing,
                       FillSearch search = FillSearch::then_around_crossings);

    // The triangulation of the hole with the largest smallest angle (dynamic programming over
    // its corners in order, which keeps the fan's orientation), whose diagonals are not edges
    // yet, of proper triangles that (if asked) cross no standing face; empty when there is none.
    std::vector<Triangle> best_fill(const Hole& hole, bool facing, bool avoid_crossings);

    // Not degenerate for the pair test and, if asked, facing the way its corners' normals do.
    bool proper(const Triangle& t, bool facing) const;

    // A fill fits: proper triangles, no diagonal that is an edge already, no intersection
    // among its triangles or with any standing face.
    bool fits(const Hole& hole, const std::vector<Triangle>& fill, bool facing);

    // Whether t crosses a standing face (the first one met is the blocker).
    bool intersects_standing(const Triangle& t);

    // The standing faces whose boxes meet `box`, each once with its box. A fill's triangles lie
    // in the box of the hole's corners: one search there serves all its tests.
    void gather_standing(const Box& box);

    // The faces taken out while fills are tested (sorted): with the mesh's version, what
    // crosses_gathered()'s answers hold for.
    void set_faces_out(std::vector<std::uint32_t> faces);

    // intersects_gathered() for the triangulations of a hole (best_fill), remembered while the
    // mesh and the faces taken out stay the same: the fills facing the normals and then the
    // others, and the corners tried one after the other, test many of the same triangles
    // against the same faces. The blocker is remembered with the answer, so that it is the face
    // the test would find again (the same gathered faces in the same order).
    bool crosses_gathered(const Triangle& t);

    // intersects_standing() among the gathered faces (t within the box they were gathered for).
    bool intersects_gathered(const Triangle& t);

    // ----------------------------------------------------------------------------------------
    // Short border loops closed after the pairs: D-38, D-45, D-48 (fold_remover_loops.cpp).

    // D-38: a border loop of at most kMaxClosedGap edges is a gap of about a spacing (D-28),
    // whichever phase left it; D-28's fans cross the mesh where the faces around it fold over
    // the gap. Such a loop is closed the way close_cut closes a cut face's hole: triangulated
    // across, else a corner's fan filled with it, else a disc of fans near it; the vertices
    // those take out must all go back at once (put_back), or the closing is undone: a gap is
    // not worth a point.
    void close_small_holes_left(FoldRemovalStats& stats);

    // D-45: once every other vertex is back, the loops longer than kMaxFilledLoop and no longer
    // than pinhole_edges_ of a piece whose every border loop is so short (as D-39 on the coarse
    // mesh) are closed as D-38 closes a gap, at most a vertex per kMaxFilledLoop edges left out.
    // After the other closings and D-55, so that no vertex the earlier steps placed is kept out
    // by their fills (only D-48's slits and D-60's last put-back come after).
    void close_pinholes(FoldRemovalStats& stats);

    // D-48: a border loop of up to kMaxOptimisedHole edges whose two sides run closer than
    // kMaxSlitWidth edges of the faces around it (a slit: where a thin part's rim or two sheets
    // closer than the spacing left the faces apart) is closed as D-38 closes a gap; every vertex
    // the closing takes out goes back, or it is undone.
    void close_slits(FoldRemovalStats& stats);

    // ----------------------------------------------------------------------------------------
    // D-64 and D-65, last: faces winding against their corners' normals turned by edge flips,
    // then refilled around a corner (fold_remover_facing.cpp).

    // Every standing face whose normal points away from the sum of its corners' normals (a fold
    // flat on the surface meets its neighbours only along edges: no pair shows it), in face
    // order, has an edge flipped: the first whose two new faces both face their normals (in the
    // later passes, fewer of the two against them than before: a flap of several faces turns one
    // flip at a time), are proper, repeat no face, cross no standing face nor each other, and
    // whose new diagonal is not an edge yet. Passes repeat while one flips. Vertices, pieces and
    // the border stay as they are. Returns the faces still against their normals.
    std::vector<std::uint32_t> turn_faces_against_normals(FoldRemovalStats& stats);

    // D-65: each face of `against` that still winds against its corners' normals, for its first
    // inner corner (closed link) that allows it: the corner's fan is taken out, its hole filled
    // by triangles facing their normals that cross nothing (refill()) and the corner put back
    // by a facing split of a face near the hole into three (reinsert()); kept only if the corner
    // is back and the new faces make no more sharp folds (sharp_edges()) than the fan did, else
    // undone. Every new face faces its normals, so vertices, pieces and the border
    // stay as they are (a disc replaced by a disc) and the count only falls.
    void refill_faces_against_normals(const std::vector<std::uint32_t>& against,
                                      FoldRemovalStats& stats);

    // Edges of `faces` (standing) whose two faces' normals are more than kSharpFoldDegrees
    // apart, each once.
    std::size_t sharp_edges(const std::vector<std::uint32_t>& faces) const;

    // v's faces form one fan whose link is closed (v is no border vertex and no pinch).
    bool inner_vertex(std::uint32_t v) const;

    // One such flip at face f (strict: both new faces facing); the new faces, or none.
    std::vector<std::uint32_t> turn(std::uint32_t f, bool strict);

    // Whether t faces the sum of its corners' normals (proper()'s test of facing, and D-64's).
    bool faces_its_normals(const Triangle& t) const {
        return normal_of(t).dot(normals_[t[0]] + normals_[t[1]] + normals_[t[2]]) > 0;
    }

    // A slit: the loop's median width (each corner's distance to the nearest corner at least a
    // quarter of the loop away along it) is at most kMaxSlitWidth spacings, where the spacing is
    // the median edge of the faces around its corners; it is long for its width (at most
    // kMaxSlitRoundness of a circle's of its perimeter: a round hole that narrow is D-38's); and
    // no loop edge is longer than kMaxSlitEdge spacings (a loop with such edges is what is left
    // of a real hole that faces already bridge: the shark's bored holes at p = 1/4).
    bool is_slit(const std::vector<std::uint32_t>& loop) const;

    // The median edge of the standing faces around the loop's corners (0: none).
    double spacing_around(const std::vector<std::uint32_t>& loop) const;

    // The vertices a border loop may start at: those on the border of the given mesh, and the
    // corners of faces ever added or cut (the quick tests first: most vertices are neither; a
    // vertex whose cut faces all stand again has its given faces, and its given border).
    std::vector<std::uint32_t> border_candidates();

    // Closes the loop through v of at most `limit` edges, if there is one, as D-38 does; at
    // most `may_lose` of the vertices it takes out may stay out, the others go back as D-57's
    // put-back takes them (D-61: a split that turns as its face does counts). Whether it closed.
    bool close_loop_at(std::uint32_t v, std::size_t limit, std::vector<std::uint8_t>& tried,
                       FoldRemovalStats& stats, std::size_t may_lose = 0);

    // close_loop_at() on the loop found.
    bool close_loop(const Hole& hole, std::size_t limit, FoldRemovalStats& stats,
                    std::size_t may_lose = 0);

    // Per start, whether its piece (connected by standing faces) is closed but for loops of at
    // most pinhole_edges_: every border loop of it that short, none through a vertex with two
    // border edges out, and more interior than border vertices (D-39's test of a closed coarse
    // piece). `loop_edges` are those of border_loops_at() at the `starts`. The pieces are joined
    // by parallel blocks of faces (a piece's root is its smallest vertex for any thread count),
    // and only the starts' pieces have their vertices counted.
    std::vector<std::uint8_t>
    pieces_closed_but_for_pinholes(const std::vector<std::uint32_t>& starts,
                                   const std::vector<std::size_t>& loop_edges) const;

    // Per start v: the edges of the border loop through v when it closes within `limit` edges;
    // limit + 1 for a longer loop or one through a vertex with two border edges out; 0 when v
    // has no border edge out. Each walk gives its outcome to every vertex it passes: a vertex
    // with one border edge in has one out (its fans' ends pair up), so the walks from them
    // follow the same chain and end alike (a chain that met itself elsewhere than at its start
    // would pass a vertex with two edges in, hence two out, where every walk stops).
    std::vector<std::size_t> border_loops_at(const std::vector<std::uint32_t>& starts,
                                             std::size_t limit) const;

    // Per vertex of the given mesh (one fan each): the sum of its faces' next corners minus the
    // sum of their previous ones, i.e. the last spoke minus the first of an open fan and 0 for
    // a closed one (each next corner is another face's previous). Nonzero: on the border. One
    // pass over the faces in order, instead of a walk around every vertex.
    std::vector<std::int64_t> given_fan_ends() const;

    // Closes a short loop; a corner's fan filled with it may only shrink it (the fill joins the
    // corner's neighbours on the loop), so what is left is tried again.
    bool close_small_hole(Hole hole, std::size_t limit);

    // Where an undo goes back to (the faces retired since are in retired_log_): the faces there
    // were, the count of vertices put back and of those that joined the border.
    struct Undo {
        std::size_t faces, reinserted, joined_border;
    };
    Undo begin_undo();

    // Every vertex the faces retired since begin_undo() left without a face goes back over a
    // face near it, or false.
    bool put_back_taken_out();

    // The points the faces retired since begin_undo() left without a face (no copy of them
    // stands), one vertex each.
    std::vector<std::uint32_t> taken_out() const;

    // The faces stand as they did at `undo`.
    void rewind(const Undo& undo);

    // The change since `undo` is kept or rewound; either way no vertex it took out counts as
    // put back (each is back, or lost and counted as removed by the caller).
    void end_undo(const Undo& undo, bool keep);

    // The border loop that leaves v along a border edge, as the hole a fill closes (corners in
    // the order of the faces that would fill it), if it is short, runs along a cut face (an edge
    // whose other face in the given mesh has gone) and has no edge that was on the border of the
    // given mesh (fills make edges the given mesh did not have).
    std::optional<Hole> small_cut_hole(std::uint32_t v) const;

    // The border loop of at most `limit` edges that leaves v, as the hole a fill closes; with
    // `cut_only`, only a loop as small_cut_hole() takes it.
    std::optional<Hole> small_hole(std::uint32_t v, bool cut_only, std::size_t limit) const;

    // The one border edge a→b leaving a (a standing face holds a→b, none b→a), if exactly one;
    // `out`, if given, gets how many leave a.
    std::optional<std::uint32_t> border_successor(std::uint32_t a,
                                                  std::size_t* out = nullptr) const;

    // ----------------------------------------------------------------------------------------
    // Small pieces that lie on another surface join it: D-55 (fold_remover_pieces.cpp).

    // D-55: a piece (connected by standing faces) of at most kMaxAbsorbedPieceFaces faces, not
    // the largest, whose every point goes back over a face of another piece near it (put_back's
    // rules) once its faces are gone, joins that surface so; else it stays as it was. D-56
    // first: a piece of at most kMaxPieceInHoleFaces faces lying in a short border loop of
    // another piece joins it by closing the loop, its points going into the fill. Pieces
    // largest first; their points go over the faces of another small piece not joined yet
    // only where nothing else takes them (D-58). Their points go as D-60's last pass takes
    // points (D-63).
    void absorb_small_pieces(FoldRemovalStats& stats);

    // One piece's faces out and its points over faces near them, or the piece stands again;
    // `close_holes_around`: the short border loops around it closed first (D-56), and up to
    // an eighth of its points may stay out.
    bool absorb_piece(const std::vector<std::uint32_t>& piece, bool close_holes_around,
                      FoldRemovalStats& stats);

    // D-58: whether some face ever at v (standing or not) is marked as a small piece's.
    bool ever_in_a_small_piece(std::uint32_t v) const;

    // D-58: after a piece joined another small piece, the faces it made there marked as that
    // piece's (in_small_piece_ sized to every face made since).
    void mark_faces_made_on_small_pieces();

    // D-56: the border loops of at most kMaxOptimisedHole edges near the piece (its faces
    // already out) that surround the piece's centre, closed as D-38 closes a gap; false if
    // there is none, if the piece has fewer than kMinHoleFill of the points a surface over one
    // would have at the spacing around it (a hole in the data with a scrap in it stays), or if
    // one does not close.
    bool close_holes_under(const std::vector<std::uint32_t>& piece,
                           const std::vector<std::uint32_t>& points);

    // Whether the loop winds around p in its own plane (Newell's), p no further from that plane
    // than the loop's radius.
    bool surrounds(const std::vector<std::uint32_t>& loop, const Vec3& p) const;

    // The loop's area vector (Newell's: its length is the area it spans).
    Vec3 area_vector(const std::vector<std::uint32_t>& loop) const;

    // The loop (in fill order, as small_hole() gives it) is a hole in a surface, not the rim of
    // one: a fill across it faces its corners' normals.
    bool is_a_hole(const std::vector<std::uint32_t>& loop) const;

    // Per piece (sets labelled in the order of their smallest vertex) the standing faces of the
    // pieces of at most `max_faces` faces but the largest piece; empty when the mesh is one
    // piece.
    std::vector<std::vector<std::uint32_t>> small_pieces(std::size_t max_faces) const;

    // The vertices joined by standing faces (a set's root is its smallest vertex, for any thread
    // count).
    ConcurrentSets standing_pieces() const;

    // Whether some vertex at v's position has a standing face (v itself or a copy of it).
    bool point_has_standing_face(std::uint32_t v) const;

    // ----------------------------------------------------------------------------------------
    // Vertices put back into faces near them: D-37, D-41 (fold_remover_put_back.cpp).

    // The ways a point may go back over a face near it: first by a split facing its corners'
    // normals over faces facing its own normal (D-41), else
    enum class PutBack {
        or_turned, ///< by one that only turns as the faces it replaces (D-57, D-61)
        /// the same, or over a face its normal is not within 60° of opposed to (D-62) or that it
        /// lies flat on (D-60): the last pass, and a small piece's points (D-63)
        or_flat_against,
    };

    // Puts removed vertices back where they fit into a face around the hole's `corners` (the
    // fill's, or one next to it): a face split into three around the vertex, proper triangles
    // facing their normals that cross no standing face, the split with the largest smallest
    // angle. Returns how many went back.
    std::size_t reinsert(const std::vector<std::uint32_t>& removed,
                         const std::vector<std::uint32_t>& corners);

    // Removed vertices that no hole took back, once every fold is resolved: each over a
    // standing face near it, splitting that face into three or, over one of its edges, the
    // edge's two faces into four, or beyond a border vertex as two triangles closing its corner
    // (D-37). Every new triangle is proper, faces its corners' normals, turns the way the face
    // it replaces (or borders) does and crosses no standing face; of those that fit, the split
    // with the largest smallest angle.
    // D-37: vertices that never had a face (points in no triangle, given as such) go the same
    // way, within a grid cell of where they are.
    // D-57: in rounds while one places a point; where no facing split fits, one whose triangles
    // only turn as the face they replace does (`how`: PutBack::or_turned, or
    // PutBack::or_flat_against once every other step is done, D-60).
    void put_back_the_rest(PutBack how);

    bool never_had_a_face(std::uint32_t v) const;

    // v had faces and has none now (the original ones are looked at first: no map lookup for
    // the many vertices that kept one).
    bool lost_all_faces(std::uint32_t v) const;

    struct Split {
        std::vector<std::uint32_t> faces;  ///< replaced (none for a triangle beyond the border)
        std::vector<Triangle> triangles;   ///< instead
        std::vector<std::uint32_t> source; ///< per triangle: the face it lies over (or beside)
        bool lengthens_border = false;     ///< D-41: v joins a border edge
    };
    // v's old fan's mean edge: how far from v a face may be to take it back (a vertex that had
    // no fan: a cell of the grid, about two mean face sizes).
    double fan_reach(std::uint32_t v) const;

    // The standing face across f's edge k (from corner k to k + 1), or none.
    std::optional<std::uint32_t> across(std::uint32_t f, int k) const;

    std::vector<Split> splits_near(std::uint32_t v, PutBack how);

    // v beyond the border at b, between the border edges a → b (of face f) and b → c: the
    // triangles (b, a, v) and (c, b, v) close b's corner, and the border runs a → v → c, as long
    // as before (a point left out is worth less than no sliver along the border). The edge
    // b → c is found by walking b's fan from f, so that it is f's own fan's other side (b may
    // still be pinched between D-32's cuts).
    void add_corner_fill(std::uint32_t f, int k, std::uint32_t v, std::vector<Split>& splits) const;

    // Whether f is a face of a small piece D-55/D-56 has not joined yet, while such faces take
    // no point (D-58).
    bool of_a_small_piece(std::uint32_t f) const { return !scraps_take_points_ && marked_small(f); }

    // Whether f is marked in in_small_piece_ (faces made after the marks were sized are not).
    bool marked_small(std::uint32_t f) const {
        return f < in_small_piece_.size() && in_small_piece_[f] != 0;
    }

    // v may go over face f: f faces v's normal (or, if `how` allows it, v lies flat on f: D-60)
    // and v is not a spike over it.
    bool goes_over(std::uint32_t v, std::uint32_t f, PutBack how) const;

    // v is at most `sides` of face f's longest side off its plane.
    bool within_height(std::uint32_t v, std::uint32_t f, double sides) const;

    // D-41: every face v goes over must face v's own normal (but in D-60's last pass), not only
    // the sum of the new triangles' corners' normals: two sheets closer than a spacing with
    // opposed normals would otherwise trade points (a point of one went into a face of the
    // other). `how` says what else is allowed where no such split fits.
    bool put_back(std::uint32_t v, PutBack how);

    // The best of `splits` (the border lengthened last, then the largest smallest angle) whose
    // triangles are proper (facing their corners' normals if `facing`), turn as the faces they
    // replace do and cross no standing face, made; false if none fits.
    bool fit_split(std::uint32_t v, const std::vector<Split>& splits, bool facing, PutBack how);

    // intersects_gathered() among the gathered faces that still stand.
    bool intersects_gathered_standing(const Triangle& t) const;

    // ----------------------------------------------------------------------------------------
    // The mesh as it stands: queries every part asks.

    // A face of the given mesh held a→b.
    bool given_edge(std::uint32_t a, std::uint32_t b) const {
        for (std::uint32_t e = at_.begin(a); e < at_.end(a); ++e)
            if (triangles_[at_.corner[e] / 3][(at_.corner[e] % 3 + 1) % 3] == b) return true;
        return false;
    }

    Vec3 normal_of(const Triangle& t) const {
        return (positions_[t[1]] - positions_[t[0]]) ^ (positions_[t[2]] - positions_[t[0]]);
    }

    static std::array<Triangle, 3> split_around(const Triangle& t, std::uint32_t r) {
        return {{{t[0], t[1], r}, {t[1], t[2], r}, {t[2], t[0], r}}};
    }

    double angle(const Triangle& t) const {
        return smallest_angle(positions_[t[0]], positions_[t[1]], positions_[t[2]]);
    }

    Box corners_box(const std::vector<std::uint32_t>& corners) const {
        Box box{positions_[corners.front()], positions_[corners.front()]};
        for (std::uint32_t c : corners) box.add(positions_[c]);
        return box;
    }

    Triangle welded(const Triangle& t) const {
        return {representative_[t[0]], representative_[t[1]], representative_[t[2]]};
    }

    std::vector<std::uint32_t> faces_of(std::uint32_t v) const {
        std::vector<std::uint32_t> faces;
        any_face_index(v, [&](std::uint32_t f) {
            faces.push_back(f);
            return false;
        });
        return faces;
    }

    // Whether `test` holds for a standing face of v (faces_of without the list: the edge and
    // duplicate tests run inside the fills' search).
    template <class Test>
    bool any_face(std::uint32_t v, Test&& test) const {
        return any_face_index(v, [&](std::uint32_t f) { return test(triangles_[f]); });
    }

    // any_face() with the face's number: the given faces first, then those added.
    template <class Test>
    bool any_face_index(std::uint32_t v, Test&& test) const {
        for (std::uint32_t e = at_.begin(v); e < at_.end(v); ++e)
            if (alive_[at_.corner[e] / 3] && test(at_.corner[e] / 3)) return true;
        if (!touched_[v]) return false; // no face was ever added at v
        const auto it = added_at_.find(v);
        if (it == added_at_.end()) return false;
        return std::any_of(it->second.begin(), it->second.end(),
                           [&](std::uint32_t f) { return alive_[f] && test(f); });
    }

    bool has_standing_face(std::uint32_t v) const {
        return any_face(v, [](const Triangle&) { return true; });
    }

    // Whether a and b are the same triangle of positions.
    bool same_positions(const Triangle& a, const Triangle& b) const {
        return sorted_positions(a) == sorted_positions(b);
    }

    // t's corners welded, in increasing order.
    Triangle sorted_positions(const Triangle& t) const {
        std::uint32_t a = representative_[t[0]], b = representative_[t[1]],
                      c = representative_[t[2]];
        if (a > b) std::swap(a, b);
        if (b > c) std::swap(b, c);
        if (a > b) std::swap(a, b);
        return {a, b, c};
    }

    // A standing face has t's three corners (the fill would make a duplicate). Positions
    // count, as in `hrsr check`: the faces around every copy of t's first corner.
    bool repeats_a_face(const Triangle& t) const {
        const Triangle corners = sorted_positions(t);
        const auto repeats = [&](std::uint32_t corner) {
            return any_face(
                corner, [&](const Triangle& other) { return sorted_positions(other) == corners; });
        };
        const auto copies = copies_.find(representative_[t[0]]);
        if (copies == copies_.end()) return repeats(t[0]);
        return std::any_of(copies->second.begin(), copies->second.end(), repeats);
    }

    // A standing face holds a followed by b.
    bool has_directed_edge(std::uint32_t a, std::uint32_t b) const {
        return any_face(a, [&](const Triangle& t) {
            for (int k = 0; k < 3; ++k)
                if (t[k] == a && t[(k + 1) % 3] == b) return true;
            return false;
        });
    }

    bool has_edge(std::uint32_t a, std::uint32_t b) const {
        return any_face(
            a, [&](const Triangle& t) { return std::find(t.begin(), t.end(), b) != t.end(); });
    }

    // ----------------------------------------------------------------------------------------

    const std::size_t pinhole_edges_; ///< D-45's loops on pieces closed but for them
    const std::vector<Vec3>& positions_;
    const Execution exec_; ///< for the passes over the whole mesh
    const std::vector<Vec3>& normals_;
    std::vector<Triangle> triangles_;  ///< by vertex; faces added at the end
    const std::size_t original_faces_; ///< the faces given; later ones were added
    const std::vector<std::uint32_t>& representative_;
    /// Vertices at one position, by their representative (only where there are several).
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> copies_;
    TriangleGeometry& geometry_; ///< the same faces, welded; new ones appended
    TriangleGrid& grid_;         ///< new faces are filed again
    const VertexCorners at_;     ///< the given faces around each vertex
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> added_at_;
    std::vector<std::uint8_t> alive_;
    /// Per face, while D-55/D-56 run: of a small piece not joined yet (D-58).
    std::vector<std::uint8_t> in_small_piece_;
    bool scraps_take_points_ = true;         ///< whether those faces take other pieces' points
    std::vector<std::uint8_t> touched_;      ///< per vertex: a corner of a face cut or added
    std::vector<std::uint8_t> given_border_; ///< per vertex: on the given mesh's border (lazy)
    const std::vector<TrianglePair>& pairs_;
    std::vector<std::uint32_t> partner_start_, partner_, live_pairs_;
    FacesNearBox near_;                    ///< gather_standing()'s faces
    std::uint32_t blocker_ = kNoFace;      ///< the standing face that the last fill crossed
    std::size_t mesh_version_ = 0;         ///< changes whenever a face goes or comes
    std::vector<std::uint32_t> faces_out_; ///< taken out while fills are tested (sorted)
    /// crosses_gathered()'s answers (the face crossed, or kNoFace) for the mesh's version,
    /// by the faces out and the box the faces were gathered in (their order decides the blocker)
    std::map<std::pair<std::vector<std::uint32_t>, std::array<double, 6>>,
             std::map<Triangle, std::uint32_t>>
        crossing_memo_;
    std::size_t crossing_memo_version_ = ~std::size_t(0);
    /// crossing_memo_'s entry for the current faces out and gathered box (null: look it up)
    std::map<Triangle, std::uint32_t>* crossing_answers_ = nullptr;
    Box gathered_box_{};                     ///< of the last gather_standing()
    std::size_t reinserted_ = 0;             ///< removed vertices put back (reinsert)
    std::size_t placed_ = 0;                 ///< vertices without a face given, placed (D-37)
    std::size_t joined_border_ = 0;          ///< put back across a border edge (D-41)
    std::vector<Triangle> inner_cuts_;       ///< faces cut with no edge on the border
    std::vector<std::uint32_t> cut_corners_; ///< the corners of every face cut
    std::optional<std::vector<std::uint32_t>> retired_log_; ///< while a D-38 closing may be undone
};

} // namespace hrsr::folds
