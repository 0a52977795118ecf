#include "mesh/small_holes_fill.h"

#include "geometry.h"
#include "mesh/triangle_grid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <unordered_map>

namespace hrsr {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr std::uint32_t kMany = 0xfffffffeu;
const double kMinFanAngle = M_PI / 180.0;

std::uint64_t directed(std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t(a) << 32) | b;
}

/// The mesh's directed edges, sorted: 8 bytes per corner, no hash table (D-28 runs on the whole
/// output, so its memory counts against the peak).
class DirectedEdges {
public:
    explicit DirectedEdges(const std::vector<Triangle>& triangles) {
        keys_.reserve(triangles.size() * 3);
        for (const Triangle& t : triangles)
            for (int k = 0; k < 3; ++k) keys_.push_back(directed(t[k], t[(k + 1) % 3]));
        std::sort(keys_.begin(), keys_.end());
    }
    bool has(std::uint32_t a, std::uint32_t b) const {
        return std::binary_search(keys_.begin(), keys_.end(), directed(a, b));
    }
    bool has_either(std::uint32_t a, std::uint32_t b) const { return has(a, b) || has(b, a); }
    const std::vector<std::uint64_t>& keys() const { return keys_; }

private:
    std::vector<std::uint64_t> keys_;
};

// next[v]: the vertex after v along the hole it borders (a → b is a boundary edge of a triangle
// when no triangle has b → a; the hole then runs b → a), kNone when v is on no hole, kMany when
// on more than one hole edge.
std::vector<std::uint32_t> hole_successors(const DirectedEdges& edges, std::size_t vertices) {
    std::vector<std::uint32_t> next(vertices, kNone);
    for (std::uint64_t key : edges.keys()) {
        const std::uint32_t a = std::uint32_t(key >> 32), b = std::uint32_t(key);
        if (edges.has(b, a)) continue;
        next[b] = next[b] == kNone ? a : kMany;
    }
    return next;
}

// The loop through v, if it is short, simple, visited from its smallest vertex, and every vertex
// on it borders only this hole.
bool short_loop(const std::vector<std::uint32_t>& next, std::uint32_t v, std::size_t max_edges,
                std::vector<std::uint32_t>& loop) {
    loop.clear();
    for (std::uint32_t x = v; loop.size() <= max_edges;) {
        if (next[x] == kNone || next[x] == kMany) return false;
        loop.push_back(x);
        x = next[x];
        if (x == v) break;
    }
    if (loop.size() < 3 || loop.size() > max_edges || next[loop.back()] != v) return false;
    std::vector<std::uint32_t> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end() && sorted.front() == v;
}

using TriangleSet = std::set<std::array<std::uint32_t, 3>>;

std::array<std::uint32_t, 3> sorted_corners(std::array<std::uint32_t, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
}

// Whether the three vertices of a 3-loop already form a triangle (a lone triangle's outline:
// closing it would double the triangle). The set is built on first use: 3-loops are rare.
bool is_triangle(const std::vector<Triangle>& triangles, const std::vector<std::uint32_t>& loop,
                 TriangleSet& existing) {
    if (existing.empty())
        for (const Triangle& t : triangles) existing.insert(sorted_corners(t));
    return existing.count(sorted_corners({loop[0], loop[1], loop[2]})) > 0;
}

// The fan (triangulation) of the loop with the largest smallest angle among those whose
// diagonals are not edges; empty if none reaches kMinFanAngle.
std::vector<Triangle> best_fan(const std::vector<std::uint32_t>& loop, const DirectedEdges& edges,
                               const std::vector<Vec3>& positions) {
    const std::size_t n = loop.size();
    std::vector<Triangle> best;
    double best_angle = kMinFanAngle;
    for (std::size_t apex = 0; apex < n; ++apex) {
        std::vector<Triangle> fan;
        double angle = M_PI;
        bool free = true;
        for (std::size_t k = 1; k + 1 < n; ++k) {
            const std::uint32_t a = loop[apex], b = loop[(apex + k) % n],
                                c = loop[(apex + k + 1) % n];
            if (k + 2 < n && edges.has_either(a, c)) free = false; // a diagonal
            angle = std::min(angle, smallest_angle(positions[a], positions[b], positions[c]));
            fan.push_back({a, b, c});
        }
        if (free && angle > best_angle) {
            best_angle = angle;
            best = std::move(fan);
        }
    }
    return best;
}

struct Fill {
    std::vector<Triangle> fan;
    Box box;
    bool rejected = false;
};

