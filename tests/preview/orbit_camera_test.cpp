// The previewer's camera starts as exactly the camera `woven render` uses (sceneCamera), so the
// Render button's first frame is the command line's; moving it keeps +y up.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "demo_scene.h"
#include "orbit_camera.h"

namespace woven {
namespace {

TEST(OrbitCamera, StartsAsTheScenesCameraExactlyRollAndAspectIncluded) {
    SceneDescription scene = wavyClothScene(demoClothParams());
    // A rolled camera (25 degrees about its view axis) with its own aspect ratio.
    scene.camera.cameraToWorld = glm::rotate(scene.camera.cameraToWorld, glm::radians(25.0f), glm::vec3(0, 0, 1));
    scene.camera.aspect = 1.7f;
    OrbitCamera orbit = OrbitCamera::forScene(scene);
    EXPECT_EQ(orbit.camera().cameraToWorld, scene.camera.cameraToWorld);
    EXPECT_EQ(orbit.camera().yfov, scene.camera.yfov);
    EXPECT_EQ(orbit.camera().aspect, 1.7f);

    // The pivot lies on the view axis at the depth of the bounds' centre.
    const glm::vec3 eye(scene.camera.cameraToWorld[3]), forward = -glm::vec3(scene.camera.cameraToWorld[2]);
    const glm::vec3 toPivot = orbit.pivot() - eye;
    EXPECT_NEAR(glm::length(glm::cross(toPivot, forward)), 0.0f, 1e-4f * glm::length(toPivot));
    EXPECT_NEAR(orbit.distance(), glm::dot(sceneBounds(scene).centre() - eye, forward), 1e-4f);

    // Orbiting moves it about the pivot, upright: the roll is gone, the pivot stays in view.
    orbit.orbit(0.3f, 0.1f);
    const Camera moved = orbit.camera();
    EXPECT_NE(moved.cameraToWorld, scene.camera.cameraToWorld);
    EXPECT_EQ(moved.aspect, 1.7f);
    EXPECT_EQ(moved.yfov, scene.camera.yfov);
    EXPECT_NEAR(glm::vec3(moved.cameraToWorld[0]).y, 0.0f, 1e-6f);  // right vector horizontal
    const glm::vec3 movedForward = -glm::vec3(moved.cameraToWorld[2]);
    EXPECT_NEAR(glm::dot(glm::normalize(orbit.pivot() - glm::vec3(moved.cameraToWorld[3])), movedForward), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(orbit.pivot() - glm::vec3(moved.cameraToWorld[3])), orbit.distance(), 1e-4f);
}

TEST(OrbitCamera, WithoutASceneCameraItFramesTheBoundsAsCoreDoes) {
    SceneDescription scene = wavyClothScene(demoClothParams());
    scene.hasCamera = false;
    const OrbitCamera orbit = OrbitCamera::forScene(scene);
    const Camera expected = sceneCamera(scene);
    EXPECT_EQ(orbit.camera().cameraToWorld, expected.cameraToWorld);

    // framingCamera: looks at the box centre, the bounding sphere inside the vertical field of view.
    const SceneBox box = sceneBounds(scene);
    const glm::vec3 eye(expected.cameraToWorld[3]), forward = -glm::vec3(expected.cameraToWorld[2]);
    const glm::vec3 toCentre = box.centre() - eye;
    EXPECT_NEAR(glm::dot(glm::normalize(toCentre), forward), 1.0f, 1e-5f);
    const float sinHalfAngle = box.radius() / glm::length(toCentre);
    EXPECT_LT(sinHalfAngle, std::sin(0.5f * expected.yfov));
    EXPECT_GT(sinHalfAngle, 0.9f * std::sin(0.5f * expected.yfov));
    EXPECT_LT(forward.y, 0.0f);  // from above
}

}  // namespace
}  // namespace woven
