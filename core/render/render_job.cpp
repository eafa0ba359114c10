#include "render_job.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "adaptive_sampling.h"
#include "film.h"
#include "frame_limits.h"
#include "integrator.h"
#include "integrators.h"
#include "render_scene.h"
#include "scene_camera.h"
#include "scene_hash.h"
#include "scene_loader.h"

namespace woven {

namespace {

constexpr int kTileSize = 16;

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Renders one pass (one sample per pixel, sample index `sampleIndex`) over tiles on the arena's
// threads, of the pixels `sampled` marks (empty: all), with the first hits' records where
// `firstHits` (else pass->firstHits is left empty). Every pixel's random numbers come from
// (seed, pixel, sample index) alone. Returns false, leaving `pass` incomplete, when `cancel`
// became true.
bool renderPass(const Integrator& integrator, int width, int height, SamplerKind samplerKind, uint64_t seed, uint64_t sampleIndex,
                const std::vector<uint8_t>& sampled, size_t sampledCount, bool firstHits, tbb::task_arena& arena,
                const std::atomic<bool>& cancel, uint64_t* rays, PassImage* pass) {
    const int tilesX = (width + kTileSize - 1) / kTileSize, tilesY = (height + kTileSize - 1) / kTileSize;
    pass->width = width;
    pass->height = height;
    pass->radiance.assign(size_t(width) * height, glm::vec3(0.0f));
    pass->firstHits.assign(firstHits ? size_t(width) * height : 0, FirstHit{});
    pass->tileSplats.assign(size_t(tilesX) * tilesY, {});
    pass->sampled = sampled;
    const size_t pixels = size_t(width) * height;
    pass->splatScale = sampled.empty() || sampledCount == pixels ? 1.0f : float(double(pixels) / double(sampledCount));
    std::atomic<uint64_t> rayCount{0};
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY, 1), [&](const tbb::blocked_range<int>& range) {
            for (int tile = range.begin(); tile != range.end(); ++tile) {
                if (cancel.load(std::memory_order_relaxed)) return;
                SampleSink sink;
                sink.recordsFirstHit = firstHits;
                const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
                for (int y = y0; y < std::min(y0 + kTileSize, height); ++y)
                    for (int x = x0; x < std::min(x0 + kTileSize, width); ++x) {
                        const uint64_t pixel = uint64_t(y) * uint64_t(width) + uint64_t(x);
                        if (!pass->samples(pixel)) continue;
                        Sampler sampler(samplerKind, seed, pixel, sampleIndex);
                        const glm::vec2 pRaster = glm::vec2(float(x), float(y)) + sampler.get2D(kPixelDimension);
                        sink.firstHit = FirstHit{};
                        const glm::vec3 L = integrator.Li(pRaster, sampler, sink);
                        // A rare non-finite sample would poison the pixel for good: drop it.
                        pass->radiance[pixel] = std::isfinite(L.x + L.y + L.z) ? L : glm::vec3(0.0f);
                        if (firstHits) pass->firstHits[pixel] = sink.firstHit;
                    }
                pass->tileSplats[size_t(tile)] = std::move(sink.splats);
                rayCount.fetch_add(sink.rays, std::memory_order_relaxed);
            }
        });
    });
    *rays += rayCount.load();
    return !cancel.load();
}

}  // namespace

struct RenderJob::Impl {
    std::shared_ptr<const SceneDescription> description;
    RenderSettings settings;
    std::shared_ptr<const RenderScene> scene;
    Camera camera;
    std::unique_ptr<CameraModel> cameraModel;
    std::unique_ptr<Integrator> integrator;
    std::string integratorName;
    std::string sceneHash;  // of the scene through `camera`, for the frame's identity
    tbb::task_arena arena;

    mutable std::mutex filmMutex;
    Film film;

    Impl(std::shared_ptr<const SceneDescription> scene_, RenderSettings settings_)
        : description(std::move(scene_)), settings(std::move(settings_)),
          arena(workerThreads(settings.threads)),
          film(settings.width, settings.height, settings.renderPasses) {}

