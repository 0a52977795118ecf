#include "hrsr/unsampled_triangles.h"

#include "hrsr/input_reach.h"
#include "knn.h"
#include "mesh/small_holes_fill.h"
#include "options.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace hrsr {

namespace {

// Only vertices whose longest edge is over this many times their shortest are queried, to keep
// the kNN queries to the few vertices next to a long edge: twice the rank-th neighbour distance
// is about 7.6 spacings for rank 46, and a vertex's shortest edge is about one spacing.
constexpr double kScreen = 4.0;

double squared_length(const std::vector<Vec3>& points, PointIndex a, PointIndex b) {
    return (points[a.value()] - points[b.value()]).SquaredNorm();
}

double length(const std::vector<Vec3>& points, PointIndex a, PointIndex b) {
    return std::sqrt(squared_length(points, a, b)); // as vcg's Norm()
}

/// The triangles around each vertex, and the triangles on an edge found through them.
class EdgeTriangles {
public:
    EdgeTriangles(const std::vector<Triangle>& triangles, std::size_t vertices,
                  const Execution& exec)
        : triangles_(triangles), corners_(corners_by_vertex(vertices, triangles, exec)) {}
    template <class Visit>
    void on_edge(std::uint32_t a, std::uint32_t b, Visit&& visit) const {
        for (std::uint32_t i = corners_.begin(a); i < corners_.end(a); ++i) {
            const std::uint32_t t = corners_.corner[i] / 3;
            const Triangle& f = triangles_[t];
            if (f[0] == b || f[1] == b || f[2] == b) visit(t);
        }
    }
    /// Calls visit(a, b) for the edges a → b of the triangles around v (an edge twice when two
    /// of v's corners are on it, as in a triangle with v twice).
    template <class Visit>
    void edges_at(std::uint32_t v, Visit&& visit) const {
        for (std::uint32_t i = corners_.begin(v); i < corners_.end(v); ++i) {
            const std::uint32_t c = corners_.corner[i];
            const Triangle& f = triangles_[c / 3];
            visit(f[c % 3], f[(c % 3 + 1) % 3]);
            visit(f[(c % 3 + 2) % 3], f[c % 3]);
        }
    }
    /// Calls visit(t) for the triangles around v (a triangle twice when it has v twice).
    template <class Visit>
    void triangles_at(std::uint32_t v, Visit&& visit) const {
        for (std::uint32_t i = corners_.begin(v); i < corners_.end(v); ++i)
            visit(corners_.corner[i] / 3);
    }
    /// v is on a boundary edge of the mesh.
    bool on_boundary(std::uint32_t v) const {
        for (std::uint32_t i = corners_.begin(v); i < corners_.end(v); ++i) {
            const Triangle& f = triangles_[corners_.corner[i] / 3];
            for (std::uint32_t x : f) {
                if (x == v) continue;
                int count = 0;
                on_edge(v, x, [&](std::uint32_t) { ++count; });
                if (count == 1) return true;
            }
        }
        return false;
    }

private:
    const std::vector<Triangle>& triangles_;
    VertexCorners corners_;
};

/// The edge-connected patches of overlong triangles that cover a hole the data has: a disk
/// (χ = 1) whose every vertex is on its outline (no data point inside) and none on the mesh's
/// boundary (the hole was closed completely), so removing it opens exactly one new loop and
/// leaves every vertex in a triangle and manifold (of patches sharing a vertex only the largest
/// goes). Other overlong triangles
/// stay: a hole that is still partly open, or a strip joining two pieces, is the data's and RsR's
/// too.
std::vector<std::uint8_t> hole_covers(const std::vector<Triangle>& triangles,
                                      const EdgeTriangles& edges, std::size_t vertices,
                                      const std::vector<std::uint8_t>& overlong) {
    std::vector<std::uint8_t> remove(triangles.size(), 0), seen(triangles.size(), 0);
    struct Cover {
        std::vector<std::uint32_t> triangles, vertices;
    };
    std::vector<Cover> covers;
    std::vector<std::uint32_t> patch, patch_vertices;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> patch_edges;
    for (std::uint32_t seed = 0; seed < triangles.size(); ++seed) {
        if (!overlong[seed] || seen[seed]) continue;
        patch.assign(1, seed);
        seen[seed] = 1;
        for (std::size_t i = 0; i < patch.size(); ++i) // breadth-first through shared edges
            for (int k = 0; k < 3; ++k)
                edges.on_edge(triangles[patch[i]][k], triangles[patch[i]][(k + 1) % 3],
                              [&](std::uint32_t t) {
                                  if (overlong[t] && !seen[t]) {
                                      seen[t] = 1;
                                      patch.push_back(t);
                                  }
                              });
        patch_edges.clear();
        patch_vertices.clear();
        for (std::uint32_t t : patch)
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
                ++patch_edges[{std::min(a, b), std::max(a, b)}];
                patch_vertices.push_back(a);
            }
        std::sort(patch_vertices.begin(), patch_vertices.end());
        patch_vertices.erase(std::unique(patch_vertices.begin(), patch_vertices.end()),
                             patch_vertices.end());
        std::map<std::uint32_t, int> outline_degree;
        for (const auto& [edge, count] : patch_edges)
            if (count == 1) {
                ++outline_degree[edge.first];
                ++outline_degree[edge.second];
            }
        const long euler =
            long(patch_vertices.size()) - long(patch_edges.size()) + long(patch.size());
        // A loop of at most five points is a gap in the sampling, not a hole in the data (D-28):
        // such a cover stays (opening it left a 4-gon that no fan closes without a fold on the
        // graded triple torus).
        bool disk = euler == 1 && outline_degree.size() == patch_vertices.size() &&
                    outline_degree.size() > kMaxFilledLoop;
        for (const auto& [v, degree] : outline_degree) disk = disk && degree == 2;
        for (std::size_t i = 0; disk && i < patch_vertices.size(); ++i)
            disk = !edges.on_boundary(patch_vertices[i]);
        if (disk) covers.push_back({patch, patch_vertices});
    }
    // A vertex keeps one fan only if at most one patch around it goes: the largest covers go
    // first (ties: in order of their first triangle).
    std::stable_sort(covers.begin(), covers.end(), [](const Cover& a, const Cover& b) {
        return a.triangles.size() > b.triangles.size();
    });
    std::vector<std::uint8_t> in_removed_patch(vertices, 0);
    for (const Cover& c : covers) {
        if (std::any_of(c.vertices.begin(), c.vertices.end(),
                        [&](std::uint32_t v) { return in_removed_patch[v] != 0; }))
            continue;
        for (std::uint32_t t : c.triangles) remove[t] = 1;
        for (std::uint32_t v : c.vertices) in_removed_patch[v] = 1;
    }
    return remove;
}

