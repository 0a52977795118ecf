#include "preprocess/near_duplicates.h"

#include "preprocess/cell_hash.h"
#include "preprocess/near_screen.h"

#include <array>
#include <cmath>
#include <numeric>

namespace hrsr {

namespace {

using Cell = GridCell;
constexpr std::uint32_t kNone = ~0u;

// The representatives' cells, each with the head of its chain of representatives: open
// addressing with linear probing over a power-of-two table at most half full. A slot stores the
// head and the hash's high half; the cell itself is the head's, recomputed from its position (no
// copy of 24 bytes per point, no node per cell: the table is 8 bytes a slot, one cache line a
// probe).
class CellTable {
public:
    CellTable(const std::vector<Vec3>& positions, double width, std::size_t points)
        : positions_(positions), width_(width) {
        std::size_t capacity = 16;
        while (capacity < 2 * points) capacity *= 2;
        slots_.assign(capacity, {kNone, 0});
        mask_ = capacity - 1;
    }

    Cell cell_of(const Vec3& p) const {
        return {std::int64_t(std::floor(p[0] / width_)), std::int64_t(std::floor(p[1] / width_)),
                std::int64_t(std::floor(p[2] / width_))};
    }

    /// The head of the cell's chain, or kNone.
    std::uint32_t head(const Cell& c) const { return slots_[find(c, hash_of(c))].head; }

    /// Makes point i the head of its cell's chain; returns the previous head (or kNone).
    std::uint32_t push(const Cell& c, std::uint32_t i) {
        const std::uint64_t h = hash_of(c);
        Slot& slot = slots_[find(c, h)];
        const std::uint32_t previous = slot.head;
        slot = {i, std::uint32_t(h >> 32)};
        return previous;
    }

private:
    struct Slot {
        std::uint32_t head, tag;
    };

    // The cell's slot, or the empty slot where it would go (h: the cell's hash).
    std::size_t find(const Cell& c, std::uint64_t h) const {
        const std::uint32_t tag = std::uint32_t(h >> 32);
        for (std::size_t s = h & mask_;; s = (s + 1) & mask_) {
            const Slot& slot = slots_[s];
            if (slot.head == kNone || (slot.tag == tag && cell_of(positions_[slot.head]) == c))
                return s;
        }
    }

    const std::vector<Vec3>& positions_;
    double width_;
    std::vector<Slot> slots_;
    std::size_t mask_ = 0;
};

} // namespace

std::vector<std::uint32_t> near_duplicate_representatives(const std::vector<Vec3>& positions,
                                                          double tolerance, const Execution& exec) {
    const std::uint32_t n = std::uint32_t(positions.size());
    std::vector<std::uint32_t> representative(n);
    std::iota(representative.begin(), representative.end(), 0u);
    // Only the screened points can be merged or represent another one: a point within the
    // tolerance of any other point is screened with it, so they meet each other here in the
    // order given, as in a search over all points.
    const std::vector<std::uint32_t> screened = near_point_candidates(positions, tolerance, exec);
    // Representatives only, chained per cell: head of the cell -> next[...] -> ... -> kNone.
    std::vector<std::uint32_t> next(n, kNone);
    const double squared = tolerance * tolerance;
    // Cells twice the tolerance wide: a ball of radius `tolerance` then meets at most two cells
    // per axis, the point's own and the one on the side of the half it lies in (8 cells, not 27).
    // Nothing is missed: a pair the distance test accepts differs by at most `tolerance` on
    // every axis (the difference of two doubles that close is exact), and p / width, a correctly
    // rounded quotient, never rounds across a cell's middle the wrong way. Points within 1e-6
    // of the middle look on both sides anyway (cheap insurance).
    const double width = 2 * tolerance;
    CellTable cells(positions, width, screened.size());
    for (std::uint32_t i : screened) {
        const Vec3& p = positions[i];
        const Cell cell = cells.cell_of(p);
        std::array<std::int64_t, 3> low, high; // cell offsets to search, per axis
        for (int axis = 0; axis < 3; ++axis) {
            const double scaled = p[axis] / width;
            const double half = scaled - std::floor(scaled) - 0.5;
            low[axis] = half < 1e-6 ? -1 : 0;
            high[axis] = half > -1e-6 ? 1 : 0;
        }
        std::uint32_t best = kNone;
        for (std::int64_t a = low[0]; a <= high[0]; ++a)
            for (std::int64_t b = low[1]; b <= high[1]; ++b)
                for (std::int64_t c = low[2]; c <= high[2]; ++c)
                    for (std::uint32_t r = cells.head({cell[0] + a, cell[1] + b, cell[2] + c});
                         r != kNone; r = next[r])
                        if (r < best && (positions[r] - p).SquaredNorm() <= squared) best = r;
        representative[i] = best != kNone ? best : i;
        if (best == kNone) next[i] = cells.push(cell, i);
    }
    return representative;
}

} // namespace hrsr
