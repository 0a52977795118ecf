#include "mesh/fold_repair.h"

#include "index_types.h"
#include "mesh/split_mesh.h"
#include "mesh/triangle_against_faces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

namespace hrsr {

namespace {

// How far from a pair's corners the region reaches: a flip joins corners up to two rings away,
// and a later round works around the corners of earlier flips.
constexpr int kRegionRings = 6;

// The region's own spaces: its SplitMesh's vertices, and the slots of its face storage. The
// mesh's vertices and faces are VertexIndex and FaceIndex; the flip search inside the region
// (Repair) keeps plain face numbers of the mesh.
using RegionVertex = Index<struct RegionVertexTag>;
using FaceSlot = Index<struct FaceSlotTag>;

// The part of the mesh the flips may touch: the faces around every vertex within `rings`
// rings of the pairs' corners, as a SplitMesh of its own (a whole-mesh one costs more than the
// search). Those vertices are complete: all their faces are in the region, so what can_flip
// and star see around them is the whole mesh's; flips are made only among complete vertices.
class Region {
public:
    Region(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
           const std::vector<TrianglePair>& pairs, int rings, const Execution& exec) {
        const std::size_t n = positions.size();
        const VertexCorners at = corners_by_vertex(n, triangles, exec);
        // Rings around the pairs' corners, breadth first.
        std::vector<std::uint8_t> depth(n, kFar);
        std::vector<std::uint32_t> reached;
        for (const TrianglePair& p : pairs)
            for (std::uint32_t f : {p.first, p.second})
                for (std::uint32_t v : triangles[f])
                    if (depth[v] == kFar) {
                        depth[v] = 0;
                        reached.push_back(v);
                    }
        for (std::size_t i = 0; i < reached.size(); ++i) {
            const std::uint32_t v = reached[i];
            if (depth[v] >= rings) continue;
            for (std::uint32_t e = at.begin(v); e < at.end(v); ++e)
                for (std::uint32_t w : triangles[at.corner[e] / 3])
                    if (depth[w] == kFar) {
                        depth[w] = std::uint8_t(depth[v] + 1);
                        reached.push_back(w);
                    }
        }
        for (std::uint32_t v : reached)
            for (std::uint32_t e = at.begin(v); e < at.end(v); ++e)
                global_face_.push_back(FaceIndex(at.corner[e] / 3));
        std::sort(global_face_.begin(), global_face_.end());
        global_face_.erase(std::unique(global_face_.begin(), global_face_.end()),
                           global_face_.end());
        build_mesh(positions, triangles, depth);
    }

    SplitMesh& mesh() { return *mesh_; }
    /// The region's face for a face of the mesh, or null when it is outside.
    SFace* face(FaceIndex global) const { return face_[global]; }
    FaceIndex global_face(const SFace* f) const {
        return slot_face_[FaceSlot(std::uint32_t(mesh_->slot(f)))];
    }
    VertexIndex global_vertex(const SFace* f, int k) const { return global_vertex_[vertex(f, k)]; }
    bool complete(const SFace* f, int k) const { return complete_[vertex(f, k)] != 0; }
    std::size_t faces() const { return global_face_.size(); }

    /// Writes the region's triangles back into the mesh's list.
    void write_back(std::vector<Triangle>& triangles) const {
        for (FaceIndex f : global_face_)
            triangles[f.value()] = {global_vertex(face_[f], 0).value(),
                                    global_vertex(face_[f], 1).value(),
                                    global_vertex(face_[f], 2).value()};
    }

private:
    static constexpr std::uint8_t kFar = 0xff; ///< depth of a vertex the rings do not reach

    RegionVertex vertex(const SFace* f, int k) const {
        return RegionVertex(mesh_->vertex_of(f, k));
    }

