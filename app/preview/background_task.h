#pragma once
// Work on a thread of its own, so that the window stays responsive while it runs: one at a time,
// cancellable through a flag the work polls, and its failure kept as a message. The Render
// button's FinalRender and the Fit section's FitJob run theirs on it.
#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace woven {

class BackgroundTask {
public:
    BackgroundTask() = default;
    ~BackgroundTask();  // cancels and waits
    BackgroundTask(const BackgroundTask&) = delete;
    BackgroundTask& operator=(const BackgroundTask&) = delete;

    // Cancels and waits for the work before, then runs `work` with the cancel flag; what it
    // throws becomes error().
    void start(std::function<void(const std::atomic<bool>& cancel)> work);
    void cancel();
    // Blocks until the work has finished (or was cancelled).
    void wait();

    bool running() const { return running_; }
    std::string error() const;  // why the last work failed, empty if it did not

private:
    std::thread worker_;
    std::atomic<bool> cancel_{false}, running_{false};
    mutable std::mutex mutex_;
    std::string error_;
};

}  // namespace woven
