#include "mesh/small_holes_fill.h"

#include "geometry.h"
#include "graph/neighbour_graph.h"
#include "knn.h"
#include "mesh/triangle_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <unordered_map>

namespace hrsr {

namespace {

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr std::uint32_t kMany = 0xfffffffeu;
const double kMinFanAngle = M_PI / 180.0;

/// Vertex v at points[vertex_point[v]] (or points[v] when vertex_point is empty): HRsR's
/// vertices stand for cloud points, and a copy of their positions would add to the peak.
struct VertexPositions {
    const std::vector<Vec3>& points;
    const IndexVector<VertexIndex, PointIndex>& vertex_point;
    std::size_t vertex_count;
    std::uint32_t point(std::uint32_t v) const {
        return vertex_point.empty() ? v : vertex_point[VertexIndex(v)].value();
    }
    const Vec3& operator[](std::uint32_t v) const { return points[point(v)]; }
    /// The triangle over point ids, for the intersection test (which compares corner ids).
    Triangle as_points(const Triangle& t) const { return {point(t[0]), point(t[1]), point(t[2])}; }
};

/// The mesh's directed edges, looked up through the triangles around each vertex (a CSR of 4
/// bytes per corner: D-28 runs on the whole output, so its memory counts against the peak).
class DirectedEdges {
public:
    DirectedEdges(const std::vector<Triangle>& triangles, std::size_t vertices,
                  const Execution& exec)
        : triangles_(triangles), corners_(corners_by_vertex(vertices, triangles, exec)) {}
    /// The vertex before b along the hole b borders (see hole_successors), kNone or kMany: the
    /// edges a → b into b are at b's corners, and a → b borders a hole when no b → a exists.
    std::uint32_t hole_successor(std::uint32_t b) const {
        // The edges out of b and into b, read once from b's corners (not b's triangles again
        // for every edge into b).
        thread_local std::vector<std::uint32_t> after, before;
        after.clear();
        before.clear();
        for (std::uint32_t i = corners_.begin(b); i < corners_.end(b); ++i) {
            const std::uint32_t c = corners_.corner[i];
            const Triangle& t = triangles_[c / 3];
            after.push_back(t[(c % 3 + 1) % 3]);
            before.push_back(t[(c % 3 + 2) % 3]);
        }
        std::uint32_t next = kNone;
        for (std::uint32_t a : before)
            if (std::find(after.begin(), after.end(), a) == after.end())
                next = next == kNone ? a : kMany;
        return next;
    }
    /// Some triangle has the edge {a, b}.
    bool has_either(std::uint32_t a, std::uint32_t b) const {
        for (std::uint32_t i = corners_.begin(a); i < corners_.end(a); ++i) {
            const std::uint32_t c = corners_.corner[i];
            const Triangle& t = triangles_[c / 3];
            if (t[(c % 3 + 1) % 3] == b || t[(c % 3 + 2) % 3] == b) return true;
        }
        return false;
    }
    /// Some triangle has the corners a, b, c (in either winding): a 3-loop around it is that
    /// triangle's outline (a lone triangle), and closing it would double the triangle.
    bool has_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) const {
        for (std::uint32_t i = corners_.begin(a); i < corners_.end(a); ++i) {
            const Triangle& t = triangles_[corners_.corner[i] / 3];
            const auto has = [&](std::uint32_t x) { return t[0] == x || t[1] == x || t[2] == x; };
            if (has(b) && has(c)) return true;
        }
        return false;
    }

private:
    const std::vector<Triangle>& triangles_;
    VertexCorners corners_;
};

// next[v]: the vertex after v along the hole it borders (a → b is a boundary edge of a triangle
// when no triangle has b → a; the hole then runs b → a), kNone when v is on no hole, kMany when
// on more than one hole edge. By vertex (each writes its own entry), in parallel blocks.
std::vector<std::uint32_t> hole_successors(const DirectedEdges& edges, std::size_t vertices,
                                           const Execution& exec) {
    std::vector<std::uint32_t> next(vertices, kNone);
    parallel_for_blocks(exec, vertices, kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t b = first; b < end; ++b)
                                next[b] = edges.hole_successor(std::uint32_t(b));
                        });
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

