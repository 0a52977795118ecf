#include "mesh/triangle_mesh.h"

#include "radix_pass.h"

#include <algorithm>
#include <numeric>

namespace hrsr {

namespace {

// Below this many faces one thread builds the lists (the tasks' extra passes would not pay).
constexpr std::size_t kParallelFaces = std::size_t(1) << 16;

} // namespace

VertexCorners corners_by_vertex(std::size_t n, const std::vector<Triangle>& triangles) {
    VertexCorners c;
    c.start.assign(n + 1, 0);
    for (const Triangle& t : triangles)
        for (std::uint32_t v : t) ++c.start[v + 1];
    std::partial_sum(c.start.begin(), c.start.end(), c.start.begin());
    c.corner.resize(c.start[n]);
    std::vector<std::uint32_t> cursor(c.start.begin(), c.start.end() - 1);
    for (std::uint32_t t = 0; t < triangles.size(); ++t)
        for (std::uint32_t k = 0; k < 3; ++k) c.corner[cursor[triangles[t][k]]++] = 3 * t + k;
    return c;
}

// The cost of the sequential build is its scattered writes (counts and corners at random
// vertices), not the reading of the faces. Each task owns a range of vertices: it reads every
// face, in order, and writes only its own vertices' counts and corners, so each vertex's corners
// come in increasing order, as above, for any number of tasks.
VertexCorners corners_by_vertex(std::size_t n, const std::vector<Triangle>& triangles,
                                const Execution& exec) {
    const auto tasks = std::size_t(thread_count(exec));
    if (tasks < 2 || triangles.size() < kParallelFaces) return corners_by_vertex(n, triangles);
    const Execution quiet = without_progress(exec);
    const auto first_of = [&](std::size_t task) { return std::uint32_t(n * task / tasks); };
    VertexCorners c;
    c.start.assign(n + 1, 0);
    parallel_for(
        quiet, tasks,
        [&](std::size_t task) {
            const std::uint32_t lo = first_of(task), hi = first_of(task + 1);
            for (const Triangle& t : triangles)
                for (std::uint32_t v : t)
                    if (v >= lo && v < hi) ++c.start[v + 1];
        },
        1);
    std::partial_sum(c.start.begin(), c.start.end(), c.start.begin());
    c.corner.resize(c.start[n]);
    parallel_for(
        quiet, tasks,
        [&](std::size_t task) {
            const std::uint32_t lo = first_of(task), hi = first_of(task + 1);
            std::vector<std::uint32_t> cursor(c.start.begin() + lo, c.start.begin() + hi);
            for (std::uint32_t t = 0; t < triangles.size(); ++t)
                for (std::uint32_t k = 0; k < 3; ++k) {
                    const std::uint32_t v = triangles[t][k];
                    if (v >= lo && v < hi) c.corner[cursor[v - lo]++] = 3 * t + k;
                }
        },
        1);
    return c;
}

// A stable radix sort on the smallest vertex, a byte at a time.
void sort_by_smallest_vertex(std::vector<Triangle>& triangles, const Execution& exec) {
    std::vector<Triangle> buffer;
    for (int shift = 0; shift < 32; shift += 8)
        stable_radix_pass(
            triangles, buffer,
            [shift](const Triangle& t) {
                return std::size_t(std::min({t[0], t[1], t[2]}) >> shift) & 0xff;
            },
            exec);
}

} // namespace hrsr