    // The region's faces over its own vertices (in order of first use) as a SplitMesh, and the
    // maps between its faces and the mesh's.
    void build_mesh(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
                    const std::vector<std::uint8_t>& depth) {
        const RegionVertex none(~0u);
        IndexVector<VertexIndex, RegionVertex> local(positions.size(), none);
        std::vector<Vec3> local_positions;
        std::vector<Triangle> local_triangles;
        for (FaceIndex f : global_face_) {
            Triangle t;
            for (std::size_t k = 0; k < 3; ++k) {
                const VertexIndex v(triangles[f.value()][k]);
                if (local[v] == none) {
                    local[v] = global_vertex_.next_key();
                    global_vertex_.push_back(v);
                    local_positions.push_back(positions[v.value()]);
                    complete_.push_back(std::uint8_t(depth[v.value()] != kFar));
                }
                t[k] = local[v].value();
            }
            local_triangles.push_back(t);
        }
        mesh_ = std::make_unique<SplitMesh>(local_positions, local_triangles,
                                            local_positions.size(), local_triangles.size());
        const std::vector<SFace*> live = mesh_->live_faces(); // in local_triangles' order
        face_ = IndexVector<FaceIndex, SFace*>(triangles.size(), nullptr);
        slot_face_ = IndexVector<FaceSlot, FaceIndex>(mesh_->face_slots(), FaceIndex(~0u));
        for (std::size_t i = 0; i < live.size(); ++i) {
            face_[global_face_[i]] = live[i];
            slot_face_[FaceSlot(std::uint32_t(mesh_->slot(live[i])))] = global_face_[i];
        }
    }

    std::vector<FaceIndex> global_face_; ///< the region's faces, increasing
    IndexVector<RegionVertex, VertexIndex> global_vertex_;
    IndexVector<RegionVertex, std::uint8_t> complete_; ///< all its faces are in the region
    IndexVector<FaceSlot, FaceIndex> slot_face_;
    IndexVector<FaceIndex, SFace*> face_;
    std::unique_ptr<SplitMesh> mesh_;
};

class Repair {
public:
    // `geometry` holds the mesh's triangles (welded by `representative`) in face order.
    Repair(Region& region, const std::vector<std::uint32_t>& representative,
           TriangleGeometry& geometry, TriangleGrid& grid)
        : region_(region), mesh_(region.mesh()), representative_(representative),
          geometry_(geometry), grid_(grid), count_(geometry.size(), 0),
          counted_at_(geometry.size(), 0) {}

    // From the pairs found by the grid: flips, round by round; `pairs` ends as the pairs left,
    // `stats` gets the flips, the rounds and their number.
    void run(std::vector<TrianglePair>& pairs, int rounds, FoldRepairStats& stats) {
        // A pair that found no flip is tried again only once a face around it has changed.
        std::vector<int> flipped_in_round(geometry_.size(), -1);
        // A flip changes only faces that held its four corners, so a change around a pair shows
        // among the faces that were around it when it settled.
        struct Settled {
            int round;                         ///< it found no flip in this round
            std::vector<std::uint32_t> around; ///< the faces around it then
        };
        std::map<TrianglePair, Settled> settled;
        for (int round = 0; round < rounds && !pairs.empty(); ++round) {
            std::vector<std::uint32_t> changed;
            std::vector<std::uint8_t> waiting(geometry_.size(), 0);
            intersecting_.assign(geometry_.size(), 0);
            for (const TrianglePair& p : pairs)
                intersecting_[p.first] = intersecting_[p.second] = 1;
            for (const TrianglePair& p : pairs) {
                if (waiting[p.first] || waiting[p.second]) continue;
                const auto was = settled.find(p);
                if (was != settled.end() &&
                    std::none_of(
                        was->second.around.begin(), was->second.around.end(),
                        [&](std::uint32_t f) { return flipped_in_round[f] >= was->second.round; }))
                    continue;
                const std::vector<std::uint32_t>& around = faces_around(p);
                bool flipped = false;
                for (std::uint32_t f : around) {
                    if (waiting[f]) continue;
                    const std::uint32_t g = try_flips(f, waiting);
                    if (g == kNoFace) continue;
                    waiting[f] = waiting[g] = 1;
                    flipped_in_round[f] = flipped_in_round[g] = round;
                    changed.push_back(f);
                    changed.push_back(g);
                    ++stats.flips;
                    flipped = true;
                    break;
                }
                if (!flipped) settled[p] = {round, around};
            }
            if (changed.empty()) break;
            ++stats.rounds;
            pairs = retest(pairs, changed);
        }
        stats.pairs_after = pairs.size();
    }

private:
    static constexpr std::uint32_t kNoFace = ~0u;

    // Faces other than `skip_a`, `skip_b` whose box overlaps `box`: from the grid, plus the
    // faces flipped so far, filed again after each flip (they may have left the cells the grid
    // has them in). None is degenerate: the grid leaves those out and no flip makes one.
    const FacesNearBox::Found& near(const Box& box, std::uint32_t skip_a, std::uint32_t skip_b) {
        return near_.gather(grid_, geometry_, box,
                            [&](std::uint32_t f) { return f != skip_a && f != skip_b; });
    }

