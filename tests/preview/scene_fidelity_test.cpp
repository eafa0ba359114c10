// The preview against core on every scene woven ships (assets/*.json, and cloth_drape.glb, whose
// cloth is woven of itself; cloth_room.glb is converge_indirect.json's): each scene as `woven
// preview SCENE --headless --screenshot` shows it (the resting refinement, shadows, the ambient
// weighed by the sky's share, one bounce of light) and as `woven render` does (path tracing, every
// bounce), from the scene's own camera and lights, compared by the fidelity harness's 8 x 8 block
// means over the blocks wholly on woven cloth. The whole frame's figures are printed beside them (the rest is
// glTF shading, held by gltf_glsl_vs_core_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "fidelity_blocks.h"
#include "frame_options.h"
#include "gl_test_context.h"
#include "orbit_camera.h"
#include "render_job.h"
#include "scene_loader.h"

namespace woven::test {
namespace {

// Small, so that the 17 scenes take about a minute on two loaded cores; 4:3 as every scene's render.
constexpr int kWidth = 96, kHeight = 72;

std::vector<std::string> sceneFiles() {
    std::vector<std::string> all = {"cloth_drape.glb"};
    for (const auto& entry : std::filesystem::directory_iterator(WOVEN_ASSETS_DIR))
        if (entry.path().extension() == ".json") all.push_back(entry.path().filename().string());
    std::sort(all.begin(), all.end());
    return all;
}

// As `woven preview` and `woven render` open it: the studio light where the scene's are too dim,
// the camera the previewer starts from (the scene's own, or one framing it).
SceneDescription openScene(const std::string& file) {
    SceneDescription scene = loadScene(std::string(WOVEN_ASSETS_DIR) + "/" + file);
    applySceneOptions(scene, FrameOptions{});
    scene.camera = OrbitCamera::forScene(scene).camera();
    scene.hasCamera = true;
    return scene;
}

// Core's frame: path tracing (whatever the scene asks: every integrator converges to the same
// frame, and this one fastest here) at kSpp samples a pixel, each taken (no noise threshold).
constexpr int kSpp = 64;
FilmImage coreFrame(const SceneDescription& scene) {
    RenderSettings settings = defaultRenderSettings(scene);
    settings.width = kWidth;
    settings.height = kHeight;
    settings.spp = kSpp;
    settings.noiseThreshold = 0.0;
    settings.integrator = pathIntegrator().name;
    settings.camera = scene.camera;
    RenderJob job(std::make_shared<const SceneDescription>(scene), settings);
    const std::atomic<bool> cancel{false};
    job.run(cancel);
    return job.snapshot();
}

// Where woven cloth is seen: the preview's frame of the scene with its woven materials unlit white,
// the rest unlit black, no light.
std::vector<uint8_t> wovenMask(SceneDescription scene) {
    for (Material& m : scene.materials) {
        m.baseColor = glm::vec4(glm::vec3(m.woven ? 1.0f : 0.0f), 1.0f);
        m.woven.reset();
        m.baseColorTexture = {};
        m.emission = glm::vec3(0.0f);
        m.alphaMode = AlphaMode::Opaque;
        m.unlit = true;
    }
    scene.lights.clear();
    scene.environment = {};
    const Image flat = previewRadiance(scene, kWidth, kHeight, false, false, false);
    std::vector<uint8_t> mask(flat.pixels.size());
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = flat.pixels[i].g > 0.5f;
    return mask;
}

// The scenes that miss the bounds (median 5 %, worst block 15 %), measured on llvmpipe, held at
// 1.3 x their figures (the bound where that is larger) so that they cannot get worse unseen; the
// causes in docs/results/fidelity/README.md.
struct KnownMiss {
    const char* name;
    double median, worst;
};
constexpr KnownMiss kKnownMisses[] = {
    {"converge_indirect", 0.597, 0.832},    // lit off the ceiling: one bounce of the path tracer's many
    {"curtain_window", 0.083, 0.338},       // the window's glow through the curtain as a few points
    {"default_scene", 0.05, 0.271},         // the fold's edge: the area light as eight points
    {"default_scene_backlit", 0.067, 0.262},  // the same fold's edge, lit from behind
    {"lampshade", 0.125, 0.282},            // the shade's glow, lit by the light bounced inside it
    {"twill_stripes", 0.05, 0.224},         // its worst block, a miss before the bounce too
};

class SceneFidelity : public testing::TestWithParam<std::string> {};

TEST_P(SceneFidelity, BlockMeansMatchCore) {
    const std::string name = std::filesystem::path(GetParam()).stem().string();
    const SceneDescription scene = openScene(GetParam());
    const FilmImage core = coreFrame(scene);
    const RenderPasses passes = core.passes();
    std::vector<uint8_t> onScene(passes.depth.size());
    for (size_t i = 0; i < onScene.size(); ++i) onScene[i] = passes.depth[i] > 0.0f;
    const std::vector<uint8_t> onCloth = wovenMask(scene);
    const Image preview = previewRadiance(scene, kWidth, kHeight, true, true, true, true);
    const BlockErrors e = blockErrors(preview, core.radiance, onCloth), frame = blockErrors(preview, core.radiance, onScene);
    const BlockErrors noise = blockNoise(core.radiance, passes.variance, onCloth);
    writeFidelityPicture("scene_" + name, preview, core.radiance, 1);
    std::cout << "fidelity scene " << name << ": " << e.blocks << " blocks on the cloth, median " << e.median
              << ", worst " << e.worst << " (core's noise alone " << noise.median << ", " << noise.worst
              << "); the frame's " << frame.blocks << ": " << frame.median << ", " << frame.worst << "\n";
    ASSERT_GE(e.blocks, size_t(3));
    double medianBound = 0.05, worstBound = 0.15;
    for (const KnownMiss& miss : kKnownMisses)
        if (name == miss.name) medianBound = miss.median, worstBound = miss.worst;
    EXPECT_LE(e.median, medianBound);
    EXPECT_LE(e.worst, worstBound);
}

std::string sceneName(const testing::TestParamInfo<std::string>& info) {
    std::string name = info.param;
    std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
    return name;
}
INSTANTIATE_TEST_SUITE_P(Shipped, SceneFidelity, testing::ValuesIn(sceneFiles()), sceneName);

}  // namespace
}  // namespace woven::test
