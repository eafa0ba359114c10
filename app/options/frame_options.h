#pragma once
// The options `woven render` and `woven preview` share, so the Render button (and
// `woven preview --headless --final`) takes a frame exactly as `woven render` does: material
// edits (--woven), the final frame's settings on top of the scene's, and the display transform
// of every PNG written or shown.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "display_transform.h"
#include "image_io.h"
#include "render_job.h"
#include "scene_loader.h"

namespace woven {

struct FrameOptions {
    int width = 0, height = 0, spp = 0;  // 0: the scene's, else defaultRenderSettings()'
    std::string integrator;              // empty: the scene's, else auto
    uint64_t seed = 0;
    std::string sampler;                 // --sampler: kSamplerNames; empty: the scene's, else sobol
    int maxDepth = 8;
    std::optional<double> noiseThreshold;  // RenderSettings::noiseThreshold (0: off); none: the default
    bool noFilter = false;               // the preview point-samples the weave everywhere (preview's --no-filter)
    bool filterRender = false;           // the final render filters the weave over footprints (--filter)
    bool denoise = true;                 // the final frame's beauty is denoised (--no-denoise: not; frame_denoise.h)
    bool passes = true;                  // the frame keeps the render passes (--no-passes: the beauty alone, undenoised)
    std::vector<std::string> woven;      // TARGET=JSON (woven_assignment.h)
    std::string environment;             // empty: the scene's (or the studio, when it has no light)
    std::optional<float> environmentRotation;  // degrees about +y; none: the scene's
    float environmentIntensity = 1.0f;   // scales the environment's colour (and image)
    LoadOptions load;                    // --allow-any-path, --strict
    std::string camera;                  // --camera N|NAME|auto (chooseCamera()); empty: the scene's
    DisplayTransform display;
};

// Registers --width --height --spp --integrator --seed --sampler --max-depth --noise-threshold --filter
// --denoise/--no-denoise --no-passes --allow-any-path --strict --camera --woven --environment
// --environment-rotation --environment-intensity --exposure --tone-map.
void addFrameOptions(CLI::App& command, FrameOptions& options);

// The scene as a frame sees it: --environment, then the --woven edits, then, without
// --environment, the studio environment if nothing lights it or its light is too dim to see
// (lightByDefault(), said on stderr), then --environment-rotation and --environment-intensity on
// whichever environment that is. Throws SceneError for a scene that cannot be
// shown (no triangles, NaN vertices: validateScene()).
void applySceneOptions(SceneDescription& scene, const FrameOptions& options);

// defaultRenderSettings(scene) with the options that were given.
RenderSettings frameSettings(const SceneDescription& scene, const FrameOptions& options);

}  // namespace woven
