#include "progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace woven {

std::string formatDuration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0) return "?";
    char buffer[32];
    // Beyond about three years hours and minutes mean nothing (and 1e300 s overflows a long).
    if (seconds >= 1e8) {
        std::snprintf(buffer, sizeof buffer, "%.3g s", seconds);
        return buffer;
    }
    const long s = std::lround(seconds);
    if (s >= 3600) std::snprintf(buffer, sizeof buffer, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
    else std::snprintf(buffer, sizeof buffer, "%ld:%02ld", s / 60, s % 60);
    return buffer;
}

std::string formatCount(double value) {
    const char* suffix[] = {"", "k", "M", "G", "T"};
    int i = 0;
    while (std::abs(value) >= 1000.0 && i < 4) {
        value /= 1000.0;
        ++i;
    }
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, i == 0 ? "%.0f%s" : "%.3g%s", value, suffix[i]);
    return buffer;
}

ProgressBar::ProgressBar(std::string unit) : unit_(std::move(unit)), terminal_(isatty(STDERR_FILENO) == 1) {}

void ProgressBar::update(double fraction, const std::string& status) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    const auto now = std::chrono::steady_clock::now();
    if (terminal_) {
        if (drawn_ && fraction < 1.0 && now - lastDraw_ < std::chrono::milliseconds(100)) return;
        constexpr int kWidth = 30;
        const int filled = int(fraction * kWidth);
        std::string bar(size_t(filled), '=');
        if (filled < kWidth) bar += '>' + std::string(size_t(kWidth - filled - 1), ' ');
        std::cerr << "\r\033[K" << unit_ << " [" << bar << "] " << status << std::flush;
        drawn_ = true;
    } else {
        if (fraction < nextFraction_ && drawn_ && now - lastDraw_ < std::chrono::seconds(10)) return;
        std::cerr << unit_ << ": " << status << "\n" << std::flush;
        nextFraction_ = std::floor(fraction * 10.0 + 1.0) / 10.0;
        drawn_ = true;
    }
    lastDraw_ = now;
}

void ProgressBar::finish() {
    if (terminal_ && drawn_) std::cerr << "\n";
    drawn_ = false;
}

}  // namespace woven
