#include "preprocess/near_duplicates.h"

#include <array>
#include <cmath>
#include <unordered_map>

namespace hrsr {

namespace {

using Cell = std::array<std::int64_t, 3>;

struct CellHash {
    std::size_t operator()(const Cell& c) const {
        std::uint64_t h = 1469598103934665603ull;
        for (std::int64_t v : c) h = (h ^ std::uint64_t(v)) * 1099511628211ull;
        return std::size_t(h);
    }
};

} // namespace

std::vector<std::uint32_t> near_duplicate_representatives(const std::vector<Vec3>& positions,
                                                          double tolerance) {
    const std::uint32_t n = std::uint32_t(positions.size());
    std::vector<std::uint32_t> representative(n);
    // Representatives only, chained per cell: head[cell] -> next[...] -> ... -> kNone.
    constexpr std::uint32_t kNone = ~0u;
    std::unordered_map<Cell, std::uint32_t, CellHash> head;
    head.reserve(n);
    std::vector<std::uint32_t> next(n, kNone);
    const double squared = tolerance * tolerance;
    // Cells twice the tolerance wide: a ball of radius `tolerance` then meets at most two cells
    // per axis, the point's own and the one on the side of the half it lies in (8 cells, not 27).
    // Nothing is missed: a pair the distance test accepts differs by at most `tolerance` on
    // every axis (the difference of two doubles that close is exact), and p / width, a correctly
    // rounded quotient, never rounds across a cell's middle the wrong way. Points within 1e-6
    // of the middle look on both sides anyway (cheap insurance).
    const double width = 2 * tolerance;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Vec3& p = positions[i];
        Cell cell;
        std::array<std::int64_t, 3> low, high; // cell offsets to search, per axis
        for (int axis = 0; axis < 3; ++axis) {
            const double scaled = p[axis] / width, floor = std::floor(scaled);
            const double half = scaled - floor - 0.5;
            cell[axis] = std::int64_t(floor);
            low[axis] = half < 1e-6 ? -1 : 0;
            high[axis] = half > -1e-6 ? 1 : 0;
        }
        std::uint32_t best = kNone;
        for (std::int64_t a = low[0]; a <= high[0]; ++a)
            for (std::int64_t b = low[1]; b <= high[1]; ++b)
                for (std::int64_t c = low[2]; c <= high[2]; ++c) {
                    const auto it = head.find({cell[0] + a, cell[1] + b, cell[2] + c});
                    if (it == head.end()) continue;
                    for (std::uint32_t r = it->second; r != kNone; r = next[r])
                        if (r < best && (positions[r] - p).SquaredNorm() <= squared) best = r;
                }
        if (best != kNone) {
            representative[i] = best;
            continue;
        }
        representative[i] = i;
        auto [it, inserted] = head.emplace(cell, i);
        if (!inserted) {
            next[i] = it->second;
            it->second = i;
        }
    }
    return representative;
}

} // namespace hrsr
