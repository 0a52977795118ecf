#include "options.h"

#include "errors.h"

#include <cmath>
#include <string>

namespace hrsr {

namespace {
void require(bool ok, OptionId option, const std::string& problem) {
    if (!ok) throw InvalidOption(option, problem);
}
std::string got(double x) {
    return " (got " + std::to_string(x) + ")";
}
std::string got(int x) {
    return " (got " + std::to_string(x) + ")";
}
} // namespace

const char* option_name(OptionId option) {
    switch (option) {
    case OptionId::K:
        return "k";
    case OptionId::R:
        return "r";
    case OptionId::Theta:
        return "theta";
    case OptionId::KNormals:
        return "k_normals";
    case OptionId::KSmoothing:
        return "k_smoothing";
    case OptionId::MinComponentSize:
        return "min_component_size";
    case OptionId::MinHandleLoop:
        return "n";
    case OptionId::Handles:
        return "handles";
    case OptionId::FoldRepairRounds:
        return "fold_repair_rounds";
    case OptionId::CollapseRatio:
        return "collapse_ratio";
    case OptionId::CollapseK:
        return "collapse_k";
    case OptionId::LMin:
        return "l_min";
    case OptionId::RefinementIterations:
        return "refinement_iterations";
    case OptionId::Output:
        return "output";
    }
    return "an option";
}

void validate(const PreprocessOptions& o) {
    require(o.k >= 3 && o.k <= 1000, OptionId::K, "must be between 3 and 1000" + got(o.k));
    require(std::isfinite(o.r) && o.r > 0, OptionId::R, "must be a positive number" + got(o.r));
    require(std::isfinite(o.theta_degrees) && o.theta_degrees > 0 && o.theta_degrees <= 180,
            OptionId::Theta, "must be in (0, 180] degrees" + got(o.theta_degrees));
    require(o.k_normals == 0 || (o.k_normals >= 3 && o.k_normals <= 1000), OptionId::KNormals,
            "must be 0 (automatic) or between 3 and 1000" + got(o.k_normals));
    require(o.k_smoothing == 0 || (o.k_smoothing >= 3 && o.k_smoothing <= 1000),
            OptionId::KSmoothing,
            "must be 0 (automatic) or between 3 and 1000" + got(o.k_smoothing));
    require(o.min_component_size >= 1, OptionId::MinComponentSize,
            "must be at least 1" + got(o.min_component_size));
}

void validate(const RsrOptions& o) {
    validate(o.preprocess);
    require(std::isfinite(o.min_handle_loop) && o.min_handle_loop >= 1 && o.min_handle_loop <= 1e6,
            OptionId::MinHandleLoop,
            "(shortest handle loop, in point spacings) must be between 1 and 1e6" +
                got(o.min_handle_loop));
    require(o.handles >= -1, OptionId::Handles,
            "must be -1 (automatic), 0 (none) or a positive limit" + got(o.handles));
    require(o.fold_repair_rounds >= 0 && o.fold_repair_rounds <= 100, OptionId::FoldRepairRounds,
            "must be between 0 and 100" + got(o.fold_repair_rounds));
}

void validate(const CollapseOptions& o) {
    require(std::isfinite(o.collapse_ratio) && o.collapse_ratio > 0 && o.collapse_ratio <= 1,
            OptionId::CollapseRatio, "must be in (0, 1]" + got(o.collapse_ratio));
    require(o.collapse_k >= 1 && o.collapse_k <= 100, OptionId::CollapseK,
            "must be between 1 and 100" + got(o.collapse_k));
}

void validate(const ReexpandOptions& o) {
    require(std::isfinite(o.l_min) && o.l_min >= 0, OptionId::LMin,
            "must be 0 or a positive length" + got(o.l_min));
    require(o.refinement_iterations >= 0 && o.refinement_iterations <= 100,
            OptionId::RefinementIterations,
            "must be between 0 and 100" + got(o.refinement_iterations));
}

void validate(const ReconstructionOptions& o) {
    validate(o.rsr);
    validate(o.collapse);
    validate(o.reexpand);
    require(std::isfinite(o.l_min_percent) && o.l_min_percent >= 0 && o.l_min_percent <= 100,
            OptionId::LMin,
            "must be between 0% and 100% of the bounding-box diagonal (got " +
                std::to_string(o.l_min_percent) + "%)");
    require(o.l_min_percent == 0 || o.reexpand.l_min == 0, OptionId::LMin,
            "must be given either as a length or as a percentage");
}

} // namespace hrsr
