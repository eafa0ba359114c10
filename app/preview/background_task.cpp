#include "background_task.h"

namespace woven {

BackgroundTask::~BackgroundTask() { cancel(); }

void BackgroundTask::start(std::function<void(const std::atomic<bool>& cancel)> work) {
    cancel();
    cancel_ = false;
    running_ = true;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        error_.clear();
    }
    worker_ = std::thread([this, work = std::move(work)] {
        try {
            work(cancel_);
        } catch (const std::exception& e) {
            std::lock_guard<std::mutex> lock(mutex_);
            error_ = e.what();
        }
        running_ = false;
    });
}

void BackgroundTask::cancel() {
    cancel_ = true;
    wait();
}

void BackgroundTask::wait() {
    if (worker_.joinable()) worker_.join();
}

std::string BackgroundTask::error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
}

}  // namespace woven