// v's hole is a short loop: following next from v comes back to v within max_edges edges. (next
// is a function, so such a walk is a simple loop, and it has at least 3 edges: a → b and b → a
// cannot both be border edges.)
bool on_short_loop(const std::vector<std::uint32_t>& next, std::uint32_t v, std::size_t max_edges) {
    std::uint32_t x = v;
    for (std::size_t edges = 0; edges < max_edges; ++edges) {
        x = next[x];
        if (x == kNone || x == kMany) return false;
        if (x == v) return true;
    }
    return false;
}

// Per vertex: its piece (the vertices its triangles join) is not a closed surface with pinholes:
// it has a border that is not a short loop (a longer loop, or a vertex on several hole edges),
// or at least as many border vertices as interior ones (a scrap of a few points).
// `on_long_loop`: vertices on loops that count as short too (D-53), or empty.
std::vector<std::uint8_t> on_open_piece(const std::vector<Triangle>& triangles,
                                        const std::vector<std::uint32_t>& next,
                                        std::size_t max_edges,
                                        const std::vector<std::uint8_t>& on_long_loop) {
    const std::size_t n = next.size();
    DisjointSets pieces(n);
    std::vector<std::uint8_t> used(n, 0);
    for (const Triangle& t : triangles) {
        pieces.unite(t[0], t[1]);
        pieces.unite(t[0], t[2]);
        used[t[0]] = used[t[1]] = used[t[2]] = 1;
    }
    std::vector<std::uint8_t> open_root(n, 0);
    std::vector<std::int64_t> interior_minus_border(n, 0);
    for (std::uint32_t v = 0; v < n; ++v) {
        if (!used[v]) continue;
        const std::uint32_t root = pieces.find(v);
        interior_minus_border[root] += next[v] == kNone ? 1 : -1;
        if (next[v] != kNone && !on_short_loop(next, v, max_edges) &&
            (on_long_loop.empty() || !on_long_loop[v]))
            open_root[root] = 1;
    }
    std::vector<std::uint8_t> open(n, 0);
    for (std::uint32_t v = 0; v < n; ++v) {
        const std::uint32_t root = pieces.find(v);
        open[v] = open_root[root] || interior_minus_border[root] <= 0;
    }
    return open;
}

// The fans (triangulations) of the loop whose diagonals are not edges and whose smallest angle
// reaches kMinFanAngle, best (largest smallest angle) first; ties by apex position.
std::vector<std::vector<Triangle>> candidate_fans(const std::vector<std::uint32_t>& loop,
                                                  const DirectedEdges& edges,
                                                  const VertexPositions& positions) {
    const std::size_t n = loop.size();
    std::vector<std::pair<double, std::vector<Triangle>>> fans;
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
        if (free && angle > kMinFanAngle) fans.emplace_back(angle, std::move(fan));
        if (n == 3) break; // a triangle has one triangulation
    }
    std::stable_sort(fans.begin(), fans.end(),
                     [](const auto& x, const auto& y) { return x.first > y.first; });
    std::vector<std::vector<Triangle>> out;
    for (auto& f : fans) out.push_back(std::move(f.second));
    return out;
}

struct Fill {
    std::vector<std::vector<Triangle>> fans; ///< candidates, best first
    std::vector<bool> crossing;              ///< per candidate: it intersects the mesh or itself
    int chosen = -1;                         ///< the first candidate that does not
    Box box;
};

Fill fill_of(const std::vector<std::uint32_t>& loop, const DirectedEdges& edges,
             const VertexPositions& positions) {
    Fill f;
    f.fans = candidate_fans(loop, edges, positions);
    f.box = {positions[loop[0]], positions[loop[0]]};
    for (std::uint32_t x : loop) f.box.add(positions[x]);
    return f;
}

