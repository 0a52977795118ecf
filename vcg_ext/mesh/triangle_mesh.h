// An indexed triangle mesh (no positions: vertices are referred to by index).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace hrsr {

using Triangle = std::array<std::uint32_t, 3>;

} // namespace hrsr
