#include "preprocess/near_screen.h"

#include "preprocess/cell_hash.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

namespace hrsr {

namespace {

using Cell = GridCell;

// Cells far wider than the tolerance, marked in two bit sets indexed by a hash of the cell: seen
// once, seen twice (a collision only adds points to the screen, never drops one). A point looks
// at its own cell and, only when it lies within the tolerance of a face, at the cells beyond.
class CellMarks {
public:
    CellMarks(std::size_t points, double tolerance) : tolerance_(tolerance) {
        std::size_t bits = 1024;
        while (bits < 16 * points) bits *= 2; // about one point in 16 collides
        once_ = std::vector<std::atomic<std::uint64_t>>(bits / 64);
        twice_ = std::vector<std::atomic<std::uint64_t>>(bits / 64);
        mask_ = bits - 1;
        // A million tolerances: a cell holds about one point of any real cloud (D-25's
        // tolerance is 1e-11 of the diagonal), and few points lie near a face.
        width_ = 1e6 * tolerance;
    }

    Cell cell_of(const Vec3& p) const {
        return {std::int64_t(std::floor(p[0] / width_)), std::int64_t(std::floor(p[1] / width_)),
                std::int64_t(std::floor(p[2] / width_))};
    }

    void mark(const Vec3& p) {
        const std::uint64_t b = hash_of(cell_of(p)) & mask_, bit = 1ull << (b % 64);
        if (once_[b / 64].fetch_or(bit, std::memory_order_relaxed) & bit)
            twice_[b / 64].fetch_or(bit, std::memory_order_relaxed);
    }

    /// Whether p's cell index is far from the range where the quotient and the margin below
    /// are exact enough (then nothing is screened out).
    bool too_far(const Vec3& p) const {
        for (int axis = 0; axis < 3; ++axis)
            if (!(std::abs(p[axis] / width_) < 0x1p40)) return true;
        return false;
    }

    /// Whether a point other than p may lie within the tolerance of p.
    bool crowded(const Vec3& p) const {
        const Cell cell = cell_of(p);
        std::array<std::int64_t, 3> low, high; // cells beyond a near face, per axis
        for (int axis = 0; axis < 3; ++axis) {
            // The position in the cell, in cell widths; the margin (twice the tolerance and more
            // than the quotients' rounding) keeps every partner in a cell looked at.
            const double scaled = p[axis] / width_, in_cell = scaled - std::floor(scaled);
            const double margin = 2 * tolerance_ / width_ + 1e-9 +
                                  8 * std::numeric_limits<double>::epsilon() * std::abs(scaled);
            low[axis] = in_cell < margin ? -1 : 0;
            high[axis] = in_cell > 1 - margin ? 1 : 0;
        }
        for (std::int64_t a = low[0]; a <= high[0]; ++a)
            for (std::int64_t b = low[1]; b <= high[1]; ++b)
                for (std::int64_t c = low[2]; c <= high[2]; ++c) {
                    const bool own = a == 0 && b == 0 && c == 0;
                    const std::uint64_t h =
                        hash_of({cell[0] + a, cell[1] + b, cell[2] + c}) & mask_;
                    const auto& marks = own ? twice_ : once_; // p itself marked its own cell
                    if (marks[h / 64].load(std::memory_order_relaxed) >> (h % 64) & 1) return true;
                }
        return false;
    }

private:
    double tolerance_, width_ = 0;
    std::vector<std::atomic<std::uint64_t>> once_, twice_;
    std::uint64_t mask_ = 0;
};

} // namespace

std::vector<std::uint32_t> near_point_candidates(const std::vector<Vec3>& positions,
                                                 double tolerance, const Execution& exec) {
    const std::size_t n = positions.size();
    CellMarks marks(n, tolerance);
    std::vector<std::uint8_t> too_far(block_count(n, kCheapBlock), 0);
    parallel_for_blocks(exec, n, kCheapBlock,
                        [&](std::size_t b, std::size_t first, std::size_t end) {
                            for (std::size_t i = first; i < end; ++i) {
                                if (marks.too_far(positions[i])) {
                                    too_far[b] = 1;
                                    return;
                                }
                                marks.mark(positions[i]);
                            }
                        });
    std::vector<std::uint32_t> all;
    if (std::count(too_far.begin(), too_far.end(), 1) > 0) { // every point, unscreened
        for (std::uint32_t i = 0; i < n; ++i) all.push_back(i);
        return all;
    }
    std::vector<std::vector<std::uint32_t>> found(block_count(n, kCheapBlock));
    parallel_for_blocks(exec, n, kCheapBlock,
                        [&](std::size_t b, std::size_t first, std::size_t end) {
                            for (std::size_t i = first; i < end; ++i)
                                if (marks.crowded(positions[i]))
                                    found[b].push_back(std::uint32_t(i));
                        });
    for (const std::vector<std::uint32_t>& f : found) all.insert(all.end(), f.begin(), f.end());
    return all;
}

} // namespace hrsr
