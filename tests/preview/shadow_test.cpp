// The preview's shadows (ShadowMaps): a square hovering over the flat cloth must block a point
// light (cube map; turned six ways so each cube face does the work), a distant point light
// (perspective map) and a directional light (orthographic map) exactly where geometry says, and
// change nothing elsewhere. A square that lets light through (woven yarns that transmit, glTF
// diffuse transmission) must pass, per colour, the share of the light its material passes.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>
#include <iostream>

#include "flat_cloth.h"
#include "gl_test_context.h"
#include "weave.h"
#include "weave_coverage.h"
#include "yarn_transmission.h"

namespace woven::test {
namespace {

constexpr float kHeight = 0.5f, kHalf = 0.2f;  // the occluder: y = 0.5, |x|, |z| < 0.2

SceneDescription occludedCloth(const PunctualLight& light, const Material& occluder = Material{}) {
    WovenParams p;
    p.repeat = glm::vec2(30.0f);  // near and far field both in view
    p.yarn_width = p.warp_width = 1.0f;  // no see-through gaps
    SceneDescription scene = flatClothScene(p);
    scene.lights = {light};
    Mesh square;
    square.name = "occluder";
    square.positions = {{-kHalf, kHeight, kHalf}, {kHalf, kHeight, kHalf}, {kHalf, kHeight, -kHalf}, {-kHalf, kHeight, -kHalf}};
    square.triangles = {{0, 1, 2}, {0, 2, 3}};
    square.material = 1;
    scene.meshes.push_back(square);
    scene.materials.push_back(occluder);
    return scene;
}

// How far `q` (on the plane y = kHeight) is inside the square: negative outside.
float insideSquare(const glm::vec3& q) { return kHalf - std::max(std::abs(q.x), std::abs(q.z)); }

// The scene turned by `rotation` as a whole: the same picture, other cube faces.
SceneDescription turned(SceneDescription scene, const glm::mat3& rotation) {
    for (Mesh& m : scene.meshes) {
        for (glm::vec3& p : m.positions) p = rotation * p;
        for (glm::vec3& n : m.normals) n = rotation * n;
    }
    for (PunctualLight& l : scene.lights) {
        l.position = rotation * l.position;
        l.direction = rotation * l.direction;
    }
    scene.camera.cameraToWorld = glm::mat4(rotation) * scene.camera.cameraToWorld;
    return scene;
}

void expectShadowWhereGeometrySaysSo(const PunctualLight& light, const glm::mat3& rotation = glm::mat3(1.0f)) {
    const SceneDescription scene = occludedCloth(light);  // the geometry below is worked out here
    const int w = 256, h = 192;
    const Image shadowed = previewRadiance(turned(scene, rotation), w, h, true, false, true);
    const Image open = previewRadiance(turned(scene, rotation), w, h, true, false, false);

    const glm::vec3 eye(scene.camera.cameraToWorld[3]);
    // Pixel centres whose floor point is 0.05 (several shadow-map texels) or more from the
    // shadow's edge; near the edge the filtered lookup is partial, as a soft edge should be.
    constexpr float kMargin = 0.05f;
    size_t inShadow = 0, lit = 0, reachedWithoutShadows = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3 d = cameraRayDirection(scene.camera, x + 0.5f, y + 0.5f, w, h);
            if (d.y >= 0.0f) continue;
            if (insideSquare(eye + d * ((kHeight - eye.y) / d.y)) > -kMargin) continue;  // sees the occluder
            const glm::vec3 p = eye + d * (-eye.y / d.y);
            if (std::max(std::abs(p.x), std::abs(p.z)) > 1.0f - kMargin) continue;  // off or at the cloth's edge
            // Where the segment from p towards the light crosses the occluder's plane.
            const glm::vec3 toLight = light.type == PunctualLight::Type::Directional ? -light.direction
                                                                                     : light.position - p;
            const float depth = insideSquare(p + toLight * (kHeight / toLight.y));
            const size_t i = size_t(y) * w + x;
            if (depth > kMargin) {
                ++inShadow;
                EXPECT_EQ(shadowed.pixels[i], glm::vec3(0.0f)) << "pixel " << x << "," << y << " should be in shadow";
                reachedWithoutShadows += open.pixels[i].g > 0.0f;
            } else if (depth < -kMargin) {
                ++lit;
                // Turning the scene rounds its numbers differently: equal within float rounding.
                EXPECT_NEAR(shadowed.pixels[i].g, open.pixels[i].g, 1e-5f * (1.0f + open.pixels[i].g))
                    << "pixel " << x << "," << y << " should be lit";
            }
        }
    std::cout << inShadow << " pixels in shadow, " << lit << " lit\n";
    EXPECT_GT(inShadow, size_t(300));
    // Without shadows the light reaches those pixels, but for yarn edges whose bumped normal
    // faces away from it (a fraction of a percent here).
    EXPECT_GT(double(reachedWithoutShadows), 0.98 * double(inShadow));
    EXPECT_GT(lit, size_t(w * h / 4));
}

PunctualLight pointLight(const glm::vec3& position, float intensity) {
    PunctualLight point;
    point.type = PunctualLight::Type::Point;
    point.position = position;
    point.intensity = glm::vec3(intensity);
    return point;
}

class CubeFace : public testing::TestWithParam<int> {};

// The light above the cloth looks down (-y) at the occluder and the floor; turning the scene
// takes that direction to each of the six cube faces in turn.
TEST_P(CubeFace, NearPointLightIsBlockedExactlyWhereTheOccluderProjects) {
    const glm::vec3 x(1, 0, 0), z(0, 0, 1);
    const glm::mat4 turns[6] = {glm::mat4(1.0f),                         // -y stays -y
                                glm::rotate(glm::mat4(1.0f), float(M_PI), x),   // -y to +y
                                glm::rotate(glm::mat4(1.0f), float(M_PI_2), z),  // -y to +x
                                glm::rotate(glm::mat4(1.0f), -float(M_PI_2), z), // -y to -x
                                glm::rotate(glm::mat4(1.0f), -float(M_PI_2), x), // -y to +z
                                glm::rotate(glm::mat4(1.0f), float(M_PI_2), x)}; // -y to -z
    expectShadowWhereGeometrySaysSo(pointLight({-0.5f, 1.5f, 0.4f}, 3.0f), glm::mat3(turns[GetParam()]));
}
INSTANTIATE_TEST_SUITE_P(PreviewShadows, CubeFace, testing::Range(0, 6));

TEST(PreviewShadows, DistantPointLightIsBlockedExactlyWhereTheOccluderProjects) {
    // 16 units away, 11 bounding radii: a perspective map fitted to the scene, not a cube.
    expectShadowWhereGeometrySaysSo(pointLight({-5.0f, 15.0f, 4.0f}, 300.0f));
}

TEST(PreviewShadows, DirectionalLightIsBlockedExactlyWhereTheOccluderProjects) {
    PunctualLight sun;
    sun.type = PunctualLight::Type::Directional;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
    sun.intensity = glm::vec3(1.0f);
    expectShadowWhereGeometrySaysSo(sun);
}

// The floor behind an occluder in `sheet`: per pixel well inside its shadow (as above), the light
// that reaches the floor with shadows over the light without them, per colour, must be
// `passed(mu)`, mu the cosine between the light's direction and the sheet's normal. With the
// environment off, the floor's radiance is its BSDF times that one light, so the ratio is the
// shadow's factor alone. Returns the mean ratio.
glm::vec3 expectShadowPasses(const PunctualLight& light, const Material& sheet, const std::function<glm::vec3(float)>& passed) {
    const SceneDescription scene = occludedCloth(light, sheet);
    const int w = 256, h = 192;
    const Image shadowed = previewRadiance(scene, w, h, true, false, true);
    const Image open = previewRadiance(scene, w, h, true, false, false);
    const glm::vec3 eye(scene.camera.cameraToWorld[3]);
    constexpr float kMargin = 0.05f;  // as in expectShadowWhereGeometrySaysSo
    // The transmitted colour is stored in 8 bits a channel (half a step: 0.002) and filtered
    // bilinearly over texels whose cosines differ by under 1e-3 this far inside the square: 0.005
    // is two and a half steps, and a wrong factor (a missed Fresnel, the cosine, the colour's
    // square) is off by 0.02 or more.
    constexpr float kTolerance = 0.005f;
    glm::dvec3 sum(0.0);
    size_t inShadow = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3 d = cameraRayDirection(scene.camera, x + 0.5f, y + 0.5f, w, h);
            if (d.y >= 0.0f) continue;
            if (insideSquare(eye + d * ((kHeight - eye.y) / d.y)) > -kMargin) continue;  // sees the occluder
            const glm::vec3 p = eye + d * (-eye.y / d.y);
            if (std::max(std::abs(p.x), std::abs(p.z)) > 1.0f - kMargin) continue;
            const glm::vec3 toLight = light.type == PunctualLight::Type::Directional ? -light.direction
                                                                                     : light.position - p;
            if (insideSquare(p + toLight * (kHeight / toLight.y)) <= kMargin) continue;
            const size_t i = size_t(y) * w + x;
            // Yarn edges whose bumped normal faces away from the light get none either way.
            if (!(glm::min(open.pixels[i].r, glm::min(open.pixels[i].g, open.pixels[i].b)) > 0.0f)) continue;
            ++inShadow;
            const glm::vec3 ratio = shadowed.pixels[i] / open.pixels[i];
            const glm::vec3 expected = passed(std::abs(toLight.y) / glm::length(toLight));
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(ratio[c], expected[c], kTolerance) << "pixel " << x << "," << y << " channel " << c;
            sum += glm::dvec3(ratio);
        }
    EXPECT_GT(inShadow, size_t(300));
    return glm::vec3(sum / double(std::max<size_t>(inShadow, 1)));
}