/// Files fills in a hash grid of cells as large as the largest fill, so that one pass over the
/// mesh tests each triangle against the fills it may touch only.
class FillGrid {
public:
    FillGrid(const std::vector<Fill>& fills, const VertexPositions& positions)
        : positions_(positions), count_(fills.size()) {
        for (const Fill& f : fills)
            for (int k = 0; k < 3; ++k) cell_ = std::max(cell_, f.box.hi[k] - f.box.lo[k]);
        if (!(cell_ > 0)) cell_ = 1;
        for (std::uint32_t i = 0; i < fills.size(); ++i)
            for_cells(fills[i].box, [&](std::uint64_t c) { cells_[c].push_back(i); });
    }

    Box box(const Triangle& t) const {
        Box b{positions_[t[0]], positions_[t[0]]};
        b.add(positions_[t[1]]);
        b.add(positions_[t[2]]);
        return b;
    }

    /// The fills whose cells `b` covers (every fill when b is much larger than a cell).
    void near(const Box& b, std::vector<std::uint32_t>& out) const {
        out.clear();
        const double extent = std::max({b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]});
        if (extent > 8 * cell_) {
            for (std::uint32_t i = 0; i < count_; ++i) out.push_back(i);
            return;
        }
        for_cells(b, [&](std::uint64_t c) {
            if (auto it = cells_.find(c); it != cells_.end())
                out.insert(out.end(), it->second.begin(), it->second.end());
        });
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

private:
    template <class Visit>
    void for_cells(const Box& b, Visit&& visit) const {
        // The box's cell range, worked out once (D-28 asks it of every triangle of the mesh).
        std::int64_t lo[3], hi[3];
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::int64_t(std::floor(b.lo[k] / cell_));
            hi[k] = std::int64_t(std::floor(b.hi[k] / cell_));
        }
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
            for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
                for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
                    visit(std::uint64_t((x * 73856093) ^ (y * 19349663) ^ (z * 83492791)));
    }
    const VertexPositions& positions_;
    std::size_t count_;
    double cell_ = 0;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

// Marks the fans that a triangle of the mesh intersects, by parallel blocks of triangles, each
// listing the (fill, fan) pairs it finds: crossing is an OR over the triangles, so merging the
// lists afterwards gives what one pass in triangle order gives.
template <class Intersect>
void mark_crossed_by_mesh(std::vector<Fill>& fills, const std::vector<Triangle>& triangles,
                          const FillGrid& grid, const Intersect& intersect, const Execution& exec) {
    using Hit = std::pair<std::uint32_t, std::uint32_t>; // fill, fan
    std::vector<std::vector<Hit>> hits(block_count(triangles.size(), kCheapBlock));
    parallel_for_blocks(
        exec, triangles.size(), kCheapBlock,
        [&](std::size_t block, std::size_t first, std::size_t end) {
            std::vector<std::uint32_t> near;
            std::vector<Hit>& found = hits[block];
            for (std::size_t t = first; t < end; ++t) {
                const Box b = grid.box(triangles[t]);
                grid.near(b, near);
                for (std::uint32_t i : near) {
                    const Fill& f = fills[i];
                    if (!f.box.overlaps(b)) continue;
                    for (std::uint32_t k = 0; k < f.fans.size(); ++k) {
                        if (f.crossing[k] || std::count(found.begin(), found.end(), Hit{i, k}))
                            continue; // known to cross
                        for (const Triangle& s : f.fans[k])
                            if (intersect(s, triangles[t])) {
                                found.emplace_back(i, k);
                                break;
                            }
                    }
                }
            }
        });
    for (const std::vector<Hit>& found : hits)
        for (const auto& [i, k] : found) fills[i].crossing[k] = true;
}

