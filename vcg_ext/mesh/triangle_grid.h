// Triangles over fixed positions in a uniform grid: the intersecting pairs of a mesh (hrsr check)
// and the faces near a place (the fold repair, D-26).
#pragma once

#include "mesh/triangle_intersection.h"
#include "mesh/triangle_mesh.h"
#include "parallel.h"
#include "point_set.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace hrsr {

using TrianglePair = std::pair<std::uint32_t, std::uint32_t>;

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

inline Vec3 unit_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 n = (b - a) ^ (c - a);
    const double length = n.Norm();
    return length > 0 ? n / length : Vec3(0, 0, 0);
}

/// Triangles over fixed positions, with the tests the grid and the fold repair need. Corner ids
/// decide which corners two triangles share (weld copies at one position first for
/// self_intersecting_pairs(), or not for intersecting_pairs_by_index()).
class TriangleGeometry {
public:
    TriangleGeometry(const std::vector<Vec3>& positions, std::vector<Triangle> triangles)
        : positions_(positions), triangles_(std::move(triangles)) {}

    const Triangle& triangle(std::uint32_t f) const { return triangles_[f]; }
    void set(std::uint32_t f, const Triangle& t) { triangles_[f] = t; }
    /// Appends a face; returns its number.
    std::uint32_t add(const Triangle& t) {
        triangles_.push_back(t);
        return std::uint32_t(triangles_.size() - 1);
    }
    std::size_t size() const { return triangles_.size(); }
    const std::vector<Triangle>& triangles() const { return triangles_; }
    std::size_t vertex_count() const { return positions_.size(); }
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
    /// Not tested, as in self_intersections.h: corners exactly on one line (a repeated corner
    /// included).
    bool degenerate(const Triangle& t) const {
        return t[0] == t[1] || t[1] == t[2] || t[2] == t[0] ||
               collinear_corners(positions_[t[0]], positions_[t[1]], positions_[t[2]]);
    }
    bool intersect(const Triangle& a, const Triangle& b) const {
        return box(a).overlaps(box(b)) && intersect_unboxed(a, b);
    }
    /// The same without the box test (the caller has done it).
    bool intersect_unboxed(const Triangle& a, const Triangle& b) const {
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
// as the faces stand when the grid is built. A face flipped or added later may reach other
// cells: the fold repair and removal file it again.
class TriangleGrid {
public:
    /// Files every non-degenerate triangle of `g` (at least one triangle); in parallel, the same
    /// grid for any thread count.
    TriangleGrid(const TriangleGeometry& g, const Execution& exec);

    /// Every intersecting pair (i < j), sorted; each pair is tested in the first cell both
    /// boxes share only, cells in parallel blocks. Pairs that share a vertex flagged in
    /// `embedded_fan` (embedded_fans.h, for `g` as it stands; empty: none) are not tested: they
    /// do not intersect.
    std::vector<TrianglePair> all_pairs(const TriangleGeometry& g,
                                        const std::vector<std::uint8_t>& embedded_fan,
                                        const Execution& exec) const;
    /// The same, with the fans of `g` found first.
    std::vector<TrianglePair> all_pairs(const TriangleGeometry& g, const Execution& exec) const;

    /// Calls visit(cell index) for every cell `box` covers.
    template <class Visit>
    void for_each_cell(const Box& box, Visit&& visit) const {
        const Cell lo = cell_of(box.lo), hi = cell_of(box.hi);
        for (std::uint64_t x = lo[0]; x <= hi[0]; ++x)
            for (std::uint64_t y = lo[1]; y <= hi[1]; ++y)
                for (std::uint64_t z = lo[2]; z <= hi[2]; ++z) visit(index(x, y, z));
    }

    /// A cell's side: about twice the mean extent of a face.
    double cell_size() const { return cell_; }

    /// Faces filed in the cells `box` covers (possibly repeated), those filed again included.
    void query(const Box& box, std::vector<std::uint32_t>& out) const {
        for_each_cell(box, [&](std::uint64_t c) {
            auto it = std::lower_bound(entries_.begin(), entries_.end(), c << 32);
            for (; it != entries_.end() && cell(*it) == c; ++it) out.push_back(face(*it));
            const auto late = late_.find(c);
            if (late != late_.end())
                out.insert(out.end(), late->second.begin(), late->second.end());
        });
    }

    /// Files face f (changed or added after the grid was built) under the cells `box` covers;
    /// entries it had stay (callers test the boxes of what query() lists).
    void file_again(const Box& box, std::uint32_t f) {
        for_each_cell(box, [&](std::uint64_t c) { late_[c].push_back(f); });
    }

private:
    static constexpr double kMaxCellsPerAxis = 1600; // 1601³ < 2³²

    /// The origin, the cell size and the number of cells a side.
    void size_cells(const TriangleGeometry& g, const Execution& exec);
    /// entries_, in face order.
    void file_faces(const TriangleGeometry& g, const Execution& exec);
    static void sort_by_cell(std::vector<std::uint64_t>& entries, const Execution& exec);
    using Cell = std::array<std::uint64_t, 3>;
    /// The faces filed in one cell, their boxes by coordinate (all_pairs' box tests run over
    /// them without a branch).
    struct CellMembers {
        std::vector<std::uint32_t> face;
        std::vector<Cell> corner_cell; ///< the cell of each box's low corner
        std::array<std::vector<double>, 3> lo, hi;
        std::vector<std::uint32_t> candidates;

        void clear();
        void add(std::uint32_t f, const Box& box, const Cell& cell_of_lo);
        /// Calls visit(s, t) for every pair of members whose boxes overlap (Box::overlaps),
        /// once.
        template <class Visit>
        void for_each_overlapping_pair(Visit&& visit) {
            const std::size_t m = face.size();
            candidates.resize(m);
            if (m > kAllPairsMembers) {
                sweep_overlapping_pairs(visit);
                return;
            }
            for (std::size_t s = 0; s < m; ++s) {
                // Most pairs of a cell do not overlap, unpredictably: the tests are computed for
                // every t and the overlapping ones listed without a branch.
                std::size_t count = 0;
                for (std::size_t t = s + 1; t < m; ++t) {
                    candidates[count] = std::uint32_t(t);
                    count += overlap(s, t);
                }
                for (std::size_t c = 0; c < count; ++c) visit(s, candidates[c]);
            }
        }

    private:
        /// Above this many members a cell's pairs are swept along x instead (a dense part of
        /// a mesh puts many more faces than the mean in a cell).
        static constexpr std::size_t kAllPairsMembers = 48;
        bool overlap(std::size_t s, std::size_t t) const {
            // int: all six compared (no branch); Box::overlaps for finite coordinates
            return (int(lo[0][t] <= hi[0][s]) & int(lo[0][s] <= hi[0][t]) &
                    int(lo[1][t] <= hi[1][s]) & int(lo[1][s] <= hi[1][t]) &
                    int(lo[2][t] <= hi[2][s]) & int(lo[2][s] <= hi[2][t])) != 0;
        }
        /// The members by the low x of their boxes: one meets only those whose x range starts
        /// before its own ends.
        template <class Visit>
        void sweep_overlapping_pairs(Visit&& visit) {
            const std::size_t m = face.size();
            for (std::size_t s = 0; s < m; ++s) candidates[s] = std::uint32_t(s);
            std::sort(candidates.begin(), candidates.end(), [&](std::uint32_t s, std::uint32_t t) {
                return lo[0][s] < lo[0][t] || (lo[0][s] == lo[0][t] && s < t);
            });
            for (std::size_t i = 0; i < m; ++i)
                for (std::size_t j = i + 1; j < m; ++j) {
                    const std::uint32_t s = candidates[i], t = candidates[j];
                    if (lo[0][t] > hi[0][s]) break;
                    if (overlap(s, t)) visit(s, t);
                }
        }
    };
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
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> late_; ///< file_again()
};

/// The faces a grid files near a box, each once and with its box: the neighbourhood search of
/// the fold repair (D-26) and the fold removal (D-32). A face filed in several cells is listed
/// once, in the order the grid's query() meets it first.
class FacesNearBox {
public:
    using Found = std::vector<std::pair<std::uint32_t, Box>>;

    /// The faces in the cells `box` covers whose boxes overlap it and that keep(face) accepts.
    /// The list stays valid until the next call.
    template <class Keep>
    const Found& gather(const TriangleGrid& grid, const TriangleGeometry& g, const Box& box,
                        Keep&& keep) {
        listed_.clear();
        grid.query(box, listed_);
        ++search_;
        found_.clear();
        for (std::uint32_t f : listed_) {
            if (f >= stamp_.size()) stamp_.resize(std::size_t(f) + 1, 0);
            if (stamp_[f] == search_) continue;
            stamp_[f] = search_; // listed again later in the same search: seen
            if (!keep(f)) continue;
            const Box b = g.box(g.triangle(f));
            if (b.overlaps(box)) found_.emplace_back(f, b);
        }
        return found_;
    }
    const Found& found() const { return found_; }

private:
    std::vector<std::uint32_t> listed_, stamp_; ///< stamp_: per face, the last search meeting it
    std::uint32_t search_ = 0;
    Found found_;
};

} // namespace hrsr
