#include "spatial_order.h"

#include "radix_pass.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace hrsr {

namespace {

constexpr int kBitsPerAxis = 21; // 3 × 21 = 63 bits: one key a point
constexpr std::uint64_t kNonFinite = std::numeric_limits<std::uint64_t>::max(); // after all
constexpr double kOutlierFraction = 0.001; // order statistics of the central extent, each side
constexpr double kOutlierMargin = 0.5;     // of the central extent, beyond which points are clamped

// The low 21 bits of x, two zero bits after each (x's bit k goes to bit 3k).
std::uint64_t spread(std::uint64_t x) {
    x &= (std::uint64_t(1) << kBitsPerAxis) - 1;
    x = (x | x << 32) & 0x1f00000000ffffULL;
    x = (x | x << 16) & 0x1f0000ff0000ffULL;
    x = (x | x << 8) & 0x100f00f00f00f00fULL;
    x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
    x = (x | x << 2) & 0x1249249249249249ULL;
    return x;
}

bool finite(const Vec3& p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

struct Keyed {
    std::uint64_t key;
    std::uint32_t index;
};

// A stable radix sort on the key, a byte at a time (bytes all points share are skipped): equal
// keys keep the order they came in, for any thread count.
void sort_by_key(std::vector<Keyed>& items, const Execution& exec) {
    std::vector<Keyed> buffer;
    for (int shift = 0; shift < 64; shift += 8)
        stable_radix_pass(
            items, buffer, [shift](const Keyed& k) { return std::size_t(k.key >> shift) & 0xff; },
            exec);
}

// The box the curve spans: the finite points' bounding box, cut down on an axis where points lie
// more than half the central extent (the 0.1 % to 99.9 % order statistics) beyond it. A few far
// outliers, clamped into the outermost cells, then do not coarsen the cells of everything else.
// The axes in parallel (each its own copy of the coordinates: exact order statistics).
void central_box(const std::vector<Vec3>& positions, Vec3& lo, Vec3& hi, const Execution& exec) {
    parallel_for(
        exec, 3,
        [&](std::size_t k) {
            std::vector<double> values;
            values.reserve(positions.size());
            for (const Vec3& p : positions)
                if (finite(p)) values.push_back(p[k]);
            if (values.empty()) {
                lo[k] = hi[k] = 0;
                return;
            }
            const auto [min, max] = std::minmax_element(values.begin(), values.end());
            lo[k] = *min;
            hi[k] = *max;
            const auto last = double(values.size() - 1);
            const auto low = values.begin() + std::ptrdiff_t(std::floor(kOutlierFraction * last));
            const auto high =
                values.begin() + std::ptrdiff_t(std::ceil((1 - kOutlierFraction) * last));
            std::nth_element(values.begin(), low, values.end());
            const double central_lo = *low;
            std::nth_element(values.begin(), high, values.end());
            const double central_hi = *high, margin = kOutlierMargin * (central_hi - central_lo);
            lo[k] = std::max(lo[k], central_lo - margin);
            hi[k] = std::min(hi[k], central_hi + margin);
        },
        1);
}

// Points that share a cell (the key) follow their exact coordinates, then the input order (only
// exact duplicates tie there): no order of the file survives but that of identical points.
void order_within_cells(const std::vector<Vec3>& positions, std::vector<Keyed>& items) {
    const auto by_position = [&](const Keyed& a, const Keyed& b) {
        const Vec3 &p = positions[a.index], &q = positions[b.index];
        for (int k = 0; k < 3; ++k)
            if (p[k] != q[k]) return p[k] < q[k];
        return a.index < b.index;
    };
    for (std::size_t begin = 0, end = 0; begin < items.size(); begin = end) {
        end = begin + 1;
        while (end < items.size() && items[end].key == items[begin].key) ++end;
        if (end - begin > 1 && items[begin].key != kNonFinite) // NaN has no order: input order
            std::sort(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(end),
                      by_position);
    }
}

} // namespace

SpatialOrder spatial_order(const std::vector<Vec3>& positions, const Execution& exec) {
    Vec3 lo, hi;
    central_box(positions, lo, hi, exec);
    const double side = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 0.0});
    const double cells = double((std::uint64_t(1) << kBitsPerAxis) - 1);
    const double scale = side > 0 && std::isfinite(side) ? cells / side : 0.0;
    std::vector<Keyed> items(positions.size());
    parallel_for(exec, positions.size(), [&](std::size_t i) {
        const Vec3& p = positions[i];
        std::uint64_t key = kNonFinite;
        if (finite(p)) {
            key = 0;
            for (int k = 0; k < 3; ++k) {
                const double cell = std::min(cells, std::max(0.0, (p[k] - lo[k]) * scale));
                key |= spread(std::uint64_t(cell)) << k;
            }
        }
        items[i] = {key, std::uint32_t(i)};
    });
    sort_by_key(items, exec);
    order_within_cells(positions, items);
    SpatialOrder order;
    order.input_index.resize(items.size());
    parallel_for_blocks(exec, items.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t i = first; i < end; ++i)
                                order.input_index[i] = items[i].index;
                        });
    return order;
}

PointSet reordered(const PointSet& input, const SpatialOrder& order, const Execution& exec) {
    PointSet out;
    out.precision = input.precision;
    const std::vector<std::uint32_t>& from = order.input_index;
    out.positions.resize(from.size());
    const bool normals = input.normals.size() == input.size();
    if (normals)
        out.normals.resize(from.size());
    else
        out.normals = input.normals;
    parallel_for_blocks(exec, from.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t i = first; i < end; ++i) {
                                out.positions[i] = input.positions[from[i]];
                                if (normals) out.normals[i] = input.normals[from[i]];
                            }
                        });
    return out;
}

} // namespace hrsr
