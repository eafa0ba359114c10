#pragma once
// The Render button's job: core's RenderJob (BDPT or path tracing) for a copy of the scene, a
// camera and a size, on a background thread (background_task.h), so the window stays
// responsive. The window polls progress and the latest snapshot (one after each pass) and may
// cancel.
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "background_task.h"
#include "render_job.h"

namespace woven {

class FinalRender {
public:
    FinalRender() = default;
    ~FinalRender();  // cancels and waits
    FinalRender(const FinalRender&) = delete;
    FinalRender& operator=(const FinalRender&) = delete;

    // Cancels a running render first. The scene is copied: the user may keep editing. With
    // `denoise`, the last snapshot of a render that ran to its end is denoised (frame_denoise.h),
    // as `woven render` denoises its frame.
    void start(const SceneDescription& scene, const RenderSettings& settings, bool denoise);
    void cancel();
    // Blocks until the job has finished (or was cancelled).
    void wait();

    bool running() const { return task_.running(); }
    // For the window's progress bar: the fraction done (all of it once every pixel is below the
    // noise threshold), and a line such as "12/64 spp, 35% of pixels sampling, 4.2 s left".
    float fractionDone() const;
    std::string progressText() const;
    // The snapshot after the latest pass, once per pass: nullopt when there is nothing new.
    std::optional<FilmImage> newSnapshot();
    // The latest snapshot, whether or not it was taken before.
    std::optional<FilmImage> latest() const;
    std::string error() const;  // why the last job failed, empty if it did not
    std::string integrator() const;  // the one RenderJob chose

private:
    mutable std::mutex mutex_;
    RenderProgress progress_;
    bool adaptive_ = false;  // a noise threshold was given
    std::optional<FilmImage> snapshot_;
    bool fresh_ = false;
    std::string integrator_;
    BackgroundTask task_;  // last: it stops before what its work writes to goes
};

}  // namespace woven
