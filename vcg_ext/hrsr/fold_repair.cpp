#include "hrsr/fold_repair.h"

#include "hrsr/split_mesh.h"
#include "mesh/self_intersections.h"
#include "mesh/triangle_intersection.h"
#include "mesh/welding.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <unordered_map>

namespace hrsr {

namespace {

using reexpand::SFace;
using reexpand::SplitMesh;

// How far from a pair's corners the region reaches: a flip joins corners up to two rings away,
// and a later round works around the corners of earlier flips.
constexpr int kRegionRings = 6;

struct Box {
    Vec3 lo, hi;
    void add(const Vec3& p) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    bool overlaps(const Box& o) const {
        for (int k = 0; k < 3; ++k)
            if (hi[k] < o.lo[k] || o.hi[k] < lo[k]) return false;
        return true;
    }
};

Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a) ^ (c - a);
    const double length = n.Norm();
    return length > 0 ? n / length : Vec3(0, 0, 0);
}

// The triangles (welded corner ids: copies at one position are one vertex, as in
// self_intersections.h) over fixed positions, with the geometric tests the repair needs.
class Geometry {
public:
    Geometry(const std::vector<Vec3>& positions, std::vector<Triangle> triangles)
        : positions_(positions), triangles_(std::move(triangles)) {}

    const Triangle& triangle(std::uint32_t f) const { return triangles_[f]; }
    void set(std::uint32_t f, const Triangle& t) { triangles_[f] = t; }
    std::size_t size() const { return triangles_.size(); }
    const Vec3& position(std::uint32_t v) const { return positions_[v]; }

    Box box(const Triangle& t) const {
        Box b{positions_[t[0]], positions_[t[0]]};
        b.add(positions_[t[1]]);
        b.add(positions_[t[2]]);
        return b;
    }
    Vec3 normal(const Triangle& t) const {
        return unit_normal(positions_[t[0]], positions_[t[1]], positions_[t[2]]);
    }
    /// Not tested, as in self_intersections.h: a repeated corner or no area.
    bool degenerate(const Triangle& t) const {
        return t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || normal(t) == Vec3(0, 0, 0);
    }
    bool intersect(const Triangle& a, const Triangle& b) const {
        return box(a).overlaps(box(b)) && intersect_exactly(a, b);
    }
    /// The same without the box test (the caller has done it).
    bool intersect_exactly(const Triangle& a, const Triangle& b) const {
        return mesh_triangles_intersect(corners(a), a, corners(b), b);
    }

private:
    Corners corners(const Triangle& t) const {
        return {positions_[t[0]], positions_[t[1]], positions_[t[2]]};
    }
    const std::vector<Vec3>& positions_;
    std::vector<Triangle> triangles_;
};

// Faces filed by the cells of a uniform grid (about the mean face size) that their box covers,
// as the faces stand when the grid is built. A face flipped later may reach other cells: the
// repair adds its flipped faces to every query.
class FaceGrid {
public:
    FaceGrid(const Geometry& g, const Execution& exec) {
        Box all{g.position(g.triangle(0)[0]), g.position(g.triangle(0)[0])};
        double extent_sum = 0;
        for (std::uint32_t f = 0; f < g.size(); ++f) {
            const Box b = g.box(g.triangle(f));
            all.add(b.lo);
            all.add(b.hi);
            const Vec3 d = b.hi - b.lo;
            extent_sum += std::max(d[0], std::max(d[1], d[2]));
        }
        origin_ = all.lo;
        const Vec3 size = all.hi - all.lo;
        const double largest = std::max(size[0], std::max(size[1], size[2]));
        // At most kMaxCellsPerAxis cells a side, so that a cell's index fits in 32 bits.
        cell_ = std::max({2.0 * extent_sum / double(g.size()), largest / kMaxCellsPerAxis, 1e-300});
        for (int k = 0; k < 3; ++k) cells_[k] = std::uint64_t(size[k] / cell_) + 1;
        for (std::uint32_t f = 0; f < g.size(); ++f) {
            if (exec.progress && f % 65536 == 0) // a chance to cancel in the serial part
                exec.progress->update(0.0);      // the search below reports the fraction
            if (!g.degenerate(g.triangle(f)))
                for_each_cell(g.box(g.triangle(f)),
                              [&](std::uint64_t c) { entries_.push_back(c << 32 | f); });
        }
        sort_by_cell(entries_);
        for (std::size_t e = 0; e < entries_.size(); ++e)
            if (e == 0 || cell(entries_[e]) != cell(entries_[e - 1]))
                cell_start_.push_back(std::uint32_t(e));
        cell_start_.push_back(std::uint32_t(entries_.size()));
    }

