#include "rendered_viewport.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "frame_denoise.h"
#include "integrators.h"
#include "render_scene.h"
#include "scene_hash.h"

namespace woven {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The denoiser's share of the view's time at most (denoiseDue()).
constexpr double kDenoiseShare = 0.15;
// Before the denoiser's cost is measured it is taken as this many passes' time: it measured 1.3
// at 640x360 on the default scene (docs/RESULTS.md, "The rendered view").
constexpr double kUnmeasuredDenoisePasses = 2.0;
// While interacting, a pass should take about this long, so the view follows the drag.
constexpr double kInteractivePassSeconds = 0.08;
// The interactive resolution's scale of the width and height before any pass was measured, and
// its least (as InteractiveResolution's).
constexpr float kUnmeasuredScale = 0.25f, kMinScale = 0.125f;

bool sameCamera(const std::optional<Camera>& a, const std::optional<Camera>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->cameraToWorld == b->cameraToWorld && a->yfov == b->yfov && a->aspect == b->aspect);
}

// Whether two settings render the same frame.
bool sameFrame(const RenderSettings& a, const RenderSettings& b) {
    return a.width == b.width && a.height == b.height && a.spp == b.spp && a.firstSample == b.firstSample &&
           a.timeLimit == b.timeLimit && a.integrator == b.integrator && a.seed == b.seed && a.sampler == b.sampler &&
           a.threads == b.threads && a.maxDepth == b.maxDepth && a.noiseThreshold == b.noiseThreshold &&
           a.filterWeave == b.filterWeave && a.renderPasses == b.renderPasses && sameCamera(a.camera, b.camera);
}

// Whether to denoise after a pass other than the last, which always is: when the denoiser's time
// with this one stays within kDenoiseShare of the passes' so far, and leaves room within
// kDenoiseShare of all the passes' for the last one. `cost`: one denoising's seconds (estimated).
bool denoiseDue(double cost, double denoisedSeconds, double renderedSeconds, int passesDone, int passes) {
    const double allPasses = renderedSeconds / passesDone * passes;
    return denoisedSeconds + cost <= kDenoiseShare * renderedSeconds &&
           denoisedSeconds + 2.0 * cost <= kDenoiseShare * allPasses;
}

}  // namespace

RenderSettings viewportSettings(RenderSettings settings) {
    settings.noiseThreshold = 0.0;
    if (settings.integrator == autoIntegrator().name) settings.integrator = pathIntegrator().name;
    return settings;
}

RenderedViewport::RenderedViewport() : worker_([this] { work(); }) {}

RenderedViewport::~RenderedViewport() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        quit_ = true;
        cancel_ = true;
    }
    wake_.notify_all();
    worker_.join();
}

void RenderedViewport::show(const SceneDescription& scene, const RenderSettings& settings, bool interacting,
                            bool denoise) {
    const std::string hash = sceneHash(scene, Camera{});
    std::lock_guard<std::mutex> lock(mutex_);
    if (!interacting) interactiveScale_ = 0.0f;  // the next drag measures again
    const bool sameScene = current_.scene && hash == current_.sceneHash;
    const bool sameAsked = sameScene && sameFrame(settings, current_.asked) && denoise == current_.denoise;
    // Nothing changed; or nothing since a drag's change, which goes on.
    if (sameAsked && (interacting || !current_.interacting)) return;
    RenderSettings wanted = settings;
    if (interacting) {
        // One scale a drag, so that the drag's frames differ by the camera or the value alone.
        if (interactiveScale_ == 0.0f) {
            const double pixels = double(settings.width) * settings.height;
            interactiveScale_ = samplesPerSecond_ > 0.0
                                    ? float(std::sqrt(samplesPerSecond_ * kInteractivePassSeconds / pixels))
                                    : kUnmeasuredScale;
            interactiveScale_ = std::clamp(interactiveScale_, kMinScale, 1.0f);
        }
        wanted.width = std::max(1, int(std::lround(settings.width * interactiveScale_)));
        wanted.height = std::max(1, int(std::lround(settings.height * interactiveScale_)));
        // The full frame's aspect, which rounding the size would change.
        if (wanted.camera && wanted.camera->aspect <= 0.0f)
            wanted.camera->aspect = float(settings.width) / float(settings.height);
    }
    Request request;
    request.scene = sameScene ? current_.scene : std::make_shared<const SceneDescription>(scene);
    request.sceneHash = hash;
    request.asked = settings;
    request.settings = wanted;
    request.interacting = interacting;
    request.denoise = denoise;
    request.generation = ++generation_;
    // A drag's pass in flight that has shown nothing yet is let finish: a drag that goes on longer
    // than a pass still shows frames. Any other change cancels what is in flight.
    const bool letFirstPassFinish = interacting && working_ && current_.interacting && progress_.samples == 0;
    if (!letFirstPassFinish) cancel_ = true;
    current_ = request;
    pending_ = std::move(request);
    wake_.notify_all();
}

void RenderedViewport::stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    Request none;  // no scene: the worker drops the one it built
    none.generation = ++generation_;
    current_ = none;
    pending_ = none;
    cancel_ = true;
    interactiveScale_ = 0.0f;
    frame_.reset();
    shown_ = Image{};
    fresh_ = false;
    progress_ = ViewportProgress{};
    wake_.notify_all();
}

void RenderedViewport::waitUntilIdle() {
    std::unique_lock<std::mutex> lock(mutex_);
    wake_.wait(lock, [&] { return !working_ && !pending_; });
}