// A vertex the kNN reach is asked of, with its longest edge.
struct Screened {
    std::uint32_t vertex;
    double longest;
};

// The vertices whose longest edge is over kScreen times their shortest, in order. By parallel
// blocks of vertices, each writing its own entries.
std::vector<Screened> screened(const EdgeTriangles& edges, const std::vector<Vec3>& points,
                               const IndexVector<VertexIndex, PointIndex>& vertex_point,
                               const Execution& exec) {
    const std::size_t vertices = vertex_point.size();
    std::vector<double> longest_if_screened(vertices, 0);
    parallel_for_blocks(
        exec, vertices, kCheapBlock, [&](std::size_t, std::size_t first, std::size_t end) {
            for (std::size_t v = first; v < end; ++v) {
                // The square root is monotonic: the longest and shortest lengths are those of
                // the longest and shortest squared lengths.
                double shortest = std::numeric_limits<double>::infinity(), longest = 0;
                edges.edges_at(std::uint32_t(v), [&](std::uint32_t a, std::uint32_t b) {
                    const double l = squared_length(points, vertex_point[VertexIndex(a)],
                                                    vertex_point[VertexIndex(b)]);
                    shortest = std::min(shortest, l);
                    longest = std::max(longest, l);
                });
                shortest = std::sqrt(shortest);
                longest = std::sqrt(longest);
                if (longest > kScreen * shortest) longest_if_screened[v] = longest;
            }
        });
    std::vector<Screened> queried;
    for (std::uint32_t v = 0; v < vertices; ++v)
        if (longest_if_screened[v] > 0) queried.push_back({v, longest_if_screened[v]});
    return queried;
}

