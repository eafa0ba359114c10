#pragma once
// Ctrl-C for a command that stops cleanly and writes what it has (`woven render` its partial
// frame, `woven fit` its best fit so far): while an InterruptGuard lives, SIGINT sets
// interrupted() instead of ending the process. The handler resets itself, so a second Ctrl-C
// ends the process at once.
#include <atomic>
#include <csignal>

namespace woven {

const std::atomic<bool>& interrupted();

class InterruptGuard {
public:
    InterruptGuard();  // clears the flag
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    struct sigaction previous_ {};
};

}  // namespace woven