    // Intersections of `t` with the faces of the last near() search (none for a degenerate t,
    // which the pair test does not take, as `hrsr check` skips it), counted up to `limit`.
    // Faces `skip_a` and `skip_b` are not counted.
    std::size_t intersections_near(const Triangle& t, std::uint32_t skip_a, std::uint32_t skip_b,
                                   std::size_t limit) const {
        if (geometry_.degenerate(t)) return 0;
        const Box box = geometry_.box(t);
        const TriangleAgainstFaces against(geometry_, t);
        std::size_t count = 0;
        for (const auto& [f, f_box] : near_.found()) {
            if (count >= limit) break;
            if (f != skip_a && f != skip_b && box.overlaps(f_box) &&
                against.intersects(geometry_.triangle(f)))
                ++count;
        }
        return count;
    }

    // The two faces of the pair, then the other faces around their corners (in face order):
    // the flips that can undo a fold are among their edges.
    const std::vector<std::uint32_t>& faces_around(const TrianglePair& p) {
        around_.clear();
        for (std::uint32_t f : {p.first, p.second}) {
            const SFace* face = region_.face(FaceIndex(f));
            for (int k = 0; face && k < 3; ++k) {
                if (!region_.complete(face, k)) continue;
                mesh_.star(mesh_.vertex_of(face, k), star_);
                for (const SFace* w : star_.wedges)
                    if (w) around_.push_back(region_.global_face(w).value());
            }
        }
        std::sort(around_.begin(), around_.end());
        around_.erase(std::unique(around_.begin(), around_.end()), around_.end());
        around_.erase(
            std::remove_if(around_.begin(), around_.end(),
                           [&](std::uint32_t f) { return f == p.first || f == p.second; }),
            around_.end());
        around_.insert(around_.begin(), {p.first, p.second});
        return around_;
    }

    // How many faces intersect face h, from the last near() search (which must hold every face
    // near h); remembered until the next flip, since most candidates share their faces.
    std::size_t intersections_of(std::uint32_t h) {
        if (counted_at_[h] != flips_made_ + 1) {
            count_[h] = std::uint32_t(intersections_near(geometry_.triangle(h), h, kNoFace,
                                                         std::numeric_limits<std::size_t>::max()));
            counted_at_[h] = flips_made_ + 1;
        }
        return count_[h];
    }

    // The box of f and the corners across its edges: every quad a flip of f's edges replaces.
    Box quads_box(SFace* face) const {
        Box box{geometry_.position(representative_[region_.global_vertex(face, 0)].value()),
                geometry_.position(representative_[region_.global_vertex(face, 0)].value())};
        for (int z = 0; z < 3; ++z) {
            box.add(geometry_.position(representative_[region_.global_vertex(face, z)].value()));
            const SFace* across = face->FFp(z);
            if (across != face)
                box.add(geometry_.position(
                    representative_[region_.global_vertex(across, (face->FFi(z) + 2) % 3)]
                        .value()));
        }
        return box;
    }

