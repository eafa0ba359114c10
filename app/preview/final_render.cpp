#include "final_render.h"

#include <cmath>
#include <cstdio>

#include "frame_denoise.h"

namespace woven {

FinalRender::~FinalRender() { cancel(); }

void FinalRender::start(const SceneDescription& scene, const RenderSettings& settings, bool denoise) {
    task_.cancel();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        progress_ = RenderProgress{};
        progress_.samplesTotal = settings.spp;
        adaptive_ = settings.noiseThreshold > 0.0;
        snapshot_.reset();
        fresh_ = false;
    }
    auto shared = std::make_shared<const SceneDescription>(scene);
    task_.start([this, shared, settings, denoise](const std::atomic<bool>& cancel) {
        RenderJob job(shared, settings);
        {
            std::lock_guard<std::mutex> lock(mutex_);
            integrator_ = job.integratorName();
        }
        job.run(cancel, [&](const RenderProgress& p) {
            FilmImage image = job.snapshot();
            std::lock_guard<std::mutex> lock(mutex_);
            progress_ = p;
            snapshot_ = std::move(image);
            fresh_ = true;
        });
        if (denoise && !cancel) {
            FilmImage image = job.snapshot();
            denoiseFilm(image);
            std::lock_guard<std::mutex> lock(mutex_);
            snapshot_ = std::move(image);
            fresh_ = true;
        }
    });
}

void FinalRender::cancel() { task_.cancel(); }

void FinalRender::wait() { task_.wait(); }

float FinalRender::fractionDone() const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (progress_.activeFraction == 0.0) return 1.0f;
    return progress_.samplesTotal > 0 ? float(progress_.samplesDone) / float(progress_.samplesTotal) : 0.0f;
}

std::string FinalRender::progressText() const {
    std::lock_guard<std::mutex> lock(mutex_);
    char text[128];
    if (adaptive_)
        std::snprintf(text, sizeof text, "%d/%d spp, %.0f%% of pixels sampling, %.1f s left", progress_.samplesDone,
                      progress_.samplesTotal, std::ceil(100.0 * progress_.activeFraction), progress_.remaining);
    else
        std::snprintf(text, sizeof text, "%d/%d spp, %.1f s left", progress_.samplesDone, progress_.samplesTotal,
                      progress_.remaining);
    return text;
}

std::optional<FilmImage> FinalRender::newSnapshot() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!fresh_) return std::nullopt;
    fresh_ = false;
    return snapshot_;
}

std::optional<FilmImage> FinalRender::latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return snapshot_;
}

std::string FinalRender::integrator() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return integrator_;
}

std::string FinalRender::error() const { return task_.error(); }

}  // namespace woven
