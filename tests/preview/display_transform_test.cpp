// The window shows the preview through shaders/display.frag and the rendered frame through
// core's displayColor(), which PNG output also uses: the two must agree, or the live preview and
// the saved picture would differ in brightness or contrast.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>

#include "demo_scene.h"
#include "gl_test_context.h"

namespace woven::test {
namespace {

TEST(DisplayTransform, ShaderMatchesCoresDisplayColorForEveryCurve) {
    ensureHeadlessGl();
    const int w = 96, h = 64;
    // The procedural cloth with bright highlights, lit strongly so values span 0 to well over 1.
    SceneDescription scene = wavyClothScene(demoClothParams());
    for (PunctualLight& l : scene.lights) l.intensity *= 8.0f;
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    renderer.render(scene, PreviewLights::fromScene(scene), scene.camera, {w, h}, {});
    const Image radiance = renderer.radiance();
    float brightest = 0.0f;
    for (const glm::vec3& c : radiance.pixels) brightest = std::max({brightest, c.r, c.g, c.b});
    ASSERT_GT(brightest, 2.0f) << "the test image should reach the shoulder of every curve";

    GLuint target = 0, framebuffer = 0;
    glGenTextures(1, &target);
    glBindTexture(GL_TEXTURE_2D, target);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));

    for (ToneMap curve : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces})
        for (float exposure : {-1.0f, 0.0f, 1.5f}) {
            const DisplayTransform transform{exposure, curve};
            renderer.display(framebuffer, {0, 0}, transform);
            std::vector<glm::u8vec4> shown(size_t(w) * h);
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
            glPixelStorei(GL_PACK_ALIGNMENT, 1);
            glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, shown.data());
            int worst = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const glm::u8vec3 expected = displayColor(radiance.at(x, y), transform);
                    const glm::u8vec4 got = shown[size_t(h - 1 - y) * w + x];  // GL's row 0 is the bottom
                    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(got[c]) - int(expected[c])));
                }
            // The GPU rounds its float result to 8 bits itself, and its pow() may differ from
            // std::pow in the last bits: one code apart at most. A different curve or a missed
            // exposure is tens of codes off in the bright pixels.
            EXPECT_LE(worst, 1) << "tone map " << int(curve) << ", exposure " << exposure;
        }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &target);
}

}  // namespace
}  // namespace woven::test
