// The JSON form of reports (`--report R.json`).
#pragma once

#include "preprocess/report.h"

#include <nlohmann/json.hpp>

#include <string>

namespace hrsr::app {

/// Everything pre-processing did: counts, per-point reasons, normals, smoothing, components,
/// warnings, timings. Indices are input point indices (0-based, in file order).
nlohmann::json to_json(const PreprocessReport& report);

/// Writes `document` (indented) through a temporary file and a rename. Throws hrsr::IoError.
void write_json(const std::string& path, const nlohmann::json& document);

} // namespace hrsr::app
