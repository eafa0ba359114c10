#pragma once
// The view's Rendered mode: core's path tracer renders what the window shows (its scene as
// edited, its camera, the Render button's size, sampler and seed) progressively on a thread of its
// own, one sample a pixel a pass, the view showing the running mean and, every few passes,
// woven's denoiser's frame of it. Any change starts it again: a camera or size change renders the
// scene already built; a material or light edit builds the materials and lights again on the BVH
// already built; only a change of the geometry builds the BVH again. While the camera or a slider
// moves, passes render at a lower resolution, shown scaled up.
//
// The frame after N passes is the Render button's (and `woven render`'s) frame of N samples a
// pixel with no noise threshold, bit for bit: the same RenderJob over the same sample range.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "render_job.h"

namespace woven {

class RenderScene;

// The viewport's settings from the Render button's: every pixel takes every pass (no noise
// threshold), and auto, whose pilot would take seconds at each restart, is the path tracer.
RenderSettings viewportSettings(RenderSettings renderButton);

struct ViewportProgress {
    int samples = 0;      // passes in the running mean
    int target = 0;       // passes at which the view is converged (the settings' spp)
    int denoisedAt = 0;   // passes in the denoised frame last made of this restart; 0: none yet
    int width = 0, height = 0;  // of the passes: less than the settings' while interacting
    double seconds = 0.0;  // since the restart
    double denoiseSeconds = 0.0;  // of those, in the denoiser
    int denoisings = 0;           // how many frames of this restart it denoised
    bool converged = false;
    uint64_t restarts = 0;  // how many times the view started again
    uint64_t builds = 0;    // how many times it built a scene (materials, lights)
    uint64_t bvhBuilds = 0;  // of those, how many built the BVH too (the geometry changed)
};

class RenderedViewport {
public:
    RenderedViewport();
    ~RenderedViewport();  // cancels and waits
    RenderedViewport(const RenderedViewport&) = delete;
    RenderedViewport& operator=(const RenderedViewport&) = delete;

    // What the view is to show, called each frame: starts again when the scene, the camera or the
    // settings differ from what is being rendered (cancelling the passes in flight), else does
    // nothing. `interacting`: the camera or a value is being dragged: a change then renders at a
    // lower resolution, not denoised, and the end of the drag starts again at full size (a held
    // button that changes nothing changes nothing). `denoise`: woven's denoiser every few passes,
    // and on the last.
    void show(const SceneDescription& scene, const RenderSettings& settings, bool interacting, bool denoise);
    // Cancels the passes in flight and forgets the scene (the window left Rendered mode).
    void stop();
    // Blocks until the view is converged, failed or stopped (for headless frames).
    void waitUntilIdle();
    bool running() const;  // passes or a scene's build under way, or waiting to start

    // The image to draw (the denoised frame where there is one, else the running mean) when a new
    // one arrived since the last call.
    std::optional<Image> newImage();
    // The frame of the latest pass that was denoised or the last (for headless frames: once
    // converged, the last pass's, denoised with `denoise`): the other passes publish their running
    // mean alone (newImage()).
    std::optional<FilmImage> frame() const;
    ViewportProgress progress() const;
    // "12/64 spp, 3.2 s", "1/64 spp at 160x90, 0.1 s", "64/64 spp, 20.5 s, denoised, converged"
    std::string statusText() const;
    std::string error() const;       // why the last restart failed, empty if it did not

private:
    struct Request {
        std::shared_ptr<const SceneDescription> scene;
        std::string sceneHash;
        RenderSettings asked;     // as show() was given them
        RenderSettings settings;  // as rendered: smaller while interacting
        bool interacting = false, denoise = false;
        uint64_t generation = 0;
    };
    void work();
    void render(const Request& request);
    // Publishes a pass's frame; denoises it when the cadence says so. False: a newer request
    // waits, and the job is to stop.
    bool onPass(const Request& request, RenderJob& job, const RenderProgress& progress);

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Request> pending_;   // the latest request the worker has not taken
    Request current_;                  // the latest request made (what show() compares with)
    uint64_t generation_ = 0;          // of the latest request
    bool working_ = false;             // the worker renders or builds a request
    bool quit_ = false;
    std::atomic<bool> cancel_{false};  // the job in flight stops after the tile it renders

    // Built once a scene, shared with the job in flight; only the worker touches it.
    std::shared_ptr<RenderScene> built_;
    std::string builtHash_;

    // What the worker publishes, under mutex_.
    std::optional<FilmImage> frame_;  // frame()'s
    Image shown_;                     // what the view draws
    bool fresh_ = false;              // shown_ changed since newImage()
    ViewportProgress progress_;
    std::string error_;
    // Measures across restarts: camera samples per second (for the interactive resolution), and
    // the denoiser's seconds per pixel (for its cadence); 0: not measured yet.
    double samplesPerSecond_ = 0.0, denoiseSecondsPerPixel_ = 0.0;
    float interactiveScale_ = 0.0f;  // of the drag under way; 0: none

    std::thread worker_;  // last: it stops before what it works on goes
};

}  // namespace woven
