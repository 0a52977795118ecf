#include "preprocess/report.h"

#include <algorithm>

namespace hrsr {

const char* to_string(PointFate fate) {
    switch (fate) {
    case PointFate::Kept:
        return "kept";
    case PointFate::NonFinite:
        return "non_finite";
    case PointFate::Duplicate:
        return "duplicate";
    case PointFate::NoNormal:
        return "no_normal";
    case PointFate::SmallComponent:
        return "small_component";
    }
    return "unknown";
}

std::size_t PreprocessReport::count(PointFate f) const {
    return std::size_t(std::count(fate.begin(), fate.end(), f));
}

} // namespace hrsr