// The screened vertices with an edge longer than the reach, by the test overlong_triangles
// makes: at least rank + 1 points (the vertex's own included, as the reach counts it) are
// nearer than the longest edge / kOverlongFactor. Counting stops at the (rank + 1)-th, where a
// k-nearest query ranked rank + 1 points around every screened vertex (on a random sample
// of a surface 43 % of the vertices pass the screen: the dragon's 3.2M points). Parallel, each
// entry written once.
std::vector<std::uint32_t> beyond_reach(const std::vector<Screened>& queried,
                                        const std::vector<Vec3>& points,
                                        const IndexVector<VertexIndex, PointIndex>& vertex_point,
                                        const KnnIndex& index, int rank, const Execution& exec) {
    std::vector<std::uint8_t> beyond(queried.size(), 0);
    parallel_for(exec, queried.size(), [&](std::size_t i) {
        const double longest = queried[i].longest;
        // Where the test holds, √d < longest / kOverlongFactor: the margin covers rounding.
        const double radius = longest / constants::kOverlongFactor * (1 + 1e-9);
        beyond[i] =
            index.at_least(points[vertex_point[VertexIndex(queried[i].vertex)].value()], radius,
                           std::size_t(rank) + 1, [longest](double squared) {
                               return longest > constants::kOverlongFactor * std::sqrt(squared);
                           });
    });
    std::vector<std::uint32_t> found;
    for (std::size_t i = 0; i < queried.size(); ++i)
        if (beyond[i]) found.push_back(queried[i].vertex);
    return found;
}

// Per triangle: an edge is longer than the reach at one of its ends. Only triangles around the
// vertices with a finite reach can be.
std::vector<std::uint8_t>
overlong_triangles(const std::vector<Triangle>& triangles, const EdgeTriangles& edges,
                   const std::vector<Vec3>& points,
                   const IndexVector<VertexIndex, PointIndex>& vertex_point,
                   const std::vector<std::uint32_t>& reaching, const std::vector<double>& reach) {
    std::vector<std::uint8_t> overlong(triangles.size(), 0);
    for (std::uint32_t v : reaching)
        edges.triangles_at(v, [&](std::uint32_t t) {
            for (int k = 0; k < 3 && !overlong[t]; ++k) {
                const std::uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
                const double l =
                    length(points, vertex_point[VertexIndex(a)], vertex_point[VertexIndex(b)]);
                if (l > reach[a] || l > reach[b]) overlong[t] = 1;
            }
        });
    return overlong;
}

} // namespace

std::size_t remove_unsampled_triangles(std::vector<Triangle>& triangles,
                                       const std::vector<Vec3>& points,
                                       const IndexVector<VertexIndex, PointIndex>& vertex_point,
                                       int rank, const Execution& exec) {
    const std::size_t vertices = vertex_point.size();
    // No progress from the mesh loops (cheap; the reach test reports the phase's fraction).
    const Execution quiet = without_progress(exec);
    const EdgeTriangles edges(triangles, vertices, quiet);
    const std::vector<Screened> queried = screened(edges, points, vertex_point, quiet);
    if (queried.empty() || rank < 1) return 0;
    const KnnIndex index(points, quiet);
    const std::vector<std::uint32_t> beyond =
        beyond_reach(queried, points, vertex_point, index, rank, exec);
    if (beyond.empty()) return 0;

    // reach[v]: constants::kOverlongFactor times the rank-th neighbour distance of v's point, at
    // the vertices with an edge beyond it; no edge of another vertex is longer than its reach
    // (infinite here). The same reach as D-31's.
    std::vector<PointIndex> beyond_points;
    for (std::uint32_t v : beyond) beyond_points.push_back(vertex_point[VertexIndex(v)]);
    const std::vector<double> distance = input_reach(index, beyond_points, {rank}, quiet).front();
    std::vector<double> reach(vertices, std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < beyond.size(); ++i)
        reach[beyond[i]] = constants::kOverlongFactor * distance[i];
    const std::vector<std::uint8_t> overlong =
        overlong_triangles(triangles, edges, points, vertex_point, beyond, reach);
    if (std::find(overlong.begin(), overlong.end(), 1) == overlong.end()) return 0;
    const std::vector<std::uint8_t> remove = hole_covers(triangles, edges, vertices, overlong);
    std::size_t kept = 0;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        if (!remove[t]) triangles[kept++] = triangles[t];
    const std::size_t removed = triangles.size() - kept;
    triangles.resize(kept);
    return removed;
}

} // namespace hrsr
