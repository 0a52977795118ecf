#include "mesh/edge_census.h"

#include "graph/neighbour_graph.h"

#include <algorithm>
#include <numeric>

namespace hrsr {

namespace {

// A corner of a vertex with the vertices that follow and precede it in its triangle.
struct Corner {
    std::uint32_t corner, next, previous;
};

// Each vertex's corners in triangle order, [start[v], start[v + 1]): a counting sort that
// copies the neighbours along, so that the walk reads one vertex's star from one place.
struct Stars {
    std::vector<std::uint32_t> start;
    std::vector<Corner> corners;
};

Stars file_stars(std::size_t n, const std::vector<Triangle>& triangles) {
    Stars stars;
    stars.start.assign(n + 1, 0);
    for (const Triangle& t : triangles)
        for (std::uint32_t v : t) ++stars.start[v + 1];
    std::partial_sum(stars.start.begin(), stars.start.end(), stars.start.begin());
    stars.corners.resize(stars.start[n]);
    std::vector<std::uint32_t> cursor(stars.start.begin(), stars.start.end() - 1);
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (std::uint32_t k = 0; k < 3; ++k)
            stars.corners[cursor[triangles[t][k]]++] = {3 * t + k, triangles[t][(k + 1) % 3],
                                                        triangles[t][(k + 2) % 3]};
    return stars;
}

// The star of one vertex at a time, with scratch kept between the vertices of a block.
class StarWalk {
public:
    StarWalk(ConcurrentSets& sets, std::vector<std::uint8_t>& first_of_edge, EdgeCensus& census)
        : sets_(sets), first_of_edge_(first_of_edge), census_(census) {}

    void visit(std::uint32_t v, const Corner* corners, std::uint32_t count) {
        corners_ = corners;
        // A spoke: (other endpoint, local corner << 1 | 0 when the other endpoint follows v in
        // the triangle, 1 when it precedes it). Each half-edge at v is one spoke.
        spokes_.clear();
        for (std::uint32_t c = 0; c < count; ++c) {
            spokes_.emplace_back(corners[c].next, c << 1);
            spokes_.emplace_back(corners[c].previous, c << 1 | 1);
        }
        std::sort(spokes_.begin(), spokes_.end());
        fans_.reset(count);
        std::uint32_t fans = count;
        for (std::size_t a = 0, b; a < spokes_.size(); a = b) {
            // Corners with a spoke to the same vertex are in one fan (as compute_fans finds).
            for (b = a + 1; b < spokes_.size() && spokes_[b].first == spokes_[a].first; ++b)
                if (fans_.unite(spokes_[b].second >> 1, spokes_[b - 1].second >> 1)) --fans;
            if (spokes_[a].first > v) edge(v, a, b);
        }
        census_.non_manifold_vertices += fans > 1;
    }

private:
    // The triangle of spoke s and the index k of its half-edge (t[k], t[k + 1]).
    std::uint32_t triangle(std::size_t s) const {
        return corners_[spokes_[s].second >> 1].corner / 3;
    }
    std::uint32_t half_edge(std::size_t s) const {
        const std::uint32_t corner = corners_[spokes_[s].second >> 1].corner;
        return 3 * (corner / 3) + (corner % 3 + 2 * (spokes_[s].second & 1)) % 3;
    }

    // The undirected edge (v, spokes_[a].first) with its half-edges spokes_[a, b), in triangle
    // order.
    void edge(std::uint32_t v, std::size_t a, std::size_t b) {
        ++census_.edges;
        first_of_edge_[half_edge(a)] = 1;
        for (std::size_t s = a + 1; s < b; ++s) sets_.unite(triangle(s - 1), triangle(s));
        if (b - a == 1) {
            ++census_.boundary_edges;
            census_.boundary.emplace_back(v, spokes_[a].first);
        } else if (b - a > 2) {
            ++census_.non_manifold_edges;
        } else if ((spokes_[a].second & 1) == (spokes_[a + 1].second & 1)) {
            ++census_.inconsistently_oriented_edges; // both traverse it the same way
        }
    }

    ConcurrentSets& sets_;
    std::vector<std::uint8_t>& first_of_edge_;
    EdgeCensus& census_;
    const Corner* corners_ = nullptr;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> spokes_;
    DisjointSets fans_{0};
};

} // namespace

EdgeCensus census_edges(std::size_t n, const std::vector<Triangle>& triangles, ConcurrentSets& sets,
                        std::vector<std::uint8_t>& first_of_edge, const Execution& exec) {
    const Stars stars = file_stars(n, triangles);
    constexpr std::size_t kBlock = 4096; // vertices: a few dozen spokes each
    std::vector<EdgeCensus> block(block_count(n, kBlock));
    std::vector<std::uint32_t> last_triangle(n);
    parallel_for_blocks(exec, n, kBlock, [&](std::size_t b, std::size_t first, std::size_t end) {
        StarWalk walk(sets, first_of_edge, block[b]);
        for (std::uint32_t v = std::uint32_t(first); v < end; ++v) {
            const std::uint32_t begin = stars.start[v], count = stars.start[v + 1] - begin;
            last_triangle[v] = count ? stars.corners[begin + count - 1].corner / 3 : ~0u;
            if (count) walk.visit(v, stars.corners.data() + begin, count);
        }
    });
    EdgeCensus all;
    all.last_triangle = std::move(last_triangle);
    for (const EdgeCensus& c : block) {
        all.edges += c.edges;
        all.boundary_edges += c.boundary_edges;
        all.non_manifold_edges += c.non_manifold_edges;
        all.inconsistently_oriented_edges += c.inconsistently_oriented_edges;
        all.non_manifold_vertices += c.non_manifold_vertices;
        all.boundary.insert(all.boundary.end(), c.boundary.begin(), c.boundary.end());
    }
    return all;
}

} // namespace hrsr
