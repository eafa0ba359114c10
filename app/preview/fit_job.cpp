#include "fit_job.h"

#include <cmath>

#include "exposure_fold.h"
#include "fit_output.h"
#include "shot.h"

namespace woven {

FitJob::~FitJob() { cancel(); }

void FitJob::start(const std::vector<std::string>& shotPaths, const std::string& target, double seconds) {
    task_.cancel();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        progress_ = FitProgress{"loading the shots", 0, 0.0, seconds, 0.0};
        history_.clear();
        result_.reset();
    }
    task_.start([this, shotPaths, target, seconds](const std::atomic<bool>& cancel) {
        if (shotPaths.empty()) throw FitError("no shot files: name one or more scene files with a \"photo\" key");
        std::vector<Shot> shots;
        for (const std::string& path : shotPaths) shots.push_back(loadShot(path, target));
        FitOptions options;
        options.seconds = seconds;
        FittedFabric fitted;
        fitted.fit = fitFabric(shots, options, cancel, [&](const FitProgress& p) {
            std::lock_guard<std::mutex> lock(mutex_);
            progress_ = p;
            // Before the first finished render the best loss is no number to plot.
            if (std::isfinite(float(p.bestLoss)) && p.bestLoss > 0.0) history_.push_back(float(p.bestLoss));
        });
        // The edited material renders as the photos look under the shots' own light.
        const ExposureFold fold = foldFittedExposure(shots, fitted.fit);
        fitted.fit.params = fold.params;
        if (!fold.note.empty()) fitted.fit.warnings.push_back(fold.note);
        fitted.threadsPerCm = threadsPerCm(shots[0], fitted.fit.params.repeat);
        std::lock_guard<std::mutex> lock(mutex_);
        result_ = std::move(fitted);
    });
}

void FitJob::cancel() { task_.cancel(); }

FitProgress FitJob::progress() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return progress_;
}

std::vector<float> FitJob::lossHistory() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return history_;
}

std::optional<FittedFabric> FitJob::takeResult() {
    if (task_.running()) return std::nullopt;
    std::lock_guard<std::mutex> lock(mutex_);
    std::optional<FittedFabric> result = std::move(result_);
    result_.reset();
    return result;
}

std::string FitJob::error() const { return task_.error(); }

}  // namespace woven
