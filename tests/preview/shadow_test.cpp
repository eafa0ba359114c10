// The preview's shadows (ShadowMaps): a square hovering over the flat cloth must block a point
// light (cube map; turned six ways so each cube face does the work), a distant point light
// (perspective map) and a directional light (orthographic map) exactly where geometry says, and
// change nothing elsewhere.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <iostream>

#include "flat_cloth.h"
#include "gl_test_context.h"

namespace woven::test {
namespace {

constexpr float kHeight = 0.5f, kHalf = 0.2f;  // the occluder: y = 0.5, |x|, |z| < 0.2

SceneDescription occludedCloth(const PunctualLight& light) {
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
    scene.materials.push_back(Material{});
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

}  // namespace
}  // namespace woven::test
