// How the mesh measures shared by `reconstruct` and `check` are shown (JSON and text).
#pragma once

#include "mesh/mesh_stats.h"

#include <nlohmann/json.hpp>

#include <string>

namespace hrsr::app {

/// The genus of every closed component, in component order, as a JSON array.
nlohmann::json genus_of_closed_components(const MeshStats& mesh);

/// The same as text: "0, 1", or "none" when no component is closed.
std::string genus_of_closed_components_text(const MeshStats& mesh);

} // namespace hrsr::app