// A fill must not add a fold (the hrsr check test): each loop takes its best fan that intersects
// neither the mesh nor itself, and a fill whose fan intersects an earlier fill's is dropped.
void choose_fans(std::vector<Fill>& fills, const std::vector<Triangle>& triangles,
                 const VertexPositions& positions, const Execution& exec) {
    if (fills.empty()) return;
    const TriangleGeometry geometry(positions.points, {});
    // The pair test takes proper triangles: an exactly degenerate one of the mesh is skipped, as
    // `hrsr check` skips it (fans have no angle under 1°).
    auto intersect = [&](const Triangle& a, const Triangle& b) {
        const Triangle pa = positions.as_points(a), pb = positions.as_points(b);
        return !geometry.degenerate(pa) && !geometry.degenerate(pb) && geometry.intersect(pa, pb);
    };
    const FillGrid grid(fills, positions);
    for (Fill& f : fills) {
        f.crossing.assign(f.fans.size(), false);
        for (std::size_t k = 0; k < f.fans.size(); ++k)
            for (std::size_t a = 0; a < f.fans[k].size(); ++a)
                for (std::size_t b = a + 1; b < f.fans[k].size(); ++b)
                    if (intersect(f.fans[k][a], f.fans[k][b])) f.crossing[k] = true;
    }
    mark_crossed_by_mesh(fills, triangles, grid, intersect, exec);
    std::vector<std::uint32_t> near;
    for (Fill& f : fills)
        for (std::size_t k = 0; k < f.fans.size() && f.chosen < 0; ++k)
            if (!f.crossing[k]) f.chosen = int(k);
    for (std::uint32_t i = 0; i < fills.size(); ++i) {
        if (fills[i].chosen < 0) continue;
        for (const Triangle& s : fills[i].fans[std::size_t(fills[i].chosen)]) {
            grid.near(grid.box(s), near);
            for (std::uint32_t j : near) {
                if (j >= i || fills[j].chosen < 0) continue;
                for (const Triangle& u : fills[j].fans[std::size_t(fills[j].chosen)])
                    if (intersect(s, u)) fills[i].chosen = -1;
                if (fills[i].chosen < 0) break;
            }
            if (fills[i].chosen < 0) break;
        }
    }
}

// D-53: the loops longer than `max_edges` and no longer than sampled.max_edges on pieces that
// would be closed but for short loops and these, each with its fans over sampled surface (loops
// without one are left out); `on_long_loop` marks their vertices.
struct LongLoops {
    std::vector<Fill> fills;
    std::vector<std::uint32_t> smallest_vertex; ///< per fill: where the loop is met first
    std::vector<std::uint8_t> on_long_loop;     ///< empty: no such loop
};

// The loop's fans every triangle of which has a sample within `reach` of its centroid, where
// reach is the distance from a corner of the loop to its rank-th nearest sample, at the corner
// where that is shortest (RsR's candidate edges reach that far, §5.1). None when rank < 1.
std::vector<std::vector<Triangle>> fans_over_samples(std::vector<std::vector<Triangle>> fans,
                                                     const std::vector<std::uint32_t>& loop,
                                                     const VertexPositions& positions,
                                                     const KnnIndex& samples, int rank) {
    if (rank < 1) return {};
    std::vector<Neighbour> found;
    double reach = std::numeric_limits<double>::infinity();
    for (std::uint32_t x : loop) {
        samples.nearest(positions[x], rank, found);
        if (!found.empty()) reach = std::min(reach, found.back().squared_distance);
    }
    std::vector<std::vector<Triangle>> out;
    for (std::vector<Triangle>& fan : fans) {
        const bool sampled = std::all_of(fan.begin(), fan.end(), [&](const Triangle& t) {
            samples.nearest((positions[t[0]] + positions[t[1]] + positions[t[2]]) / 3.0, 1, found);
            return !found.empty() && found.front().squared_distance <= reach;
        });
        if (sampled) out.push_back(std::move(fan));
    }
    return out;
}

