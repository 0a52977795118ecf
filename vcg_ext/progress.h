// Progress reporting and cancellation (CGAL's contract: a callback that returns false cancels).
#pragma once

#include <functional>
#include <string>

namespace hrsr {

/// Receives the current phase name and the fraction done in that phase, in [0, 1].
/// Returning false asks the algorithm to stop; it then throws hrsr::Cancelled and leaves the
/// caller's data untouched. The callback is only ever invoked from the thread that called the
/// algorithm (MeshLab requires its progress bar to be updated from the main thread).
using ProgressCallback = std::function<bool(const std::string& phase, double fraction)>;

class Progress {
public:
    Progress() = default;
    explicit Progress(ProgressCallback callback) : callback_(std::move(callback)) {}

    /// Starts a phase (reports fraction 0).
    void begin(const std::string& phase);
    /// Reports the fraction done in the current phase; throws Cancelled when asked to stop.
    void update(double fraction);
    const std::string& phase() const { return phase_; }

private:
    ProgressCallback callback_;
    std::string phase_;
};

} // namespace hrsr
