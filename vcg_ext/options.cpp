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
    require(o.max_handle_hops >= 1, "n (max handle hops) must be at least 1 (got " +
                                        std::to_string(o.max_handle_hops) + ")");
    require(o.handles >= -1, "handles must be -1 (automatic), 0 (none) or a positive limit (got " +
                                 std::to_string(o.handles) + ")");
}

} // namespace hrsr