bool RenderedViewport::running() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return working_ || pending_;
}

void RenderedViewport::work() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        wake_.wait(lock, [&] { return quit_ || pending_; });
        if (quit_) return;
        const Request request = std::move(*pending_);
        pending_.reset();
        cancel_ = false;
        working_ = true;
        lock.unlock();
        try {
            render(request);
        } catch (const std::exception& e) {
            lock.lock();
            error_ = e.what();
            lock.unlock();
        }
        lock.lock();
        working_ = false;
        wake_.notify_all();  // waitUntilIdle()
    }
}

void RenderedViewport::render(const Request& request) {
    if (!request.scene) {
        built_.reset();
        builtHash_.clear();
        return;
    }
    const Clock::time_point start = Clock::now();
    // Only a changed scene is built again, on the BVH already built unless its geometry changed;
    // a camera or size change renders the one built.
    if (!built_ || builtHash_ != request.sceneHash) {
        std::shared_ptr<RenderScene> previous = std::move(built_);
        builtHash_.clear();
        // The last job has ended: nothing else holds the scene it rendered.
        built_ = previous && previous.use_count() == 1 ? std::make_shared<RenderScene>(request.scene, std::move(*previous))
                                                       : std::make_shared<RenderScene>(request.scene);
        previous.reset();
        builtHash_ = request.sceneHash;
        std::lock_guard<std::mutex> lock(mutex_);
        ++progress_.builds;
        if (!built_->tookGeometry()) ++progress_.bvhBuilds;
    }
    if (cancel_) return;
    RenderJob job(built_, request.settings);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        error_.clear();
        ++progress_.restarts;
        progress_.samples = progress_.denoisedAt = 0;
        progress_.denoiseSeconds = 0.0;
        progress_.denoisings = 0;
        progress_.target = request.settings.spp;
        progress_.width = request.settings.width;
        progress_.height = request.settings.height;
        progress_.seconds = secondsSince(start);
        progress_.converged = false;
    }
    Clock::time_point passEnd = Clock::now();
    double renderedSeconds = 0.0, denoisedSeconds = 0.0;
    job.run(cancel_, [&](const RenderProgress& p) {
        renderedSeconds += secondsSince(passEnd);
        const double pixels = double(request.settings.width) * request.settings.height;
        double perPixel = 0.0;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            samplesPerSecond_ = p.samplesPerSecond;
            perPixel = denoiseSecondsPerPixel_;
        }
        const bool last = p.samplesDone == request.settings.spp;
        const double cost =
            perPixel > 0.0 ? perPixel * pixels : kUnmeasuredDenoisePasses * renderedSeconds / p.samplesDone;
        const bool denoise = request.denoise && !request.interacting &&
                             (last || denoiseDue(cost, denoisedSeconds, renderedSeconds, p.samplesDone, request.settings.spp));
        // Only a pass to denoise and the last take the whole film (its sums and passes); the
        // others show their running mean alone: copying the film, while the render's threads
        // wait, took about a tenth of each pass (docs/results/rendered_view.md).
        std::optional<FilmImage> film;
        Image mean;
        if (denoise || last) film = job.snapshot();
        else mean = job.meanRadiance();
        double denoiseSeconds = 0.0;
        if (denoise) {
            const Clock::time_point denoiseStart = Clock::now();
            denoiseFilm(*film);
            denoiseSeconds = secondsSince(denoiseStart);
            denoisedSeconds += denoiseSeconds;
            std::lock_guard<std::mutex> lock(mutex_);
            denoiseSecondsPerPixel_ = denoiseSeconds / pixels;
        }
        std::lock_guard<std::mutex> lock(mutex_);
        if (generation_ != request.generation) {
            // A newer request waits: this job stops. Its pass is still newer than what the view
            // shows (a drag's first pass, let finish), unless the view was stopped.
            cancel_ = true;
            if (!current_.scene) return;
        }
        progress_.samples = p.samplesDone;
        if (denoise) {
            progress_.denoisedAt = p.samplesDone;
            ++progress_.denoisings;
        }
        progress_.denoiseSeconds += denoiseSeconds;
        progress_.seconds = secondsSince(start);
        progress_.converged = last;
        // The view keeps this restart's last denoised frame until the next one; the running
        // mean shows until there is one.
        if (denoise || progress_.denoisedAt == 0) {
            shown_ = !film ? std::move(mean) : film->denoised ? *film->denoised : film->radiance;
            fresh_ = true;
        }
        if (film) frame_ = std::move(*film);
        passEnd = Clock::now();
    });
}

std::optional<Image> RenderedViewport::newImage() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!fresh_) return std::nullopt;
    fresh_ = false;
    return shown_;
}

std::optional<FilmImage> RenderedViewport::frame() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return frame_;
}

ViewportProgress RenderedViewport::progress() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return progress_;
}

std::string RenderedViewport::statusText() const {
    std::lock_guard<std::mutex> lock(mutex_);
    const ViewportProgress& p = progress_;
    char text[96];
    std::snprintf(text, sizeof text, "%d/%d spp", p.samples, p.target);
    std::string status = text;
    if (p.width != current_.asked.width || p.height != current_.asked.height)
        status += " at " + std::to_string(p.width) + "x" + std::to_string(p.height);
    std::snprintf(text, sizeof text, ", %.1f s", p.seconds);
    status += text;
    if (p.denoisedAt > 0) status += ", denoised";
    if (p.converged) status += ", converged";
    return status;
}

std::string RenderedViewport::error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
}

}  // namespace woven
