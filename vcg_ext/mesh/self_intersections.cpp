#include "mesh/self_intersections.h"

#include "mesh/vcg_mesh.h"
#include "mesh/welding.h"

#include <vcg/complex/algorithms/clean.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace hrsr {

namespace {

using Cell = std::array<std::int64_t, 3>;

/// Cells of a uniform grid: integer coordinates packed into one key (21 bits per axis).
struct Grid {
    Vec3 origin;
    double cell = 1;

    Cell cell_of(const Vec3& p) const {
        Cell c;
        for (int k = 0; k < 3; ++k) c[k] = std::int64_t(std::floor((p[k] - origin[k]) / cell));
        return c;
    }
    static std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) {
        return (std::uint64_t(x) << 42) | (std::uint64_t(y) << 21) | std::uint64_t(z);
    }
};

struct Box {
    Vec3 lo, hi;
    bool overlaps(const Box& o) const {
        for (int k = 0; k < 3; ++k)
            if (hi[k] < o.lo[k] || o.hi[k] < lo[k]) return false;
        return true;
    }
};

int shared_vertices(const Triangle& a, const Triangle& b) {
    int n = 0;
    for (std::uint32_t u : a)
        for (std::uint32_t v : b) n += u == v;
    return n;
}

} // namespace

std::vector<TrianglePair> self_intersecting_pairs(const std::vector<Vec3>& positions,
                                                  const std::vector<Triangle>& triangles,
                                                  const Execution& exec) {
    const std::vector<Triangle> w =
        welded_triangles(triangles, same_position_representatives(positions));
    VcgMesh m;
    build_vcg_mesh(positions, {}, w, m);

    // Triangles worth testing, their boxes, and the grid.
    std::vector<std::uint32_t> tested;
    std::vector<Box> box(w.size());
    Box all{Vec3(HUGE_VAL, HUGE_VAL, HUGE_VAL), Vec3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL)};
    double extent_sum = 0;
    for (std::uint32_t t = 0; t < w.size(); ++t) {
        const Triangle& f = w[t];
        if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0] || m.face[t].N() == Vec3(0, 0, 0))
            continue;
        Box& b = box[t];
        b.lo = b.hi = positions[f[0]];
        for (int c = 1; c < 3; ++c)
            for (int k = 0; k < 3; ++k) {
                b.lo[k] = std::min(b.lo[k], positions[f[c]][k]);
                b.hi[k] = std::max(b.hi[k], positions[f[c]][k]);
            }
        for (int k = 0; k < 3; ++k) {
            all.lo[k] = std::min(all.lo[k], b.lo[k]);
            all.hi[k] = std::max(all.hi[k], b.hi[k]);
        }
        const Vec3 d = b.hi - b.lo;
        extent_sum += std::max(d[0], std::max(d[1], d[2]));
        tested.push_back(t);
    }
    if (tested.size() < 2) return {};
    Grid grid;
    grid.origin = all.lo;
    const Vec3 size = all.hi - all.lo;
    const double largest = std::max(size[0], std::max(size[1], size[2]));
    grid.cell = std::max({extent_sum / double(tested.size()), largest / double(1 << 20), 1e-300});

    // (cell, triangle) entries, grouped by cell.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
    entries.reserve(4 * tested.size());
    for (std::uint32_t t : tested) {
        const Cell lo = grid.cell_of(box[t].lo), hi = grid.cell_of(box[t].hi);
        for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
            for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
                for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
                    entries.emplace_back(Grid::key(x, y, z), t);
    }
    std::sort(entries.begin(), entries.end());
    std::vector<std::size_t> cell_start;
    for (std::size_t e = 0; e < entries.size(); ++e)
        if (e == 0 || entries[e].first != entries[e - 1].first) cell_start.push_back(e);
    cell_start.push_back(entries.size());

    // Cells in blocks, in parallel; a pair is tested only in the first cell both boxes share.
    const std::size_t cells = cell_start.size() - 1, block = 256;
    std::vector<std::vector<TrianglePair>> found((cells + block - 1) / block);
    parallel_for(exec, found.size(), [&](std::size_t b) {
        for (std::size_t c = b * block; c < std::min(cells, (b + 1) * block); ++c) {
            const std::uint64_t key = entries[cell_start[c]].first;
            for (std::size_t i = cell_start[c]; i < cell_start[c + 1]; ++i)
                for (std::size_t j = i + 1; j < cell_start[c + 1]; ++j) {
                    const std::uint32_t s = entries[i].second, t = entries[j].second;
                    if (!box[s].overlaps(box[t])) continue;
                    const Cell a = grid.cell_of(box[s].lo), d = grid.cell_of(box[t].lo);
                    if (Grid::key(std::max(a[0], d[0]), std::max(a[1], d[1]),
                                  std::max(a[2], d[2])) != key)
                        continue;
                    if (shared_vertices(w[s], w[t]) >= 2) continue;
                    if (vcg::tri::Clean<VcgMesh>::TestFaceFaceIntersection(&m.face[s], &m.face[t]))
                        found[b].emplace_back(std::min(s, t), std::max(s, t));
                }
        }
    });
    std::vector<TrianglePair> pairs;
    for (const auto& f : found) pairs.insert(pairs.end(), f.begin(), f.end());
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

} // namespace hrsr