    // Auto: the more efficient integrator (1 / (variance x time) per pass) in a pilot of each
    // on a low-resolution version of the frame.
    const IntegratorKind& pickIntegrator(const std::atomic<bool>& cancel);
};

const IntegratorKind& RenderJob::Impl::pickIntegrator(const std::atomic<bool>& cancel) {
    // About 20,000 pixels: enough to see the noise of every region of the frame, a few
    // seconds on two cores for both integrators together.
    const double scale = std::min(1.0, std::sqrt(20000.0 / (double(settings.width) * settings.height)));
    const int width = std::max(8, int(settings.width * scale)), height = std::max(8, int(settings.height * scale));
    Camera pilotCamera = camera;
    if (pilotCamera.aspect <= 0.0f) pilotCamera.aspect = float(settings.width) / float(settings.height);
    const CameraModel pilotModel(pilotCamera, width, height);
    // Pass counts: at least kMinPasses for a variance, at most kMaxPasses, or fewer once an
    // integrator has spent kPilotSeconds.
    constexpr int kMinPasses = 4, kMaxPasses = 16;
    constexpr double kPilotSeconds = 1.5;
    struct Pilot {
        const IntegratorKind* kind;
        double mean = 0.0, variance = 0.0, secondsPerPass = 0.0;  // per pass, over the image
    };
    std::vector<Pilot> pilots;
    for (const IntegratorKind& kind : integratorKinds())
        if (kind.make) pilots.push_back({&kind});
    for (Pilot& pilot : pilots) {
        const auto candidate = pilot.kind->make(*scene, pilotModel, settings.maxDepth, settings.filterWeave);
        std::vector<double> sum(size_t(width) * height, 0.0), sumSq(sum.size(), 0.0);
        const Clock::time_point start = Clock::now();
        int passes = 0;
        uint64_t rays = 0;
        while (passes < kMaxPasses && (passes < kMinPasses || secondsSince(start) < kPilotSeconds)) {
            PassImage pass;
            // Sample indices far from any final render's, so the pilot never repeats its samples.
            const uint64_t sampleIndex = (uint64_t(1) << 62) + uint64_t(passes);
            if (!renderPass(*candidate, width, height, settings.sampler, settings.seed, sampleIndex, {}, 0, false, arena, cancel, &rays, &pass))
                return *pilot.kind;  // cancelled: run() renders nothing
            const std::vector<glm::vec3> image = pass.combined();
            for (size_t i = 0; i < image.size(); ++i) {
                const double y = luminance(image[i]);
                sum[i] += y;
                sumSq[i] += y * y;
            }
            ++passes;
        }
        pilot.secondsPerPass = secondsSince(start) / passes;
        for (size_t i = 0; i < sum.size(); ++i) {
            const double m = sum[i] / passes;
            pilot.mean += m;
            pilot.variance += std::max(0.0, (sumSq[i] - passes * m * m) / (passes - 1));
        }
        pilot.mean /= double(sum.size());
        pilot.variance /= double(sum.size());
    }
    // All estimate the same image. One that found far less light than another has missed
    // paths it samples rarely, and its variance estimate is meaningless (zero when it found
    // none): it is out. Of the rest the efficiency 1 / (variance x time) decides, a tie going
    // to the one first in the table.
    double brightest = 0.0;
    for (const Pilot& pilot : pilots) brightest = std::max(brightest, pilot.mean);
    const Pilot* best = nullptr;
    for (const Pilot& pilot : pilots)
        if (!(pilot.mean < 0.5 * brightest) &&
            (!best || pilot.variance * pilot.secondsPerPass < best->variance * best->secondsPerPass))
            best = &pilot;
    return *best->kind;
}