// A woven sheet of red yarns that pass all they do not reflect, diffusely (gloss 0, so the
// shadow's share, yarnTransmittedAlbedo() in woven_transmission.glsl, is exactly the yarn's
// transmitted albedo), with see-through gaps between them.
Material redVoile(float transmission) {
    WovenParams p;
    p.warp_color = p.weft_color = glm::vec3(0.6f, 0.15f, 0.1f);
    p.transmission = transmission;
    p.transmission_gloss = 0.0f;
    p.yarn_width = p.warp_width = 0.8f;
    Material m;
    m.woven = p;
    return m;
}

// Core's YarnTransmission of the voile's yarn integrated over the far side's hemisphere for light
// arriving at cosine mu, by the midpoint rule over (cosine, azimuth): 64 x 64 cells, well under
// 1e-4 for this smooth, azimuth-free lobe.
glm::vec3 transmittedAlbedo(const WovenParams& p, float mu) {
    const YarnTransmission yarn(LobeShape(p.ex, p.ey, p.rs), yarnTransmittance(p.weft_color, p.transmission),
                                p.transmission_gloss);
    const glm::vec3 wi(std::sqrt(1.0f - mu * mu), 0.0f, mu);
    const int n = 64;
    glm::dvec3 sum(0.0);
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const float cosine = (a + 0.5f) / n, phi = 2.0f * float(M_PI) * (b + 0.5f) / n;
            const float sine = std::sqrt(1.0f - cosine * cosine);
            const glm::vec3 wo(sine * std::cos(phi), sine * std::sin(phi), -cosine);
            sum += glm::dvec3(yarn.eval(wo, wi)) * double(cosine);
        }
    return glm::vec3(sum * (2.0 * M_PI / (n * n)));
}

