#include "render_scene.h"

#include <gtest/gtest.h>

#include "scene_loader.h"
#include "test_scenes.h"

namespace woven {
namespace {

using test::quad;
using test::sceneWith;

// A 2 x 1 quad in the z = 0 plane facing +z, uv over [0, 1]^2: dp/du = (2, 0, 0), dp/dv = (0, 1, 0).
std::shared_ptr<SceneDescription> flatQuadScene() {
    return sceneWith({quad("quad", {0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0})});
}

TEST(RenderSceneIntersect, KnownQuadGivesDistancePointNormalsUvAndDerivatives) {
    RenderScene scene(flatQuadScene());
    Ray ray;
    ray.o = {0.5f, 0.1f, 3.0f};
    ray.d = {0.0f, 0.0f, -1.0f};
    const auto hit = scene.intersect(ray);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(hit->p, glm::vec3(0.5f, 0.1f, 0.0f)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(hit->ng, glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(hit->ns, glm::vec3(0, 0, 1)), 0.0f, 1e-6f);  // no normals: ns = ng
    EXPECT_NEAR(glm::distance(hit->uv, glm::vec2(0.25f, 0.1f)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(hit->dpdu, glm::vec3(2, 0, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(hit->dpdv, glm::vec3(0, 1, 0)), 0.0f, 1e-5f);
    EXPECT_EQ(hit->mesh, 0);
    EXPECT_EQ(hit->triangle, 0);  // below the diagonal from (0, 0) to (2, 1)
}

TEST(RenderSceneIntersect, MissesBesideTheQuadAndPastTMax) {
    RenderScene scene(flatQuadScene());
    Ray ray;
    ray.o = {2.5f, 0.5f, 1.0f};
    ray.d = {0.0f, 0.0f, -1.0f};
    EXPECT_FALSE(scene.intersect(ray));
    ray.o = {1.0f, 0.5f, 1.0f};
    ray.tMax = 0.99f;
    EXPECT_FALSE(scene.intersect(ray));
    ray.tMax = 1.01f;
    EXPECT_TRUE(scene.intersect(ray));
}

TEST(RenderSceneValidation, NanVertexNamesTheMesh) {
    auto scene = flatQuadScene();
    scene->meshes[0].positions[2].y = std::nanf("");
    try {
        RenderScene rs(scene);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("test.gltf"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'quad'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("vertex 2"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace woven
