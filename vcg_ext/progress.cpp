#include "progress.h"

#include "errors.h"

#include <algorithm>

namespace hrsr {

void Progress::begin(const std::string& phase) {
    phase_ = phase;
    update(0.0);
}

void Progress::update(double fraction) {
    if (callback_ && !callback_(phase_, std::clamp(fraction, 0.0, 1.0))) throw Cancelled();
}

} // namespace hrsr
