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
#include <iterator>

#include "fidelity_blocks.h"
#include "frame_options.h"
#include "gl_test_context.h"
#include "material_json.h"
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
// frame, and this one fastest here) at `spp` samples a pixel, each taken (no noise threshold).
FilmImage coreFrame(const SceneDescription& scene, int spp) {
    RenderSettings settings = defaultRenderSettings(scene);
    settings.width = kWidth;
    settings.height = kHeight;
    settings.spp = spp;
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
    {"default_scene", 0.05, 0.219},         // the fold's shaded side: the preview's indirect light over core's
    {"default_scene_backlit", 0.067, 0.255},  // the same fold, lit from behind
    {"lampshade", 0.09, 0.202},             // the shade's glow, lit by the light bounced inside it
    {"twill_stripes", 0.05, 0.26},          // its worst block, a miss before the bounce too
};

class SceneFidelity : public testing::TestWithParam<std::string> {};

// The preview of `scene` against core's frame at `spp`, over the blocks on woven cloth (the
// frame's printed beside them), within the bounds (median 5 %, worst block `worstBound`) or the
// named known miss's; the pair's picture is <picture>.png.
void expectFidelity(const std::string& name, const std::string& picture, const SceneDescription& scene, int spp,
                    double worstBound, const KnownMiss* misses, size_t missCount) {
    const FilmImage core = coreFrame(scene, spp);
    const RenderPasses passes = core.passes();
    std::vector<uint8_t> onScene(passes.depth.size());
    for (size_t i = 0; i < onScene.size(); ++i) onScene[i] = passes.depth[i] > 0.0f;
    const std::vector<uint8_t> onCloth = wovenMask(scene);
    const Image preview = previewRadiance(scene, kWidth, kHeight, true, true, true, true);
    const BlockErrors e = blockErrors(preview, core.radiance, onCloth), frame = blockErrors(preview, core.radiance, onScene);
    const BlockErrors noise = blockNoise(core.radiance, passes.variance, onCloth);
    writeFidelityPicture(picture, preview, core.radiance, 1);
    std::cout << "fidelity scene " << name << ": " << e.blocks << " blocks on the cloth, median " << e.median
              << ", worst " << e.worst << " (core's noise alone " << noise.median << ", " << noise.worst
              << "); the frame's " << frame.blocks << ": " << frame.median << ", " << frame.worst << "\n";
    ASSERT_GE(e.blocks, size_t(3));
    double medianBound = 0.05;
    for (size_t k = 0; k < missCount; ++k)
        if (name == misses[k].name) medianBound = misses[k].median, worstBound = misses[k].worst;
    EXPECT_LE(e.median, medianBound);
    EXPECT_LE(e.worst, worstBound);
}

TEST_P(SceneFidelity, BlockMeansMatchCore) {
    const std::string name = std::filesystem::path(GetParam()).stem().string();
    expectFidelity(name, "scene_" + name, openScene(GetParam()), 64, 0.15, kKnownMisses, std::size(kKnownMisses));
}

std::string sceneName(const testing::TestParamInfo<std::string>& info) { return testName(info.param); }
INSTANTIATE_TEST_SUITE_P(Shipped, SceneFidelity, testing::ValuesIn(sceneFiles()), sceneName);

// Every fabric of the library and every draft of assets/drafts on the default scene's drape (its
// area light, sky, floor and camera: what a user opens), seen near (threads of about 10 pixels),
// mid (about 3) and far (about 0.4, the default denim's own), where the flat cloth's harness
// (preview_fidelity_test.cpp) holds them under two point lights. Each its own ratio of ends to
// picks, the mean of the two a share of the default denim's. Core at 128 samples a pixel: its noise
// alone gives a block 1.6 to 3.4 % (at 64 about the bound's 5 %).
struct DrapeDistance {
    const char* name;
    float repeatShare;  // of the default denim's repeat
};
constexpr DrapeDistance kDrapeDistances[] = {{"near", 1.0f / 25.0f}, {"mid", 1.0f / 8.0f}, {"far", 1.0f}};

using DrapeCase = SubjectAt<DrapeDistance>;

// The drape's worst block misses the bound in 18 of the 51 cases, on the fold's shaded side, where
// the preview's indirect light (the sky's share, one bounce) is over core's (the default scene's,
// docs/results/fidelity/README.md): measured 15.3 to 19.2 % there (10.1 to 15.0 % in the other
// 33), held at 1.3 x the largest. The tartan's worst block (the same blocks, 29 to 78 % over core's
// dark) and the voile's (behind its see-through gaps the preview's shadow map passes the gaps' mean
// share, where core's rays pass each gap and draw the threads' shadows: 9.7-11.1 / 23.2-25.5 %,
// 14.5-15.7 / 48.5-53.9 % while the gaps cast a solid shadow) miss more, held as the scenes'
// misses are (llvmpipe, 2026-12-08).
constexpr double kDrapeWorstBound = 0.25;
constexpr KnownMiss kDrapeKnownMisses[] = {
    {"tartan_near", 0.05, 0.89}, {"tartan_mid", 0.05, 0.90}, {"tartan_far", 0.05, 0.93},
    {"voile_near", 0.144, 0.311}, {"voile_mid", 0.126, 0.332}, {"voile_far", 0.138, 0.302},
};

class DrapeFidelity : public testing::TestWithParam<DrapeCase> {};

TEST_P(DrapeFidelity, BlockMeansMatchCore) {
    const DrapeCase& c = GetParam();
    SceneDescription scene = openScene("default_scene.json");
    const auto cloth = std::find_if(scene.materials.begin(), scene.materials.end(),
                                    [](const Material& m) { return m.woven.has_value(); });
    ASSERT_NE(cloth, scene.materials.end());
    std::vector<std::string> warnings;
    WovenParams p = materialFromJson(c.subject.material, WovenParams{}, WOVEN_ASSETS_DIR, warnings).params;
    const glm::vec2 denim = cloth->woven->repeat;
    p.repeat *= c.distance.repeatShare * 0.5f * (denim.x + denim.y) / (0.5f * (p.repeat.x + p.repeat.y));
    cloth->woven = p;
    const std::string name = c.name();
    expectFidelity(name, "drape_" + name, scene, 128, kDrapeWorstBound, kDrapeKnownMisses, std::size(kDrapeKnownMisses));
}

INSTANTIATE_TEST_SUITE_P(Shipped, DrapeFidelity, testing::ValuesIn(subjectsAt(kDrapeDistances)), caseName<DrapeDistance>);

}  // namespace
}  // namespace woven::test
