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

/// The largest component's faces, genus and boundary loops (null for an empty mesh).
nlohmann::json largest_component_json(const MeshStats& mesh);

/// The same as text: "largest: 40654 triangles, genus 2, 51 boundary loops" ("" when empty).
std::string largest_component_text(const MeshStats& mesh);

} // namespace hrsr::app
