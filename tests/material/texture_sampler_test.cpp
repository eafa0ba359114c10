// TextureSampler against texel values worked out by hand: where glTF puts uv (0, 0), wrap modes,
// nearest and bilinear filtering, sRGB decoding, KHR_texture_transform and the coordinate set.
#include <gtest/gtest.h>

#include "image_io.h"
#include "texture_sampler.h"

namespace woven {
namespace {

// 2 x 2 bytes, row 0 at the top: red, green / blue, white (alpha 255, 128 / 64, 0).
std::vector<TextureImage> fourTexels() {
    TextureImage t;
    t.width = t.height = 2;
    t.bytes = {{255, 0, 0, 255}, {0, 255, 0, 128}, {0, 0, 255, 64}, {255, 255, 255, 0}};
    return {t};
}

TexCoords at(float u, float v) {
    TexCoords tc;
    tc.uv[0] = {u, v};
    tc.hasUv = true;
    return tc;
}

void expectNear(const glm::vec4& a, const glm::vec4& b, float eps = 1e-5f) {
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[c], b[c], eps) << "channel " << c;
}

TEST(TextureSampler, TexelCentresEdgesAndWrapModes) {
    const auto images = fourTexels();
    TextureRef ref;
    ref.image = 0;
    const TextureSampler repeat(ref, images);
    const glm::vec4 red(1, 0, 0, 1), green(0, 1, 0, 128 / 255.0f), blue(0, 0, 1, 64 / 255.0f);
    expectNear(repeat.eval(at(0.25f, 0.25f)), red);  // v = 0 is the image's top row
    expectNear(repeat.eval(at(0.75f, 0.25f)), green);
    expectNear(repeat.eval(at(0.25f, 0.75f)), blue);
    expectNear(repeat.eval(at(0.5f, 0.25f)), 0.5f * (red + green));  // bilinear between two
    expectNear(repeat.eval(at(0.0f, 0.25f)), 0.5f * (red + green));  // repeat blends across the edge
    expectNear(repeat.eval(at(3.25f, -1.75f)), red);

    ref.wrapS = TextureWrap::ClampToEdge;
    expectNear(TextureSampler(ref, images).eval(at(0.0f, 0.25f)), red);
    expectNear(TextureSampler(ref, images).eval(at(-5.0f, 0.25f)), red);
    ref.wrapS = TextureWrap::MirroredRepeat;
    // u = 1.25 mirrors back to 0.75 (green), u = 2.25 repeats the mirror to 0.25 (red).
    expectNear(TextureSampler(ref, images).eval(at(1.25f, 0.25f)), green);
    expectNear(TextureSampler(ref, images).eval(at(2.25f, 0.25f)), red);
    expectNear(TextureSampler(ref, images).eval(at(-0.25f, 0.25f)), red);
}

TEST(TextureSampler, NearestSrgbTransformAndCoordinateSet) {
    const auto images = fourTexels();
    TextureRef ref;
    ref.image = 0;
    ref.nearest = true;
    expectNear(TextureSampler(ref, images).eval(at(0.49f, 0.1f)), glm::vec4(1, 0, 0, 1));
    expectNear(TextureSampler(ref, images).eval(at(0.51f, 0.1f)), glm::vec4(0, 1, 0, 128 / 255.0f));

    // sRGB: colour channels decoded, alpha not. A grey 128 byte is 0.2158605 linear.
    TextureImage grey;
    grey.width = grey.height = 1;
    grey.bytes = {{128, 128, 128, 128}};
    TextureRef colour;
    colour.image = 0;
    colour.srgb = true;
    expectNear(TextureSampler(colour, {grey}).eval(at(0.3f, 0.3f)),
               glm::vec4(0.2158605f, 0.2158605f, 0.2158605f, 128 / 255.0f));

    // A transform that moves uv by half a texture picks the other texel; texCoord 1 reads uv[1].
    ref.uvTransform = glm::mat3(1, 0, 0, 0, 1, 0, 0.5f, 0, 1);
    ref.texCoord = 1;
    TexCoords tc = at(0.75f, 0.25f);  // set 0 would give green
    tc.uv[1] = {0.25f, 0.25f};        // set 1, shifted by 0.5: u = 0.75, green
    expectNear(TextureSampler(ref, images).eval(tc), glm::vec4(0, 1, 0, 128 / 255.0f));
    tc.uv[1] = {0.75f, 0.25f};  // shifted to 1.25 -> repeat -> 0.25: red
    expectNear(TextureSampler(ref, images).eval(tc), glm::vec4(1, 0, 0, 1));
}

TEST(TextureSampler, FloatTexturesAndNoTexture) {
    TextureImage f;
    f.width = f.height = 1;
    f.floats = {{2.5f, 0.5f, 0.25f, 1.0f}};
    TextureRef ref;
    ref.image = 0;
    expectNear(TextureSampler(ref, {f}).eval(at(0.7f, 0.2f)), glm::vec4(2.5f, 0.5f, 0.25f, 1.0f));
    const TextureSampler none;
    EXPECT_FALSE(none);
    expectNear(none.eval(at(0.1f, 0.1f), glm::vec4(0.3f)), glm::vec4(0.3f));
    // Non-finite coordinates give a texel, never undefined behaviour.
    const glm::vec4 v = TextureSampler(ref, {f}).eval(at(NAN, INFINITY));
    EXPECT_TRUE(std::isfinite(v.r));
    ref.image = 3;
    EXPECT_THROW(TextureSampler(ref, {f}), std::out_of_range);
}

}  // namespace
}  // namespace woven
