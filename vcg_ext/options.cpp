#include "options.h"

#include "errors.h"

#include <cmath>
#include <string>

namespace hrsr {

namespace {
void require(bool ok, const std::string& message) {
    if (!ok) throw InvalidOption(message);
}
} // namespace

void validate(const PreprocessOptions& o) {
    require(o.k >= 3 && o.k <= 1000,
            "k must be between 3 and 1000 (got " + std::to_string(o.k) + ")");
    require(std::isfinite(o.r) && o.r > 0,
            "r must be a positive number (got " + std::to_string(o.r) + ")");
    require(std::isfinite(o.theta_degrees) && o.theta_degrees > 0 && o.theta_degrees <= 180,
            "theta must be in (0, 180] degrees (got " + std::to_string(o.theta_degrees) + ")");
    require(o.k_normals == 0 || (o.k_normals >= 3 && o.k_normals <= 1000),
            "k-normals must be 0 (automatic) or between 3 and 1000 (got " +
                std::to_string(o.k_normals) + ")");
    require(o.k_smoothing == 0 || (o.k_smoothing >= 3 && o.k_smoothing <= 1000),
            "k-smoothing must be 0 (automatic) or between 3 and 1000 (got " +
                std::to_string(o.k_smoothing) + ")");
    require(o.min_component_size >= 1, "min-component-size must be at least 1 (got " +
                                           std::to_string(o.min_component_size) + ")");
}

void validate(const RsrOptions& o) {
    validate(o.preprocess);
    require(std::isfinite(o.min_handle_loop) && o.min_handle_loop >= 1 && o.min_handle_loop <= 1e6,
            "n (shortest handle loop, in point spacings) must be between 1 and 1e6 (got " +
                std::to_string(o.min_handle_loop) + ")");
    require(o.handles >= -1, "handles must be -1 (automatic), 0 (none) or a positive limit (got " +
                                 std::to_string(o.handles) + ")");
    require(o.fold_repair_rounds >= 0 && o.fold_repair_rounds <= 100,
            "fold-repair-rounds must be between 0 and 100 (got " +
                std::to_string(o.fold_repair_rounds) + ")");
}

void validate(const CollapseOptions& o) {
    require(std::isfinite(o.collapse_ratio) && o.collapse_ratio > 0 && o.collapse_ratio <= 1,
            "collapse-ratio must be in (0, 1] (got " + std::to_string(o.collapse_ratio) + ")");
    require(o.collapse_k >= 1 && o.collapse_k <= 100,
            "collapse-k must be between 1 and 100 (got " + std::to_string(o.collapse_k) + ")");
}

void validate(const ReexpandOptions& o) {
    require(std::isfinite(o.l_min) && o.l_min >= 0,
            "l-min must be 0 or a positive length (got " + std::to_string(o.l_min) + ")");
    require(o.refinement_iterations >= 0 && o.refinement_iterations <= 100,
            "refinement-iterations must be between 0 and 100");
    require(std::isfinite(o.min_angle_weight) && o.min_angle_weight >= 0,
            "min-angle-weight must be >= 0");
}

void validate(const ReconstructionOptions& o) {
    validate(o.rsr);
    validate(o.collapse);
    validate(o.reexpand);
    require(std::isfinite(o.l_min_percent) && o.l_min_percent >= 0 && o.l_min_percent <= 100,
            "l-min must be between 0% and 100% of the bounding-box diagonal (got " +
                std::to_string(o.l_min_percent) + "%)");
    require(o.l_min_percent == 0 || o.reexpand.l_min == 0,
            "give l-min either as a length or as a percentage");
}

} // namespace hrsr
