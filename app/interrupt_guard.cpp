#include "interrupt_guard.h"

namespace woven {

namespace {

std::atomic<bool> flag{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");
extern "C" void onInterrupt(int) { flag.store(true); }

}  // namespace

const std::atomic<bool>& interrupted() { return flag; }

InterruptGuard::InterruptGuard() {
    flag.store(false);
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_);
}

InterruptGuard::~InterruptGuard() { sigaction(SIGINT, &previous_, nullptr); }

}  // namespace woven
