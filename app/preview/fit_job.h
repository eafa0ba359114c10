#pragma once
// The panel's Fit button's job: `woven fit` (core/fit, docs/FIT.md) of shot files on a
// background thread (background_task.h), so the window stays responsive while it renders the candidates. The window
// polls its progress and the loss so far, may cancel (the best fit so far is kept, as Ctrl-C
// keeps it for the command), and takes the result once.
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "background_task.h"
#include "fabric_fit.h"

namespace woven {

struct FittedFabric {
    FitResult fit;
    // The first shot's thread counts, where its target's UVs measure it (fit_output.h).
    std::optional<glm::dvec2> threadsPerCm;
};

class FitJob {
public:
    FitJob() = default;
    ~FitJob();  // cancels and waits
    FitJob(const FitJob&) = delete;
    FitJob& operator=(const FitJob&) = delete;

    // Cancels a running fit first. The shots are loaded on the worker: a bad one is error().
    void start(const std::vector<std::string>& shotPaths, const std::string& target, double seconds);
    void cancel();

    bool running() const { return task_.running(); }
    FitProgress progress() const;
    std::vector<float> lossHistory() const;  // the best loss after each render (finite, positive)
    // The finished (or cancelled) fit, once; nullopt while it runs, after a failure, or when taken.
    std::optional<FittedFabric> takeResult();
    std::string error() const;  // why the last fit failed, empty if it did not

private:
    mutable std::mutex mutex_;
    FitProgress progress_;
    std::vector<float> history_;
    std::optional<FittedFabric> result_;
    BackgroundTask task_;  // last: it stops before what its work writes to goes
};

}  // namespace woven
