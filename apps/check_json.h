// The JSON and text forms of a mesh check.
#pragma once

#include "mesh/check.h"

#include <nlohmann/json.hpp>

#include <string>

namespace hrsr::app {

nlohmann::json to_json(const MeshCheck& check);

/// The human-readable summary (several lines, each ending in a newline).
std::string summary(const std::string& mesh_path, const MeshCheck& check);

} // namespace hrsr::app