RenderSettings defaultRenderSettings(const SceneDescription& scene) {
    RenderSettings settings;
    settings.noiseThreshold = kDefaultNoiseThreshold;
    if (scene.render.width > 0) settings.width = scene.render.width;
    if (scene.render.height > 0) settings.height = scene.render.height;
    if (scene.render.spp > 0) settings.spp = scene.render.spp;
    if (scene.render.noiseThreshold) settings.noiseThreshold = *scene.render.noiseThreshold;
    if (!scene.render.integrator.empty()) {
        if (!findIntegrator(scene.render.integrator))
            throw SceneError(scene.source + ": render.integrator: must be " + integratorChoices("\"") + ", not \"" +
                             scene.render.integrator + "\"");
        settings.integrator = scene.render.integrator;
    }
    if (!scene.render.sampler.empty()) {
        const auto* end = std::end(kSamplerNames);
        if (std::find(std::begin(kSamplerNames), end, scene.render.sampler) == end)
            throw SceneError(scene.source + ": render.sampler: must be \"sobol\" or \"independent\", not \"" +
                             scene.render.sampler + "\"");
        settings.sampler = samplerKind(scene.render.sampler);
    }
    return settings;
}

namespace {

// What the constructors refuse, before anything is built.
void checkSettings(const RenderSettings& settings) {
    if (settings.width <= 0 || settings.height <= 0)
        throw std::invalid_argument("image size must be positive, got " + std::to_string(settings.width) + "x" +
                                    std::to_string(settings.height));
    if (settings.spp < 0) throw std::invalid_argument("samples per pixel must not be negative");
    if (!withinSampleIndexLimit(settings.firstSample, settings.spp))
        throw std::invalid_argument("the sample range from " + std::to_string(settings.firstSample) + ", " +
                                    std::to_string(settings.spp) + " samples, is not within 0 to 2^62 (" +
                                    std::to_string(kSampleIndexLimit) + ")");
    if (settings.maxDepth < 1) throw std::invalid_argument("the maximum depth must be at least 1");
    if (!(settings.noiseThreshold >= 0.0)) throw std::invalid_argument("the noise threshold must not be negative");
    checkFrameFitsInMemory(settings.width, settings.height);
}

}  // namespace

RenderJob::RenderJob(std::shared_ptr<const SceneDescription> scene, RenderSettings settings) {
    checkSettings(settings);
    auto built = std::make_shared<const RenderScene>(scene);
    impl_ = std::make_unique<Impl>(std::move(scene), std::move(settings));
    impl_->scene = std::move(built);
    setUp();
}

RenderJob::RenderJob(std::shared_ptr<const RenderScene> scene, RenderSettings settings) {
    checkSettings(settings);
    // The description lives as long as the scene built from it.
    std::shared_ptr<const SceneDescription> description(scene, &scene->description());
    impl_ = std::make_unique<Impl>(std::move(description), std::move(settings));
    impl_->scene = std::move(scene);
    setUp();
}

void RenderJob::setUp() {
    Impl& im = *impl_;
    if (im.scene->lights().empty())
        throw SceneError(im.description->source +
                         ": scene has no lights: add an emissive material, a KHR_lights_punctual light or an environment");
    im.camera = im.settings.camera ? *im.settings.camera : sceneCamera(*im.description);
    im.cameraModel = std::make_unique<CameraModel>(im.camera, im.settings.width, im.settings.height);
    im.sceneHash = sceneHash(*im.description, im.camera);
    const IntegratorKind* kind = findIntegrator(im.settings.integrator);
    if (!kind)
        throw std::invalid_argument("unknown integrator '" + im.settings.integrator + "' (expected " +
                                    integratorChoices() + ")");
    im.integratorName = kind->name;
    if (kind->make) im.integrator = kind->make(*im.scene, *im.cameraModel, im.settings.maxDepth, im.settings.filterWeave);
}

RenderJob::~RenderJob() = default;

