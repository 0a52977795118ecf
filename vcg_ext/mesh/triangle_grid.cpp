#include "mesh/triangle_grid.h"

#include <algorithm>

namespace hrsr {

TriangleGrid::TriangleGrid(const TriangleGeometry& g, const Execution& exec) {
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

std::vector<TrianglePair> TriangleGrid::all_pairs(const TriangleGeometry& g,
                                                  const Execution& exec) const {
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
            // Sweep along x: a member meets only those whose x range starts before its own ends.
            std::sort(members.begin(), members.end(), [](const Member& s, const Member& t) {
                return s.box.lo[0] < t.box.lo[0] || (s.box.lo[0] == t.box.lo[0] && s.face < t.face);
            });
            for (std::size_t i = 0; i < members.size(); ++i)
                for (std::size_t j = i + 1; j < members.size(); ++j) {
                    const Member &s = members[i], &t = members[j];
                    if (t.box.lo[0] > s.box.hi[0]) break;
                    if (!s.box.overlaps(t.box)) continue;
                    if (index(std::max(s.low[0], t.low[0]), std::max(s.low[1], t.low[1]),
                              std::max(s.low[2], t.low[2])) != here)
                        continue;
                    if (g.intersect_unboxed(g.triangle(s.face), g.triangle(t.face)))
                        found[b].emplace_back(std::min(s.face, t.face), std::max(s.face, t.face));
                }
        }
    });
    std::vector<TrianglePair> pairs;
    for (const auto& f : found) pairs.insert(pairs.end(), f.begin(), f.end());
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

// Entries come in face order; a stable radix sort on the cell (4 × 8 bits) leaves them sorted
// by (cell, face) as std::sort would, in a fraction of its time.
void TriangleGrid::sort_by_cell(std::vector<std::uint64_t>& entries) {
    std::vector<std::uint64_t> buffer(entries.size());
    for (int shift = 32; shift < 64; shift += 8) {
        std::array<std::size_t, 257> start{};
        for (std::uint64_t e : entries) ++start[((e >> shift) & 0xff) + 1];
        for (int d = 0; d < 256; ++d) start[std::size_t(d) + 1] += start[std::size_t(d)];
        for (std::uint64_t e : entries) buffer[start[(e >> shift) & 0xff]++] = e;
        entries.swap(buffer);
    }
}

} // namespace hrsr
