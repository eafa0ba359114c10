// RenderedViewport without a window: what starts the view again, what it builds again, and that a
// frame depends on the view's state alone. Every wait is for the view to be idle; nothing is timed.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <atomic>

#include "orbit_camera.h"
#include "rendered_viewport.h"
#include "scene_loader.h"

namespace woven {
namespace {

struct ViewState {
    SceneDescription scene = loadScene(std::string(WOVEN_ASSETS_DIR) + "/default_scene.json");
    RenderSettings settings;

    ViewState() {
        settings = viewportSettings(defaultRenderSettings(scene));
        settings.width = 32;
        settings.height = 24;
        settings.spp = 2;
        settings.camera = OrbitCamera::forScene(scene).camera();
    }
    WovenParams& cloth() {
        for (Material& m : scene.materials)
            if (m.woven) return *m.woven;
        throw std::runtime_error("no woven material");
    }
};

ViewportProgress showAndWait(RenderedViewport& view, const ViewState& state, bool interacting = false) {
    view.show(state.scene, state.settings, interacting, false);
    view.waitUntilIdle();
    EXPECT_EQ(view.error(), "");
    return view.progress();
}

TEST(RenderedViewport, SettingsAreTheRenderButtonsWithEveryPixelSampledAndAutoThePathTracer) {
    RenderSettings button;
    button.noiseThreshold = 0.05;
    button.integrator = "auto";
    const RenderSettings view = viewportSettings(button);
    EXPECT_EQ(view.noiseThreshold, 0.0);
    EXPECT_EQ(view.integrator, "path");
    button.integrator = "bdpt";
    EXPECT_EQ(viewportSettings(button).integrator, "bdpt");
}

TEST(RenderedViewport, AnUnchangedViewDoesNotStartAgain) {
    ViewState state;
    RenderedViewport view;
    const ViewportProgress first = showAndWait(view, state);
    EXPECT_TRUE(first.converged);
    EXPECT_EQ(first.samples, 2);
    EXPECT_EQ(first.restarts, 1u);
    EXPECT_EQ(first.builds, 1u);
    EXPECT_EQ(first.bvhBuilds, 1u);
    EXPECT_EQ(showAndWait(view, state).restarts, 1u);
    // A button held over the view that changes nothing (a header clicked) changes nothing.
    EXPECT_EQ(showAndWait(view, state, true).restarts, 1u);
}

TEST(RenderedViewport, ACameraMoveRendersTheSceneAlreadyBuiltAndMovingBackTheSameFrame) {
    ViewState state;
    RenderedViewport view;
    showAndWait(view, state);
    const FilmImage before = *view.frame();
    const Camera original = *state.settings.camera;
    state.settings.camera->cameraToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.01f, 0.0f, 0.0f)) * original.cameraToWorld;
    const ViewportProgress moved = showAndWait(view, state);
    EXPECT_EQ(moved.restarts, 2u);
    EXPECT_EQ(moved.builds, 1u);
    EXPECT_EQ(moved.bvhBuilds, 1u);
    EXPECT_FALSE(view.frame()->radiance.pixels == before.radiance.pixels);
    state.settings.camera = original;
    EXPECT_EQ(showAndWait(view, state).builds, 1u);
    EXPECT_TRUE(view.frame()->radiance.pixels == before.radiance.pixels);
}

TEST(RenderedViewport, AMaterialEditBuildsTheMaterialsAgainOnTheBvhAlreadyBuilt) {
    ViewState state;
    RenderedViewport view;
    showAndWait(view, state);
    const FilmImage before = *view.frame();
    state.cloth().ex += 20.0f;
    const ViewportProgress edited = showAndWait(view, state);
    EXPECT_EQ(edited.restarts, 2u);
    EXPECT_EQ(edited.builds, 2u);
    EXPECT_EQ(edited.bvhBuilds, 1u);
    EXPECT_FALSE(view.frame()->radiance.pixels == before.radiance.pixels);
    // The frame of the edited scene built whole, bit for bit.
    RenderJob whole(std::make_shared<const SceneDescription>(state.scene), state.settings);
    std::atomic<bool> cancel{false};
    whole.run(cancel);
    EXPECT_TRUE(view.frame()->radiance.pixels == whole.snapshot().radiance.pixels);
}

TEST(RenderedViewport, OnlyAGeometryChangeBuildsTheBvhAgain) {
    ViewState state;
    RenderedViewport view;
    showAndWait(view, state);
    state.scene.environment.color *= 1.5f;  // a light edit
    EXPECT_EQ(showAndWait(view, state).bvhBuilds, 1u);
    state.scene.meshes[0].positions[0].y += 0.01f;
    const ViewportProgress moved = showAndWait(view, state);
    EXPECT_EQ(moved.builds, 3u);
    EXPECT_EQ(moved.bvhBuilds, 2u);
}

TEST(RenderedViewport, TheEndOfADragStartsAgainAtFullSizeDenoised) {
    ViewState state;
    RenderedViewport view;
    showAndWait(view, state);
    state.cloth().ex += 20.0f;
    const ViewportProgress dragged = showAndWait(view, state, true);
    EXPECT_EQ(dragged.restarts, 2u);
    EXPECT_EQ(dragged.denoisedAt, 0);  // no denoising while interacting (nor asked for here)
    view.show(state.scene, state.settings, false, true);
    view.waitUntilIdle();
    const ViewportProgress rested = view.progress();
    EXPECT_EQ(rested.restarts, 3u);
    EXPECT_EQ(rested.width, 32);
    EXPECT_EQ(rested.height, 24);
    EXPECT_TRUE(rested.converged);
    EXPECT_EQ(rested.denoisedAt, 2);  // the last pass is denoised
    EXPECT_TRUE(view.frame()->denoised.has_value());
}

TEST(RenderedViewport, StopForgetsTheFrame) {
    ViewState state;
    RenderedViewport view;
    showAndWait(view, state);
    view.stop();
    view.waitUntilIdle();
    EXPECT_FALSE(view.frame().has_value());
    EXPECT_EQ(view.progress().samples, 0);
    // Shown again, it starts again.
    EXPECT_EQ(showAndWait(view, state).samples, 2);
}

TEST(RenderedViewport, AFailedStartIsItsError) {
    ViewState state;
    state.scene.environment = Environment{};
    state.scene.lights.clear();
    for (Material& m : state.scene.materials) m.emission = glm::vec3(0.0f);
    RenderedViewport view;
    view.show(state.scene, state.settings, false, false);
    view.waitUntilIdle();
    EXPECT_NE(view.error().find("no lights"), std::string::npos) << view.error();
}

}  // namespace
}  // namespace woven