TEST(PreviewShadows, WovenYarnsAndGapsThatPassLightCastTheirColouredShadow) {
    const Material voile = redVoile(1.0f);
    const WeaveCoverage coverage = weaveCoverage(Weave(*voile.woven), false);
    const float yarns = coverage.weft + coverage.warp;
    ASSERT_LT(yarns, 0.99f);  // gaps, which pass everything
    // The crossing yarns pass the albedo, the gaps all the light.
    auto passed = [&](float mu) { return yarns * transmittedAlbedo(*voile.woven, mu) + glm::vec3(1.0f - yarns); };
    const glm::vec3 cube = expectShadowPasses(pointLight({-0.5f, 1.5f, 0.4f}, 3.0f), voile, passed);
    PunctualLight sun;
    sun.type = PunctualLight::Type::Directional;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
    sun.intensity = glm::vec3(1.0f);
    const glm::vec3 flat = expectShadowPasses(sun, voile, passed);
    std::cout << "red voile's shadow passes " << cube.r << " " << cube.g << " " << cube.b << " (cube), " << flat.r << " "
              << flat.g << " " << flat.b << " (flat)\n";
    // Lit, darker than the open floor, and red: T = (0.40, 0.053, 0.025) before the gaps.
    for (const glm::vec3& c : {cube, flat}) {
        EXPECT_LT(c.r, 0.9f);
        EXPECT_GT(c.r, c.g + 0.1f);
        EXPECT_GT(c.g, 1.0f - yarns - 0.01f);  // the gaps' share at least
    }
    // The same cloth with yarns that pass nothing passes its gaps' share alone, as core's rays
    // pass the gaps (shadow_maps.h); with a backing behind the gaps it is an opaque caster.
    expectShadowPasses(sun, redVoile(0.0f), [&](float) { return glm::vec3(1.0f - yarns); });
    Material backed = redVoile(0.0f);
    backed.woven->backing = 1;
    expectShadowPasses(sun, backed, [](float) { return glm::vec3(0.0f); });
}

TEST(PreviewShadows, DiffuseTransmissionCastsItsColouredShadow) {
    Material leaf;
    leaf.baseColor = glm::vec4(0.3f, 0.5f, 0.2f, 1.0f);
    leaf.diffuseTransmission.factor = 0.7f;
    leaf.diffuseTransmission.color = glm::vec3(0.2f, 0.8f, 0.3f);
    // The factor x colour through the dielectric's Fresnel at normal incidence, F0 = 0.04 for an IOR
    // of 1.5, whatever the angle (the BTDF is Lambertian).
    const glm::vec3 expected = 0.7f * (1.0f - 0.04f) * leaf.diffuseTransmission.color;
    const glm::vec3 cube = expectShadowPasses(pointLight({-0.5f, 1.5f, 0.4f}, 3.0f), leaf, [&](float) { return expected; });
    EXPECT_GT(cube.g, 2.0f * cube.r);
}

}  // namespace
}  // namespace woven::test