    /// Every intersecting pair (i < j), sorted; each pair is tested in the first cell both
    /// boxes share only, cells in parallel blocks.
    std::vector<TrianglePair> all_pairs(const Geometry& g, const Execution& exec) const {
        const std::size_t cells = cell_start_.size() - 1, block = 256;
        std::vector<std::vector<TrianglePair>> found((cells + block - 1) / block);
        parallel_for(exec, found.size(), [&](std::size_t b) {
            struct Member {
                std::uint32_t face;
                Box box;
                Cell low; ///< the cell of the box's low corner
            };
            thread_local std::vector<Member> members;
            for (std::size_t c = b * block; c < std::min(cells, (b + 1) * block); ++c) {
                const std::uint64_t here = cell(entries_[cell_start_[c]]);
                members.clear();
                for (std::size_t e = cell_start_[c]; e < cell_start_[c + 1]; ++e) {
                    const std::uint32_t f = face(entries_[e]);
                    const Box box = g.box(g.triangle(f));
                    members.push_back({f, box, cell_of(box.lo)});
                }
                for (std::size_t i = 0; i < members.size(); ++i)
                    for (std::size_t j = i + 1; j < members.size(); ++j) {
                        const Member &s = members[i], &t = members[j];
                        if (!s.box.overlaps(t.box)) continue;
                        if (index(std::max(s.low[0], t.low[0]), std::max(s.low[1], t.low[1]),
                                  std::max(s.low[2], t.low[2])) != here)
                            continue;
                        if (g.intersect(g.triangle(s.face), g.triangle(t.face)))
                            found[b].emplace_back(s.face, t.face);
                    }
            }
        });
        std::vector<TrianglePair> pairs;
        for (const auto& f : found) pairs.insert(pairs.end(), f.begin(), f.end());
        std::sort(pairs.begin(), pairs.end());
        return pairs;
    }

    /// Calls visit(cell index) for every cell `box` covers.
    template <class Visit>
    void for_each_cell(const Box& box, Visit&& visit) const {
        const Cell lo = cell_of(box.lo), hi = cell_of(box.hi);
        for (std::uint64_t x = lo[0]; x <= hi[0]; ++x)
            for (std::uint64_t y = lo[1]; y <= hi[1]; ++y)
                for (std::uint64_t z = lo[2]; z <= hi[2]; ++z) visit(index(x, y, z));
    }

    /// Faces filed in the cells `box` covers (possibly repeated).
    void query(const Box& box, std::vector<std::uint32_t>& out) const {
        for_each_cell(box, [&](std::uint64_t c) {
            auto it = std::lower_bound(entries_.begin(), entries_.end(), c << 32);
            for (; it != entries_.end() && cell(*it) == c; ++it) out.push_back(face(*it));
        });
    }

private:
    static constexpr double kMaxCellsPerAxis = 1600; // 1601³ < 2³²

    // Entries come in face order; a stable radix sort on the cell (4 × 8 bits) leaves them
    // sorted by (cell, face) as std::sort would, in a fraction of its time.
    static void sort_by_cell(std::vector<std::uint64_t>& entries) {
        std::vector<std::uint64_t> buffer(entries.size());
        for (int shift = 32; shift < 64; shift += 8) {
            std::array<std::size_t, 257> start{};
            for (std::uint64_t e : entries) ++start[((e >> shift) & 0xff) + 1];
            for (int d = 0; d < 256; ++d) start[std::size_t(d) + 1] += start[std::size_t(d)];
            for (std::uint64_t e : entries) buffer[start[(e >> shift) & 0xff]++] = e;
            entries.swap(buffer);
        }
    }
    using Cell = std::array<std::uint64_t, 3>;
    static std::uint64_t cell(std::uint64_t entry) { return entry >> 32; }
    static std::uint32_t face(std::uint64_t entry) { return std::uint32_t(entry); }
    Cell cell_of(const Vec3& p) const {
        Cell c;
        for (int k = 0; k < 3; ++k)
            c[k] = std::min(cells_[k] - 1,
                            std::uint64_t(std::max(0.0, std::floor((p[k] - origin_[k]) / cell_))));
        return c;
    }
    std::uint64_t index(std::uint64_t x, std::uint64_t y, std::uint64_t z) const {
        return x + cells_[0] * (y + cells_[1] * z);
    }
    Vec3 origin_;
    double cell_ = 1;
    std::array<std::uint64_t, 3> cells_{1, 1, 1};
    std::vector<std::uint64_t> entries_; ///< cell << 32 | face, sorted
    std::vector<std::uint32_t> cell_start_;
};

