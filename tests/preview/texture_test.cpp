// A glTF material's base colour texture in the preview: sampled where glTF puts it (v = 0 at
// the image's top row) and multiplying the diffuse reflectance, as core's renderer does.
#include <gtest/gtest.h>

#include <cmath>

#include "flat_cloth.h"
#include "gl_test_context.h"

namespace woven::test {
namespace {

// 8 x 8 texels in 2 x 2 blocks of 4 x 4, each block its own colour: top-left red, top-right
// green, bottom-left blue, bottom-right grey.
const glm::vec3 kBlock[2][2] = {{{0.8f, 0.1f, 0.1f}, {0.1f, 0.7f, 0.2f}}, {{0.1f, 0.2f, 0.9f}, {0.5f, 0.5f, 0.5f}}};

SceneDescription texturedFloor(bool textured, glm::vec3 baseColor) {
    SceneDescription scene = flatClothScene(WovenParams{});
    Material standard;
    standard.roughness = 0.5f;
    standard.baseColor = glm::vec4(baseColor, 1.0f);
    if (textured) {
        TextureImage image;  // float texels: taken as linear, exactly
        image.width = image.height = 8;
        image.floats.resize(64);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x) image.floats[size_t(y) * 8 + x] = glm::vec4(kBlock[y / 4][x / 4], 1.0f);
        scene.textures.push_back(image);
        standard.baseColorTexture.image = 0;
    }
    scene.materials[0] = standard;
    return scene;
}

TEST(PreviewTexture, BaseColourTextureMultipliesTheDiffuseWhereGltfPutsIt) {
    const int w = 160, h = 120;
    const Image textured = previewRadiance(texturedFloor(true, glm::vec3(1.0f)), w, h, true, false, false);
    Image plain[2][2];
    for (int by = 0; by < 2; ++by)
        for (int bx = 0; bx < 2; ++bx) plain[by][bx] = previewRadiance(texturedFloor(false, kBlock[by][bx]), w, h, true, false, false);

    const SceneDescription scene = texturedFloor(true, glm::vec3(1.0f));
    const glm::vec3 eye(scene.camera.cameraToWorld[3]);
    int checked[2][2] = {};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3 d = cameraRayDirection(scene.camera, x + 0.5f, y + 0.5f, w, h);
            const glm::vec3 p = eye + d * (-eye.y / d.y);
            if (d.y >= 0.0f || std::max(std::abs(p.x), std::abs(p.z)) > 0.98f) continue;
            const glm::vec2 uv((p.x + 1.0f) / 2.0f, (1.0f - p.z) / 2.0f);
            // Texel units from the block edges: at least 1.5 texels in, the bilinear lookup sees one colour.
            const glm::vec2 texel = uv * 8.0f;
            if (std::abs(texel.x - 4.0f) < 1.5f || std::abs(texel.y - 4.0f) < 1.5f) continue;
            if (texel.x < 1.5f || texel.y < 1.5f || texel.x > 6.5f || texel.y > 6.5f) continue;  // repeat wrap blends the edges
            const int bx = texel.x < 4.0f ? 0 : 1, by = texel.y < 4.0f ? 0 : 1;
            const glm::vec3 got = textured.at(x, y), want = plain[by][bx].at(x, y);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(got[c], want[c], 1e-5f + 1e-4f * want[c]) << "pixel " << x << "," << y << " block " << bx << by;
            ++checked[by][bx];
        }
    for (int by = 0; by < 2; ++by)
        for (int bx = 0; bx < 2; ++bx) EXPECT_GT(checked[by][bx], 50) << "block " << bx << by;
}

}  // namespace
}  // namespace woven::test