void RenderJob::run(const std::atomic<bool>& cancel, const std::function<void(const RenderProgress&)>& onProgress) {
    Impl& im = *impl_;
    const Clock::time_point start = Clock::now();
    if (!im.integrator) {
        const IntegratorKind& chosen = im.pickIntegrator(cancel);
        if (cancel.load()) return;
        im.integrator = chosen.make(*im.scene, *im.cameraModel, im.settings.maxDepth, im.settings.filterWeave);
        std::lock_guard<std::mutex> lock(im.filmMutex);  // snapshot() reads it from other threads
        im.integratorName = chosen.name;
    }
    const Clock::time_point renderStart = Clock::now();
    const size_t pixels = size_t(im.settings.width) * im.settings.height;
    std::optional<AdaptiveSampling> adaptive;
    const std::vector<uint8_t> everyPixel;  // renderPass's "all"
    if (im.settings.noiseThreshold > 0.0) adaptive.emplace(im.settings.width, im.settings.height, im.settings.noiseThreshold);
    RenderProgress progress;
    progress.samplesTotal = im.settings.spp;
    uint64_t samples = 0;
    PassImage pass;  // one for all passes, so that its buffers are not allocated again each pass
    for (int done = 0; done < im.settings.spp; ++done) {
        const Clock::time_point passStart = Clock::now();
        const uint64_t sampleIndex = uint64_t(im.settings.firstSample) + uint64_t(im.film.passes());
        const size_t sampled = adaptive ? adaptive->activeCount() : pixels;
        if (!renderPass(*im.integrator, im.settings.width, im.settings.height, im.settings.sampler, im.settings.seed, sampleIndex,
                        adaptive ? adaptive->active() : everyPixel, sampled, im.settings.renderPasses, im.arena, cancel,
                        &progress.rays, &pass))
            return;  // the unfinished pass is dropped: the film holds whole passes only
        {
            std::lock_guard<std::mutex> lock(im.filmMutex);
            im.arena.execute([&] { im.film.addPass(pass); });  // on the render's threads
        }
        if (adaptive) im.arena.execute([&] { adaptive->addPass(pass.combined()); });
        samples += sampled;
        const double renderSeconds = std::max(secondsSince(renderStart), 1e-9);
        progress.samplesDone = done + 1;
        progress.activeFraction = adaptive ? double(adaptive->activeCount()) / double(pixels) : 1.0;
        progress.elapsed = secondsSince(start);
        progress.samplesPerSecond = double(samples) / renderSeconds;
        progress.raysPerSecond = double(progress.rays) / renderSeconds;
        // Adaptive passes get cheaper as pixels stop: the latest one tells the cost of the next.
        const double perPass = adaptive ? secondsSince(passStart) : renderSeconds / progress.samplesDone;
        const bool converged = progress.activeFraction == 0.0;
        progress.remaining = converged ? 0.0 : perPass * (im.settings.spp - progress.samplesDone);
        const bool outOfTime = im.settings.timeLimit > 0.0 && progress.elapsed >= im.settings.timeLimit;
        if (im.settings.timeLimit > 0.0) progress.remaining = std::min(progress.remaining, std::max(0.0, im.settings.timeLimit - progress.elapsed));
        if (outOfTime) progress.remaining = 0.0;
        if (onProgress) onProgress(progress);
        if (outOfTime || converged || cancel.load()) return;
    }
}

FilmImage RenderJob::snapshot() const {
    std::lock_guard<std::mutex> lock(impl_->filmMutex);
    FilmImage image = impl_->film.image();
    const Impl& im = *impl_;
    image.samples = {im.settings.firstSample, im.film.passes()};
    image.frame = {im.sceneHash, im.settings.seed, integratorRecord(im.settings.integrator, im.integratorName),
                   im.settings.maxDepth, im.settings.filterWeave, samplerName(im.settings.sampler)};
    return image;
}

Image RenderJob::meanRadiance() const {
    std::lock_guard<std::mutex> lock(impl_->filmMutex);
    return impl_->film.meanRadiance();
}

const std::string& RenderJob::integratorName() const { return impl_->integratorName; }

}  // namespace woven
