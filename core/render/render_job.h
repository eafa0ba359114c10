#pragma once
// One final-frame render: a scene, settings, and the film it fills. Used by `woven render`, the
// previewer's Render button and the benchmarks alike. The frame is a pure function of (scene,
// settings.seed, sample range): random numbers are keyed by pixel and sample index only.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "film.h"
#include "integrators.h"
#include "sampler.h"
#include "scene_description.h"

namespace woven {

struct RenderSettings {
    int width = 640, height = 480;
    int spp = 64;              // samples per pixel to take (from firstSample on)
    int64_t firstSample = 0;   // start of this render's sample range (for distributed renders)
    double timeLimit = 0.0;    // seconds; > 0 stops after the pass that crosses it
    std::string integrator = autoIntegrator().name;  // a name in the table
    uint64_t seed = 0;
    // Owen-scrambled Sobol points by default: at equal samples they converge faster than
    // independent ones (docs/RESULTS.md, "Samplers").
    SamplerKind sampler = SamplerKind::Sobol;
    int threads = 0;           // 0 = all cores
    int maxDepth = 8;          // bounces: scattering vertices between camera and light (1 = direct light)
    // Adaptive sampling (adaptive_sampling.h): a pixel stops once the estimated relative error
    // of its mean is below this; spp is then each pixel's most. 0: every pixel takes spp samples
    // (woven render's default is defaultRenderSettings()').
    double noiseThreshold = 0.0;
    // Woven materials filtered over each pixel's footprint (--filter). Off by default: its bias
    // (about 2 % per pixel on the paper's satin) exceeds the noise it removes (docs/RESULTS.md).
    bool filterWeave = false;
    std::optional<Camera> camera;  // overrides the scene's
    // false: the film keeps the radiance's sums alone, not the render passes' (first hits, squares),
    // and the integrators make no first-hit records, for a render that no denoiser reads: woven
    // fit's, which at 512 x 512 spent a quarter of its time allocating, summing and copying them,
    // and `woven render --no-passes`.
    bool renderPasses = true;
};

// --noise-threshold's default. At 64 spp few pixels reach it before their last sample, so it
// costs a default render nothing, while flat and directly lit regions stop early; of the
// thresholds measured at equal time it did best (docs/RESULTS.md, "Time to a clean frame").
constexpr double kDefaultNoiseThreshold = 0.05;

// The scene file's render hints, the rest woven's defaults (640x480, 64 spp, auto, noise
// threshold kDefaultNoiseThreshold): what `woven render` and the previewer's Render button
// start from. Throws SceneError naming the file for a render.integrator the table lacks.
RenderSettings defaultRenderSettings(const SceneDescription& scene);

struct RenderProgress {
    int samplesDone = 0, samplesTotal = 0;  // passes, of spp: per pixel at most
    double activeFraction = 1.0;            // of the pixels, those that the next pass samples
    double elapsed = 0.0, remaining = 0.0;  // seconds (remaining: estimate)
    double samplesPerSecond = 0.0;          // camera samples (one per sampled pixel per pass) per second
    uint64_t rays = 0;                      // rays traced by the passes so far (shadow rays included)
    double raysPerSecond = 0.0;
};

class RenderScene;

class RenderJob {
public:
    RenderJob(std::shared_ptr<const SceneDescription> scene, RenderSettings settings);
    // A render of a scene already built (its BVH, materials and lights): the previewer's
    // rendered viewport keeps one across camera moves, which change nothing of it. The frame is
    // the one the constructor above makes of scene->description().
    RenderJob(std::shared_ptr<const RenderScene> scene, RenderSettings settings);
    ~RenderJob();

    // Blocks until done or `cancel` becomes true; renders in passes of one sample per pixel (per
    // pixel still sampling, with a noise threshold) so that snapshot() is a valid image after
    // every pass. Calls onProgress after each pass. Done: spp passes, the time limit crossed,
    // or, with a noise threshold, every pixel below it.
    void run(const std::atomic<bool>& cancel, const std::function<void(const RenderProgress&)>& onProgress = {});
    FilmImage snapshot() const;  // thread-safe
    Image meanRadiance() const;  // thread-safe: snapshot().radiance alone, without copying the rest
    // The one chosen: auto is resolved by a short pilot at the start of run(), so until then
    // it reads auto's name.
    const std::string& integratorName() const;

private:
    void setUp();  // the camera and integrator, once impl_ holds the scene and settings

    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace woven
