#include "mesh/welding.h"

#include "radix_pass.h"

#include <algorithm>
#include <cstring>
#include <tuple>

namespace hrsr {

namespace {

// A 32-bit hash of a position's coordinates, equal for equal positions (−0 is taken as +0).
std::uint32_t position_hash(const Vec3& p) {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int k = 0; k < 3; ++k) {
        const double c = p[k] + 0.0; // −0 + 0 = +0
        std::uint64_t bits;
        std::memcpy(&bits, &c, sizeof bits);
        h = (h ^ bits) * 0xbf58476d1ce4e5b9ull;
        h ^= h >> 31;
    }
    h *= 0x94d049bb133111ebull;
    return std::uint32_t(h >> 32);
}

} // namespace

std::vector<std::uint32_t> same_position_representatives(const std::vector<Vec3>& p) {
    return same_position_representatives(p, Execution{1, nullptr});
}

std::vector<std::uint32_t> same_position_representatives(const std::vector<Vec3>& p,
                                                         const Execution& exec) {
    // Vertices by the hash of their position (a stable radix sort of hash << 32 | index: the
    // indices rise within a hash), so that equal positions lie in one run of equal hashes, where
    // they are compared exactly; nearly every run is one vertex, whose position is not read
    // again. A comparison sort by position took 0.09 s of the lion's fold search.
    const Execution quiet = without_progress(exec);
    const std::size_t n = p.size();
    std::vector<std::uint64_t> entries(n);
    parallel_for_blocks(quiet, n, kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t i = first; i < end; ++i)
                                entries[i] = std::uint64_t(position_hash(p[i])) << 32 | i;
                        });
    std::vector<std::uint64_t> buffer;
    for (int shift = 32; shift < 64; shift += 8)
        stable_radix_pass(
            entries, buffer, [shift](std::uint64_t e) { return std::size_t(e >> shift) & 0xff; },
            quiet);
    std::vector<std::uint32_t> representative(n);
    std::vector<std::uint32_t> run;
    for (std::size_t s = 0; s < n;) {
        std::size_t e = s + 1;
        while (e < n && entries[e] >> 32 == entries[s] >> 32) ++e;
        if (e == s + 1) {
            representative[std::uint32_t(entries[s])] = std::uint32_t(entries[s]);
        } else {
            // (position, index) order: each position's first vertex is its smallest index.
            run.clear();
            for (std::size_t r = s; r < e; ++r) run.push_back(std::uint32_t(entries[r]));
            std::sort(run.begin(), run.end(), [&](std::uint32_t a, std::uint32_t b) {
                return std::tie(p[a][0], p[a][1], p[a][2], a) <
                       std::tie(p[b][0], p[b][1], p[b][2], b);
            });
            for (std::size_t r = 0; r < run.size(); ++r) {
                const Vec3 &a = p[run[r]], &b = p[run[r > 0 ? r - 1 : 0]];
                const bool same = r > 0 && a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
                representative[run[r]] = same ? representative[run[r - 1]] : run[r];
            }
        }
        s = e;
    }
    return representative;
}

std::vector<Triangle> welded_triangles(const std::vector<Triangle>& triangles,
                                       const std::vector<std::uint32_t>& representative) {
    return welded_triangles(triangles, representative, Execution{1, nullptr});
}

std::vector<Triangle> welded_triangles(const std::vector<Triangle>& triangles,
                                       const std::vector<std::uint32_t>& representative,
                                       const Execution& exec) {
    std::vector<Triangle> w(triangles.size());
    parallel_for_blocks(without_progress(exec), triangles.size(), kCheapBlock,
                        [&](std::size_t, std::size_t first, std::size_t end) {
                            for (std::size_t t = first; t < end; ++t)
                                for (int k = 0; k < 3; ++k)
                                    w[t][k] = representative[triangles[t][k]];
                        });
    return w;
}

} // namespace hrsr