// Rejects fills whose triangles intersect a triangle of the mesh or of another fill (the test of
// hrsr check): a fill must not add a fold. Fills are filed in a hash grid of cells as large as
// the largest fill; one pass over the mesh tests each triangle against the fills it may touch.
void reject_intersecting(std::vector<Fill>& fills, const std::vector<Triangle>& triangles,
                         const std::vector<Vec3>& positions) {
    if (fills.empty()) return;
    const TriangleGeometry g(positions, {});
    double cell = 0;
    for (const Fill& f : fills)
        for (int k = 0; k < 3; ++k) cell = std::max(cell, f.box.hi[k] - f.box.lo[k]);
    if (!(cell > 0)) return;
    auto key = [&](const Vec3& p, int k) { return std::int64_t(std::floor(p[k] / cell)); };
    auto cell_id = [](std::int64_t x, std::int64_t y, std::int64_t z) {
        return std::uint64_t((x * 73856093) ^ (y * 19349663) ^ (z * 83492791));
    };
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
    auto for_cells = [&](const Box& b, auto&& visit) {
        for (std::int64_t x = key(b.lo, 0); x <= key(b.hi, 0); ++x)
            for (std::int64_t y = key(b.lo, 1); y <= key(b.hi, 1); ++y)
                for (std::int64_t z = key(b.lo, 2); z <= key(b.hi, 2); ++z) visit(cell_id(x, y, z));
    };
    for (std::uint32_t i = 0; i < fills.size(); ++i)
        for_cells(fills[i].box, [&](std::uint64_t c) { grid[c].push_back(i); });
    auto crosses = [&](const Fill& f, const Triangle& t) {
        for (const Triangle& s : f.fan)
            if (g.intersect(s, t)) return true;
        return false;
    };
    auto corners_box = [&](const Triangle& t) {
        Box b{positions[t[0]], positions[t[0]]};
        b.add(positions[t[1]]);
        b.add(positions[t[2]]);
        return b;
    };
    std::vector<std::uint32_t> near;
    auto test = [&](const Triangle& t, std::uint32_t own) {
        const Box b = corners_box(t);
        // A triangle much larger than the cells would visit many empty cells: test it against
        // every fill instead (there are few).
        const double extent = std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
        near.clear();
        if (extent > 8 * cell) {
            for (std::uint32_t i = 0; i < fills.size(); ++i) near.push_back(i);
        } else {
            for_cells(b, [&](std::uint64_t c) {
                if (auto it = grid.find(c); it != grid.end())
                    near.insert(near.end(), it->second.begin(), it->second.end());
            });
            std::sort(near.begin(), near.end());
            near.erase(std::unique(near.begin(), near.end()), near.end());
        }
        for (std::uint32_t i : near)
            if (i != own && fills[i].box.overlaps(b) && crosses(fills[i], t))
                fills[i].rejected = true;
    };
    for (const Triangle& t : triangles) test(t, kNone);
    // Fills against each other (and the fan's own triangles against each other).
    for (std::uint32_t i = 0; i < fills.size(); ++i)
        for (std::size_t a = 0; a < fills[i].fan.size(); ++a) {
            for (std::size_t b = a + 1; b < fills[i].fan.size(); ++b)
                if (g.intersect(fills[i].fan[a], fills[i].fan[b])) fills[i].rejected = true;
            test(fills[i].fan[a], i);
        }
}

} // namespace

std::size_t fill_small_holes(std::vector<Triangle>& triangles, const std::vector<Vec3>& positions,
                             std::size_t max_edges) {
    std::vector<Fill> fills;
    {
        const DirectedEdges edges(triangles);
        const std::vector<std::uint32_t> next = hole_successors(edges, positions.size());
        std::vector<std::uint32_t> loop;
        TriangleSet existing;
        for (std::uint32_t v = 0; v < next.size(); ++v) {
            if (next[v] == kNone || !short_loop(next, v, max_edges, loop)) continue;
            if (loop.size() == 3 && is_triangle(triangles, loop, existing)) continue;
            Fill f;
            f.fan = best_fan(loop, edges, positions);
            if (f.fan.empty()) continue;
            f.box = {positions[loop[0]], positions[loop[0]]};
            for (std::uint32_t x : loop) f.box.add(positions[x]);
            fills.push_back(std::move(f));
        }
    }
    reject_intersecting(fills, triangles, positions);
    std::size_t closed = 0;
    for (const Fill& f : fills) {
        if (f.rejected) continue;
        triangles.insert(triangles.end(), f.fan.begin(), f.fan.end());
        ++closed;
    }
    return closed;
}

} // namespace hrsr
