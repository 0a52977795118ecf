// A one-line progress bar on stderr, drawn only when stderr is a terminal.
#pragma once

#include "progress.h"

#include <chrono>
#include <string>

namespace hrsr::app {

class TerminalProgress {
public:
    /// Draws nothing when `enabled` is false or stderr is not a terminal.
    explicit TerminalProgress(bool enabled);
    ~TerminalProgress();
    /// The callback to hand to hrsr::Progress.
    ProgressCallback callback();
    /// Clears the bar (before printing anything else).
    void finish();

private:
    void draw(const std::string& phase, double fraction);
    bool active_;
    bool drawn_ = false;
    std::string last_phase_;
    int last_percent_ = -1;
    std::chrono::steady_clock::time_point last_draw_{};
};

} // namespace hrsr::app