// The part of the mesh the flips may touch: the faces around every vertex within `rings`
// rings of the pairs' corners, as a SplitMesh of its own (a whole-mesh one costs more than the
// search). Those vertices are complete: all their faces are in the region, so what can_flip
// and star see around them is the whole mesh's; flips are made only among complete vertices.
class Region {
public:
    Region(const std::vector<Vec3>& positions, const std::vector<Triangle>& triangles,
           const std::vector<TrianglePair>& pairs, int rings) {
        const std::size_t n = positions.size();
        // Vertex → faces.
        std::vector<std::uint32_t> start(n + 1, 0);
        for (const Triangle& t : triangles)
            for (std::uint32_t v : t) ++start[v + 1];
        for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
        std::vector<std::uint32_t> faces(start.back()), cursor(start.begin(), start.end() - 1);
        for (std::uint32_t f = 0; f < triangles.size(); ++f)
            for (std::uint32_t v : triangles[f]) faces[cursor[v]++] = f;
        // Rings around the pairs' corners, breadth first.
        constexpr std::uint8_t kFar = 0xff;
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
            for (std::uint32_t e = start[v]; e < start[v + 1]; ++e)
                for (std::uint32_t w : triangles[faces[e]])
                    if (depth[w] == kFar) {
                        depth[w] = std::uint8_t(depth[v] + 1);
                        reached.push_back(w);
                    }
        }
        for (std::uint32_t v : reached)
            for (std::uint32_t e = start[v]; e < start[v + 1]; ++e)
                global_face_.push_back(faces[e]);
        std::sort(global_face_.begin(), global_face_.end());
        global_face_.erase(std::unique(global_face_.begin(), global_face_.end()),
                           global_face_.end());
        // Local vertices in order of first use, then the SplitMesh.
        std::vector<std::uint32_t> local(n, kNone);
        std::vector<Vec3> local_positions;
        std::vector<Triangle> local_triangles;
        for (std::uint32_t f : global_face_) {
            Triangle t;
            for (int k = 0; k < 3; ++k) {
                std::uint32_t& l = local[triangles[f][std::size_t(k)]];
                if (l == kNone) {
                    l = std::uint32_t(global_vertex_.size());
                    global_vertex_.push_back(triangles[f][std::size_t(k)]);
                    local_positions.push_back(positions[global_vertex_.back()]);
                    complete_.push_back(depth[global_vertex_.back()] != kFar);
                }
                t[std::size_t(k)] = l;
            }
            local_triangles.push_back(t);
        }
        mesh_ = std::make_unique<SplitMesh>(local_positions, local_triangles,
                                            local_positions.size(), local_triangles.size());
        const std::vector<SFace*> live = mesh_->live_faces(); // in local_triangles' order
        face_.assign(triangles.size(), nullptr);
        slot_face_.assign(mesh_->face_slots(), kNone);
        for (std::size_t i = 0; i < live.size(); ++i) {
            face_[global_face_[i]] = live[i];
            slot_face_[mesh_->slot(live[i])] = global_face_[i];
        }
    }

    SplitMesh& mesh() { return *mesh_; }
    /// The region's face for a face of the mesh, or null when it is outside.
    SFace* face(std::uint32_t global) const { return face_[global]; }
    std::uint32_t global_face(const SFace* f) const { return slot_face_[mesh_->slot(f)]; }
    std::uint32_t global_vertex(const SFace* f, int k) const {
        return global_vertex_[mesh_->vertex_of(f, k)];
    }
    bool complete(const SFace* f, int k) const { return complete_[mesh_->vertex_of(f, k)]; }
    std::size_t faces() const { return global_face_.size(); }

    /// Writes the region's triangles back into the mesh's list.
    void write_back(std::vector<Triangle>& triangles) const {
        for (std::uint32_t f : global_face_)
            triangles[f] = {global_vertex(face_[f], 0), global_vertex(face_[f], 1),
                            global_vertex(face_[f], 2)};
    }