LongLoops sampled_long_loops(const std::vector<Triangle>& triangles, const DirectedEdges& edges,
                             const std::vector<std::uint32_t>& next,
                             const VertexPositions& positions, std::size_t max_edges,
                             const SampledLoops& sampled, const Execution& exec) {
    LongLoops out;
    std::vector<std::vector<std::uint32_t>> loops;
    std::vector<std::uint32_t> loop;
    for (std::uint32_t v = 0; v < next.size(); ++v)
        if (next[v] != kNone && short_loop(next, v, sampled.max_edges, loop) &&
            loop.size() > max_edges)
            loops.push_back(loop);
    if (loops.empty()) return out; // the usual case: no pass over the pieces, no kd-tree
    out.on_long_loop.assign(next.size(), 0);
    const std::vector<std::uint8_t> open = on_open_piece(triangles, next, sampled.max_edges, {});
    std::unique_ptr<KnnIndex> samples; // built once a loop asks for it
    for (const std::vector<std::uint32_t>& candidate : loops) {
        if (open[candidate.front()]) continue;
        Fill f = fill_of(candidate, edges, positions);
        if (f.fans.empty()) continue;
        if (!samples) samples = std::make_unique<KnnIndex>(*sampled.samples, exec);
        f.fans = fans_over_samples(std::move(f.fans), candidate, positions, *samples, sampled.rank);
        if (f.fans.empty()) continue;
        for (std::uint32_t x : candidate) out.on_long_loop[x] = 1;
        out.fills.push_back(std::move(f));
        out.smallest_vertex.push_back(candidate.front());
    }
    return out;
}

} // namespace

std::size_t fill_small_holes(std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
                             const IndexVector<VertexIndex, PointIndex>& vertex_point,
                             std::size_t max_edges, SmallHoleScope scope, const Execution& exec,
                             const SampledLoops& sampled) {
    // No progress from these loops: the phase's fraction is not theirs to report.
    const Execution quiet = without_progress(exec);
    const VertexPositions positions{points, vertex_point,
                                    vertex_point.empty() ? points.size() : vertex_point.size()};
    std::vector<Fill> fills;
    {
        const DirectedEdges edges(triangles, positions.vertex_count, quiet);
        const std::vector<std::uint32_t> next =
            hole_successors(edges, positions.vertex_count, quiet);
        const bool closed_pieces = scope == SmallHoleScope::PiecesClosedButForThem;
        LongLoops long_loops;
        if (closed_pieces && sampled.samples && sampled.max_edges > max_edges)
            long_loops =
                sampled_long_loops(triangles, edges, next, positions, max_edges, sampled, quiet);
        const std::vector<std::uint8_t> open =
            closed_pieces ? on_open_piece(triangles, next, max_edges, long_loops.on_long_loop)
                          : std::vector<std::uint8_t>(next.size(), 0);
        std::vector<std::uint32_t> loop;
        std::size_t next_long = 0; // long_loops' fills are in order of their smallest vertex
        for (std::uint32_t v = 0; v < next.size(); ++v) {
            if (next[v] == kNone) continue;
            if (!long_loops.on_long_loop.empty() && long_loops.on_long_loop[v]) {
                if (next_long < long_loops.smallest_vertex.size() &&
                    long_loops.smallest_vertex[next_long] == v) {
                    if (!open[v]) fills.push_back(std::move(long_loops.fills[next_long]));
                    ++next_long;
                }
                continue;
            }
            if (open[v] || !short_loop(next, v, max_edges, loop)) continue;
            if (loop.size() == 3 && edges.has_triangle(loop[0], loop[1], loop[2])) continue;
            Fill f = fill_of(loop, edges, positions);
            if (!f.fans.empty()) fills.push_back(std::move(f));
        }
    }
    choose_fans(fills, triangles, positions, quiet);
    std::size_t closed = 0;
    for (const Fill& f : fills) {
        if (f.chosen < 0) continue;
        const std::vector<Triangle>& fan = f.fans[std::size_t(f.chosen)];
        triangles.insert(triangles.end(), fan.begin(), fan.end());
        ++closed;
    }
    return closed;
}

} // namespace hrsr
