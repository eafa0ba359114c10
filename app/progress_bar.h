#pragma once
// A progress line on stderr for long jobs: samples done of total, rate, elapsed and time left.
// On a terminal it is redrawn in place (at most ten times a second); into a file or pipe it
// prints plain lines, one every tenth of the job or every ten seconds.
#include <chrono>
#include <string>

namespace woven {

class ProgressBar {
public:
    explicit ProgressBar(std::string unit);
    // fraction in [0, 1]; `status` follows the bar (counts, rate, times).
    void update(double fraction, const std::string& status);
    void finish();  // ends the redrawn line

private:
    std::string unit_;
    bool terminal_;
    bool drawn_ = false;
    double nextFraction_ = 0.0;
    std::chrono::steady_clock::time_point lastDraw_;
};

// "1:05", "1:02:03".
std::string formatDuration(double seconds);
// "950", "12.3k", "4.56M", "1.2G".
std::string formatCount(double value);

}  // namespace woven
