#include "mesh/triangle_grid.h"

#include "mesh/embedded_fans.h"
#include "radix_pass.h"

#include <algorithm>
#include <utility>

namespace hrsr {

TriangleGrid::TriangleGrid(const TriangleGeometry& g, const Execution& exec) {
    // The loops report no progress (the search below reports the fraction); the calls between
    // them are chances to cancel.
    const Execution quiet = without_progress(exec);
    const auto cancel_point = [&] {
        if (exec.progress) exec.progress->update(0.0);
    };
    size_cells(g, quiet);
    cancel_point();
    file_faces(g, quiet);
    cancel_point();
    sort_by_cell(entries_, quiet);
    cancel_point();
    for (std::size_t e = 0; e < entries_.size(); ++e)
        if (e == 0 || cell(entries_[e]) != cell(entries_[e - 1]))
            cell_start_.push_back(std::uint32_t(e));
    cell_start_.push_back(std::uint32_t(entries_.size()));
}

// The boxes in parallel blocks; their extents are summed in face order, so that the cell size
// (hence every result) does not depend on the thread count.
void TriangleGrid::size_cells(const TriangleGeometry& g, const Execution& exec) {
    const std::size_t n = g.size();
    std::vector<double> extent(n);
    std::vector<Box> block_box(block_count(n, kCheapBlock));
    parallel_for_blocks(exec, n, kCheapBlock,
                        [&](std::size_t b, std::size_t first, std::size_t end) {
                            Box all = g.box(g.triangle(std::uint32_t(first)));
                            for (std::size_t f = first; f < end; ++f) {
                                const Box box = g.box(g.triangle(std::uint32_t(f)));
                                all.add(box.lo);
                                all.add(box.hi);
                                const Vec3 d = box.hi - box.lo;
                                extent[f] = std::max(d[0], std::max(d[1], d[2]));
                            }
                            block_box[b] = all;
                        });
    Box all = block_box[0];
    for (const Box& b : block_box) {
        all.add(b.lo);
        all.add(b.hi);
    }
    double extent_sum = 0;
    for (double e : extent) extent_sum += e;
    origin_ = all.lo;
    const Vec3 size = all.hi - all.lo;
    const double largest = std::max(size[0], std::max(size[1], size[2]));
    // At most kMaxCellsPerAxis cells a side, so that a cell's index fits in 32 bits.
    cell_ = std::max({2.0 * extent_sum / double(n), largest / kMaxCellsPerAxis, 1e-300});
    for (int k = 0; k < 3; ++k) cells_[k] = std::uint64_t(size[k] / cell_) + 1;
}

// Every non-degenerate face under each cell its box covers, in face order and each face's cells
// in for_each_cell's order: blocks of faces file theirs in parallel (one pass over the
// positions, the degeneracy test included), then the blocks' entries are joined in order.
void TriangleGrid::file_faces(const TriangleGeometry& g, const Execution& exec) {
    const std::size_t n = g.size();
    std::vector<std::vector<std::uint64_t>> filed(block_count(n, kCheapBlock));
    parallel_for_blocks(
        exec, n, kCheapBlock, [&](std::size_t b, std::size_t first, std::size_t end) {
            for (std::size_t f = first; f < end; ++f) {
                const Triangle& t = g.triangle(std::uint32_t(f));
                if (!g.degenerate(t))
                    for_each_cell(g.box(t),
                                  [&](std::uint64_t c) { filed[b].push_back(c << 32 | f); });
            }
        });
    std::vector<std::size_t> start(filed.size() + 1, 0);
    for (std::size_t b = 0; b < filed.size(); ++b) start[b + 1] = start[b] + filed[b].size();
    entries_.resize(start.back());
    parallel_for(
        exec, filed.size(),
        [&](std::size_t b) {
            std::copy(filed[b].begin(), filed[b].end(),
                      entries_.begin() + std::ptrdiff_t(start[b]));
            std::vector<std::uint64_t>().swap(filed[b]);
        },
        1);
}

std::vector<TrianglePair> TriangleGrid::all_pairs(const TriangleGeometry& g,
                                                  const Execution& exec) const {
    return all_pairs(g, embedded_fans(g, exec), exec);
}

std::vector<TrianglePair> TriangleGrid::all_pairs(const TriangleGeometry& g,
                                                  const std::vector<std::uint8_t>& embedded_fan,
                                                  const Execution& exec) const {
    const std::size_t cells = cell_start_.size() - 1, block = 256;
    std::vector<std::vector<TrianglePair>> found((cells + block - 1) / block);
    parallel_for(exec, found.size(), [&](std::size_t b) {
        thread_local CellMembers members;
        for (std::size_t c = b * block; c < std::min(cells, (b + 1) * block); ++c) {
            members.clear();
            for (std::size_t e = cell_start_[c]; e < cell_start_[c + 1]; ++e) {
                const std::uint32_t f = face(entries_[e]);
                const Box box = g.box(g.triangle(f));
                members.add(f, box, cell_of(box.lo));
            }
            // A pair is tested in the first cell both boxes cover only: the cell of the larger
            // low corner on each axis.
            const std::uint64_t here = cell(entries_[cell_start_[c]]);
            members.for_each_overlapping_pair([&](std::size_t s, std::size_t t) {
                if (index(std::max(members.corner_cell[s][0], members.corner_cell[t][0]),
                          std::max(members.corner_cell[s][1], members.corner_cell[t][1]),
                          std::max(members.corner_cell[s][2], members.corner_cell[t][2])) != here)
                    return;
                const std::uint32_t fs = members.face[s], ft = members.face[t];
                const Triangle &ts = g.triangle(fs), &tt = g.triangle(ft);
                if (!share_embedded_fan(ts, tt, embedded_fan) && g.intersect_unboxed(ts, tt))
                    found[b].emplace_back(std::min(fs, ft), std::max(fs, ft));
            });
        }
    });
    std::vector<TrianglePair> pairs;
    for (const auto& f : found) pairs.insert(pairs.end(), f.begin(), f.end());
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

void TriangleGrid::CellMembers::clear() {
    face.clear();
    corner_cell.clear();
    for (auto& bound : lo) bound.clear();
    for (auto& bound : hi) bound.clear();
}

void TriangleGrid::CellMembers::add(std::uint32_t f, const Box& box, const Cell& cell_of_lo) {
    face.push_back(f);
    corner_cell.push_back(cell_of_lo);
    for (int k = 0; k < 3; ++k) {
        lo[k].push_back(box.lo[k]);
        hi[k].push_back(box.hi[k]);
    }
}

// Entries come in face order; a stable radix sort on the cell (4 × 8 bits) leaves them sorted
// by (cell, face) as std::sort would, in a fraction of its time, for any thread count.
void TriangleGrid::sort_by_cell(std::vector<std::uint64_t>& entries, const Execution& exec) {
    std::vector<std::uint64_t> buffer;
    for (int shift = 32; shift < 64; shift += 8)
        stable_radix_pass(
            entries, buffer, [shift](std::uint64_t e) { return std::size_t(e >> shift) & 0xff; },
            exec);
}

} // namespace hrsr
