#include "spatial_order.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace hrsr {

namespace {

constexpr int kBitsPerAxis = 21; // 3 × 21 = 63 bits: one key a point
constexpr std::uint64_t kNonFinite = std::numeric_limits<std::uint64_t>::max(); // after all

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
// keys keep the order they came in.
void sort_by_key(std::vector<Keyed>& items) {
    std::vector<Keyed> buffer(items.size());
    for (int shift = 0; shift < 64; shift += 8) {
        std::array<std::size_t, 257> start{};
        for (const Keyed& k : items) ++start[((k.key >> shift) & 0xff) + 1];
        if (std::count(start.begin(), start.end(), items.size()) == 1) continue; // one byte value
        for (int d = 0; d < 256; ++d) start[std::size_t(d) + 1] += start[std::size_t(d)];
        for (const Keyed& k : items) buffer[start[(k.key >> shift) & 0xff]++] = k;
        items.swap(buffer);
    }
}

} // namespace

SpatialOrder spatial_order(const std::vector<Vec3>& positions, const Execution& exec) {
    Vec3 lo(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity());
    Vec3 hi = -lo;
    for (const Vec3& p : positions)
        if (finite(p))
            for (int k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], p[k]);
                hi[k] = std::max(hi[k], p[k]);
            }
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
    sort_by_key(items);
    SpatialOrder order;
    order.input_index.reserve(items.size());
    for (const Keyed& k : items) order.input_index.push_back(k.index);
    return order;
}

PointSet reordered(const PointSet& input, const SpatialOrder& order) {
    PointSet out;
    out.precision = input.precision;
    out.positions.reserve(input.size());
    for (std::uint32_t i : order.input_index) out.positions.push_back(input.positions[i]);
    if (input.normals.size() == input.size()) {
        out.normals.reserve(input.size());
        for (std::uint32_t i : order.input_index) out.normals.push_back(input.normals[i]);
    } else {
        out.normals = input.normals;
    }
    return out;
}

} // namespace hrsr