private:
    static constexpr std::uint32_t kNone = ~0u;
    std::vector<std::uint32_t> global_face_, global_vertex_, slot_face_;
    std::vector<bool> complete_;
    std::vector<SFace*> face_;
    std::unique_ptr<SplitMesh> mesh_;
};

class Repair {
public:
    // `geometry` holds the mesh's triangles (welded by `representative`) in face order.
    Repair(Region& region, const std::vector<std::uint32_t>& representative, Geometry& geometry,
           const FaceGrid& grid)
        : region_(region), mesh_(region.mesh()), representative_(representative),
          geometry_(geometry), grid_(grid), seen_in_search_(geometry.size(), 0) {}

    // From the pairs found by the grid: flips, round by round; `stats` gets the flips, the
    // rounds and the pairs left.
    void run(std::vector<TrianglePair> pairs, int rounds, FoldRepairStats& stats) {
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
    const std::vector<std::uint32_t>& near(const Box& box, std::uint32_t skip_a,
                                           std::uint32_t skip_b) {
        near_.clear();
        grid_.query(box, near_);
        grid_.for_each_cell(box, [&](std::uint64_t c) {
            const auto it = flipped_in_cell_.find(c);
            if (it != flipped_in_cell_.end())
                near_.insert(near_.end(), it->second.begin(), it->second.end());
        });
        // Each face once (it is filed in several cells), marked with this search's number.
        ++search_;
        std::size_t unique = 0;
        for (std::uint32_t c : near_)
            if (seen_in_search_[c] != search_) {
                seen_in_search_[c] = search_;
                near_[unique++] = c;
            }
        near_.resize(unique);
        // Kept with their boxes: each is tested against four triangles.
        std::size_t kept = 0;
        near_box_.resize(near_.size());
        for (std::uint32_t c : near_) {
            const Box b = geometry_.box(geometry_.triangle(c));
            if (c == skip_a || c == skip_b || !box.overlaps(b)) continue;
            near_box_[kept] = b;
            near_[kept++] = c;
        }
        near_.resize(kept);
        near_box_.resize(kept);
        return near_;
    }

    // Intersections of `t` with the faces of the last near() search.
    std::size_t intersections_near(const Triangle& t) const {
        const Box box = geometry_.box(t);
        std::size_t count = 0;
        for (std::size_t i = 0; i < near_.size(); ++i)
            if (box.overlaps(near_box_[i]) &&
                geometry_.intersect_exactly(t, geometry_.triangle(near_[i])))
                ++count;
        return count;
    }

    // The two faces of the pair, then the other faces around their corners (in face order):
    // the flips that can undo a fold are among their edges.
    const std::vector<std::uint32_t>& faces_around(const TrianglePair& p) {
        around_.clear();
        for (std::uint32_t f : {p.first, p.second}) {
            const SFace* face = region_.face(f);
            for (int k = 0; face && k < 3; ++k) {
                if (!region_.complete(face, k)) continue;
                mesh_.star(mesh_.vertex_of(face, k), star_);
                for (const SFace* w : star_.wedges)
                    if (w) around_.push_back(region_.global_face(w));
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

    // Flips the first edge of face f whose flip lowers the intersections of its two faces;
    // returns the other face of that edge, or kNoFace. Faces flipped this round stay as they are.
    std::uint32_t try_flips(std::uint32_t f, const std::vector<std::uint8_t>& waiting) {
        SFace* face = region_.face(f);
        if (!face) return kNoFace;
        for (int z = 0; z < 3; ++z) {
            SFace* across = face->FFp(z);
            if (across == face) continue; // a border edge
            const std::uint32_t g = region_.global_face(across);
            // A flip can only lower the count of faces that intersect something.
            if (waiting[g] || (!intersecting_[f] && !intersecting_[g])) continue;
            // can_flip needs the whole neighbourhood of the edge's endpoints and of the corners
            // the new edge joins.
            if (!region_.complete(face, 0) || !region_.complete(face, 1) ||
                !region_.complete(face, 2) || !region_.complete(across, (face->FFi(z) + 2) % 3) ||
                !mesh_.can_flip(face, z))
                continue;
            // f = (u, w, x) holds the edge as u→w; the face across holds w→u and y.
            const Triangle tf = geometry_.triangle(f), tg = geometry_.triangle(g);
            const std::uint32_t u = tf[z], w = tf[(z + 1) % 3], x = tf[(z + 2) % 3];
            const std::uint32_t y =
                representative_[region_.global_vertex(across, (face->FFi(z) + 2) % 3)];
            const Triangle nf{x, u, y}, ng{y, w, x}; // the flipped pair, wound the same way
            if (geometry_.degenerate(nf) || geometry_.degenerate(ng)) continue;
            const double old_fold = geometry_.normal(tf).dot(geometry_.normal(tg));
            if (geometry_.normal(nf).dot(geometry_.normal(ng)) < std::min(old_fold, 0.0)) continue;
            Box quad = geometry_.box(tf);
            quad.add(geometry_.position(y));
            near(quad, f, g);
            const std::size_t before = intersections_near(tf) + intersections_near(tg);
            const std::size_t after = intersections_near(nf) + intersections_near(ng);
            if (after >= before) continue;
            mesh_.flip(face, z);
            // vcglib's FlipEdge rewrites both faces; read their corners back.
            for (std::uint32_t h : {f, g}) {
                const SFace* s = region_.face(h);
                geometry_.set(h, {representative_[region_.global_vertex(s, 0)],
                                  representative_[region_.global_vertex(s, 1)],
                                  representative_[region_.global_vertex(s, 2)]});
                // Filed again under its new cells (the old entries are filtered by box).
                grid_.for_each_cell(geometry_.box(geometry_.triangle(h)),
                                    [&](std::uint64_t c) { flipped_in_cell_[c].push_back(h); });
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
            near(geometry_.box(t), f, kNoFace); // every face there overlaps t's box
            for (std::uint32_t o : near_)
                if (geometry_.intersect_exactly(t, geometry_.triangle(o)))
                    next.emplace_back(std::min(f, o), std::max(f, o));
        }
        std::sort(next.begin(), next.end());
        next.erase(std::unique(next.begin(), next.end()), next.end());
        return next;
    }

    Region& region_;
    SplitMesh& mesh_;
    const std::vector<std::uint32_t>& representative_;
    Geometry& geometry_;
    const FaceGrid& grid_;
    std::vector<std::uint32_t> near_, around_;
    std::vector<Box> near_box_;                 ///< the boxes of near_
    std::vector<std::uint32_t> seen_in_search_; ///< per face: the last search that listed it
    std::uint32_t search_ = 0;
    std::vector<std::uint8_t> intersecting_; ///< per face: in a pair at the start of the round
    /// Flipped faces by the cells their boxes covered after each flip.
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> flipped_in_cell_;
    reexpand::Star star_;
};

} // namespace

FoldRepairStats repair_folds(const std::vector<Vec3>& positions, std::vector<Triangle>& triangles,
                             int rounds, const Execution& exec) {
    if (triangles.size() < 2 || rounds <= 0) return {};
    const std::vector<std::uint32_t> representative = same_position_representatives(positions);
    Geometry geometry(positions, welded_triangles(triangles, representative));
    const FaceGrid grid(geometry, exec);
    FoldRepairStats stats;
    std::vector<TrianglePair> pairs = grid.all_pairs(geometry, exec);
    stats.pairs_before = stats.pairs_after = pairs.size();
    if (pairs.empty()) return stats;
    Region region(positions, triangles, pairs, kRegionRings);
    Repair(region, representative, geometry, grid).run(std::move(pairs), rounds, stats);
    if (stats.flips > 0) region.write_back(triangles); // flips keep every face in its slot
    return stats;
}

} // namespace hrsr
