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
    require(o.min_component_size >= 1, "min-component-size must be at least 1 (got " +
                                           std::to_string(o.min_component_size) + ")");
}

} // namespace hrsr
