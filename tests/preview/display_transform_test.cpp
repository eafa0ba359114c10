// The window shows the preview through shaders/display.frag and the rendered frame through
// core's displayColor(), which PNG output also uses: the two must agree, or the live preview and
// the saved picture would differ in brightness or contrast.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "demo_scene.h"
#include "gl_test_context.h"
#include "display_transform.h"

namespace woven::test {
namespace {

// An RGBA8 target of w x h pixels, cleared to magenta, that display() draws into.
class DisplayTarget {
public:
    DisplayTarget(int w, int h) : w_(w), h_(h) {
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glGenFramebuffers(1, &framebuffer_);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture_, 0);
        EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
    }
    ~DisplayTarget() {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &framebuffer_);
        glDeleteTextures(1, &texture_);
    }
    // What `renderer` shows through `transform`, row 0 at the top.
    std::vector<glm::u8vec4> show(PreviewRenderer& renderer, const DisplayTransform& transform) {
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glViewport(0, 0, w_, h_);
        glClearColor(1.0f, 0.0f, 1.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        renderer.display(framebuffer_, {0, 0}, {w_, h_}, transform);
        std::vector<glm::u8vec4> bottomUp(size_t(w_) * h_), shown(bottomUp.size());
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, w_, h_, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
        for (int y = 0; y < h_; ++y)  // GL's row 0 is the bottom one
            std::copy_n(&bottomUp[size_t(h_ - 1 - y) * w_], w_, &shown[size_t(y) * w_]);
        return shown;
    }

private:
    int w_, h_;
    GLuint texture_ = 0, framebuffer_ = 0;
};

// The procedural cloth with bright highlights, lit strongly so values span 0 to well over 1.
SceneDescription brightCloth() {
    SceneDescription scene = wavyClothScene(demoClothParams());
    for (PunctualLight& l : scene.lights) l.intensity *= 8.0f;
    return scene;
}

TEST(DisplayTransform, ShaderMatchesCoresDisplayColorForEveryCurve) {
    ensureHeadlessGl();
    const int w = 96, h = 64;
    const SceneDescription scene = brightCloth();
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    renderer.render(scene, PreviewLights::fromScene(scene), scene.camera, {w, h}, {});
    const Image radiance = renderer.radiance();
    float brightest = 0.0f;
    for (const glm::vec3& c : radiance.pixels) brightest = std::max({brightest, c.r, c.g, c.b});
    ASSERT_GT(brightest, 2.0f) << "the test image should reach the shoulder of every curve";

    DisplayTarget target(w, h);
    for (ToneMap curve : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces})
        for (float exposure : {-1.0f, 0.0f, 1.5f}) {
            const DisplayTransform transform{exposure, curve};
            const std::vector<glm::u8vec4> shown = target.show(renderer, transform);
            int worst = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const glm::u8vec3 expected = displayColor(radiance.at(x, y), transform);
                    const glm::u8vec4 got = shown[size_t(y) * w + x];
                    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(got[c]) - int(expected[c])));
                }
            // The GPU rounds its float result to 8 bits itself, and its pow() may differ from
            // std::pow in the last bits: one code apart at most. A different curve or a missed
            // exposure is tens of codes off in the bright pixels.
            EXPECT_LE(worst, 1) << "tone map " << int(curve) << ", exposure " << exposure;
        }
}

// While the camera moves the window renders at a reduced size and shows it scaled up
// (InteractiveResolution): it must fill the window, with the full frame's look.
TEST(DisplayTransform, AFrameRenderedSmallerFillsTheWindowWithTheSameLook) {
    ensureHeadlessGl();
    const int w = 96, h = 64;
    const SceneDescription scene = brightCloth();
    const PreviewLights lights = PreviewLights::fromScene(scene);
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    DisplayTarget target(w, h);
    const DisplayTransform transform{0.5f, ToneMap::Aces};
    renderer.render(scene, lights, scene.camera, {w, h}, {});
    const std::vector<glm::u8vec4> full = target.show(renderer, transform);
    const std::vector<glm::u8vec4> brighter = target.show(renderer, {transform.exposure + 0.25f, transform.toneMap});
    renderer.render(scene, lights, scene.camera, {w / 2, h / 2}, {});
    const std::vector<glm::u8vec4> half = target.show(renderer, transform);

    glm::dvec3 meanFull(0.0), meanBrighter(0.0), meanHalf(0.0);
    for (size_t i = 0; i < full.size(); ++i) {
        ASSERT_NE(half[i], glm::u8vec4(255, 0, 255, 255)) << "pixel " << i << " was not drawn";
        meanFull += glm::dvec3(full[i]);
        meanBrighter += glm::dvec3(brighter[i]);
        meanHalf += glm::dvec3(half[i]);
    }
    // The same exposure and curve: the half-size frame's mean colour is within a fifth of what a
    // quarter stop more exposure moves it (about 6 codes here) of the full frame's; it measured
    // 0.4 codes off. Scaling the radiance up before the tone curve, which bends, would brighten
    // every edge: 3.3 codes.
    for (int c = 0; c < 3; ++c)
        EXPECT_LT(std::abs(meanHalf[c] - meanFull[c]), 0.2 * (meanBrighter[c] - meanFull[c])) << "channel " << c;
}

}  // namespace
}  // namespace woven::test
