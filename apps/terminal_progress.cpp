#include "terminal_progress.h"

#include <cstdio>
#include <unistd.h>

namespace hrsr::app {

TerminalProgress::TerminalProgress(bool enabled) : active_(enabled && isatty(STDERR_FILENO)) {}

TerminalProgress::~TerminalProgress() {
    finish();
}

ProgressCallback TerminalProgress::callback() {
    return [this](const std::string& phase, double fraction) {
        draw(phase, fraction);
        return true;
    };
}

void TerminalProgress::draw(const std::string& phase, double fraction) {
    if (!active_) return;
    const int percent = int(fraction * 100.0);
    const auto now = std::chrono::steady_clock::now();
    // Redraw on a new phase, or at most ten times a second.
    if (phase == last_phase_ &&
        (percent == last_percent_ || now - last_draw_ < std::chrono::milliseconds(100)))
        return;
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\r\033[K%-22s [%.*s%*s] %3d%%", phase.c_str(), filled,
                 "##############################", kWidth - filled, "", percent);
    std::fflush(stderr);
    drawn_ = true;
    last_phase_ = phase;
    last_percent_ = percent;
    last_draw_ = now;
}

void TerminalProgress::finish() {
    if (!drawn_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
}

} // namespace hrsr::app
