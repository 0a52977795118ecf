// The integer cells of a uniform grid and their hash, shared by D-25's near-duplicate search
// and its parallel screen.
#pragma once

#include <array>
#include <cstdint>

namespace hrsr {

using GridCell = std::array<std::int64_t, 3>;

/// FNV-1a over the three indices, then splitmix64's finaliser: hash tables take the low bits,
/// which FNV alone leaves weak.
inline std::uint64_t hash_of(const GridCell& c) {
    std::uint64_t h = 1469598103934665603ull;
    for (std::int64_t v : c) h = (h ^ std::uint64_t(v)) * 1099511628211ull;
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
}

} // namespace hrsr