    // Flips the first edge of face f whose flip lowers the intersections of its two faces;
    // returns the other face of that edge, or kNoFace. Faces flipped this round stay as they are.
    std::uint32_t try_flips(std::uint32_t f, const std::vector<std::uint8_t>& waiting) {
        SFace* face = region_.face(FaceIndex(f));
        if (!face) return kNoFace;
        bool searched = false; // near() once for the three edges' quads
        for (int z = 0; z < 3; ++z) {
            SFace* across = face->FFp(z);
            if (across == face) continue; // a border edge
            const std::uint32_t g = region_.global_face(across).value();
            // A flip can only lower the count of faces that intersect something.
            if (waiting[g] || (!intersecting_[f] && !intersecting_[g])) continue;
            // can_flip needs the whole neighbourhood of the edge's endpoints and of the corners
            // the new edge joins.
            if (!region_.complete(face, 0) || !region_.complete(face, 1) ||
                !region_.complete(face, 2) || !region_.complete(across, (face->FFi(z) + 2) % 3))
                continue;
            // f = (u, w, x) holds the edge as u→w; the face across holds w→u and y.
            const Triangle tf = geometry_.triangle(f), tg = geometry_.triangle(g);
            const std::uint32_t u = tf[z], w = tf[(z + 1) % 3], x = tf[(z + 2) % 3];
            const std::uint32_t y =
                representative_[region_.global_vertex(across, (face->FFi(z) + 2) % 3)].value();
            const Triangle nf{x, u, y}, ng{y, w, x}; // the flipped pair, wound the same way
            // The geometric tests before the topological walks of can_flip.
            const double old_fold = geometry_.normal(tf).dot(geometry_.normal(tg));
            if (geometry_.normal(nf).dot(geometry_.normal(ng)) < std::min(old_fold, 0.0) ||
                geometry_.degenerate(nf) || geometry_.degenerate(ng) || !mesh_.can_flip(face, z))
                continue;
            if (!searched) {
                near(quads_box(face), kNoFace, kNoFace);
                searched = true;
            }
            // Neither face counts the other (they share the edge; they meet only folded flat).
            const std::size_t each_other = geometry_.intersect_unboxed(tf, tg) ? 2 : 0;
            const std::size_t before = intersections_of(f) + intersections_of(g) - each_other;
            // Counted only as far as it matters: most candidates do not lower the count.
            const std::size_t after_nf = intersections_near(nf, f, g, before);
            if (after_nf >= before ||
                after_nf + intersections_near(ng, f, g, before - after_nf) >= before)
                continue;
            mesh_.flip(face, z);
            ++flips_made_;
            // vcglib's FlipEdge rewrites both faces; read their corners back.
            for (std::uint32_t h : {f, g}) {
                const SFace* s = region_.face(FaceIndex(h));
                geometry_.set(h, {representative_[region_.global_vertex(s, 0)].value(),
                                  representative_[region_.global_vertex(s, 1)].value(),
                                  representative_[region_.global_vertex(s, 2)].value()});
                // Filed again under its new cells (the old entries are filtered by box).
                grid_.file_again(geometry_.box(geometry_.triangle(h)), h);
            }
            return g;
        }
        return kNoFace;
    }

    // The pairs after a round: those without a changed face stay; the changed faces are
    // tested again against every face near them.
    std::vector<TrianglePair> retest(const std::vector<TrianglePair>& pairs,
                                     const std::vector<std::uint32_t>& changed) {
        std::vector<std::uint8_t> is_changed(geometry_.size(), 0);
        for (std::uint32_t f : changed) is_changed[f] = 1;
        std::vector<TrianglePair> next;
        for (const TrianglePair& p : pairs)
            if (!is_changed[p.first] && !is_changed[p.second]) next.push_back(p);
        for (std::uint32_t f : changed) {
            const Triangle& t = geometry_.triangle(f);
            if (geometry_.degenerate(t)) continue;
            // Every face listed overlaps t's box.
            const TriangleAgainstFaces against(geometry_, t);
            for (const auto& [o, o_box] : near(geometry_.box(t), f, kNoFace))
                if (against.intersects(geometry_.triangle(o)))
                    next.emplace_back(std::min(f, o), std::max(f, o));
        }
        std::sort(next.begin(), next.end());
        next.erase(std::unique(next.begin(), next.end()), next.end());
        return next;
    }

    Region& region_;
    SplitMesh& mesh_;
    const IndexView<VertexIndex, VertexIndex> representative_; ///< welded ids
    TriangleGeometry& geometry_;
    TriangleGrid& grid_; ///< flipped faces are filed again
    FacesNearBox near_;
    std::vector<std::uint32_t> around_;
    std::vector<std::uint8_t> intersecting_; ///< per face: in a pair at the start of the round
    /// intersections_of()'s counts, valid where counted_at_ is flips_made_ + 1.
    std::vector<std::uint32_t> count_, counted_at_;
    std::uint32_t flips_made_ = 0;
    Star star_;
};

} // namespace

FoldRepairStats repair_folds(FoldSearch& search, std::vector<Triangle>& triangles, int rounds) {
    FoldRepairStats stats;
    stats.pairs_before = stats.pairs_after = search.pairs.size();
    if (search.pairs.empty() || rounds <= 0) return stats;
    Region region(search.positions, triangles, search.pairs, kRegionRings, search.exec);
    Repair(region, search.representative, search.geometry, search.grid)
        .run(search.pairs, rounds, stats);
    if (stats.flips > 0) region.write_back(triangles); // flips keep every face in its slot
    return stats;
}

FoldRepairStats repair_folds(const std::vector<Vec3>& positions, std::vector<Triangle>& triangles,
                             int rounds, const Execution& exec) {
    if (triangles.size() < 2 || rounds <= 0) return {};
    FoldSearch search(positions, triangles, exec);
    return repair_folds(search, triangles, rounds);
}

} // namespace hrsr
