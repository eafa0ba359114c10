// Woven scene files (.json): every key applied to the loaded scene, and every mistake reported
// with the file and the key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <fstream>

#include "gltf_builder.h"
#include "scene_loader.h"
#include "temp_dir.h"

namespace woven {
namespace {

using test::GltfBuilder;
using test::TempDir;
using ::testing::HasSubstr;
using json = nlohmann::json;

// Two materials, "Cloth" (already woven: ex 300) and "Floor", on two triangles, in sub/scene.gltf.
class SceneFile : public ::testing::Test {
protected:
    void SetUp() override {
        std::filesystem::create_directory(dir.file("sub"));
        GltfBuilder b;
        const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        b.addMaterial({{"name", "Cloth"}, {"extensions", {{"WOVEN_fabric", {{"ex", 300}}}}}});
        b.addMaterial({{"name", "Floor"}});
        const int position = b.addPositions(p);
        b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", position}}}, {"material", 0}})}}),
                    b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", position}}}, {"material", 1}})}})});
        b.writeGltf(dir.file("sub/scene.gltf"));
    }

    std::string write(const json& scene, const std::string& name = "scene.json") {
        const std::string path = dir.file(name);
        std::ofstream(path) << scene.dump(2);
        return path;
    }

    std::string error(const json& scene) {
        const std::string path = write(scene);
        try {
            loadScene(path);
        } catch (const SceneError& e) {
            EXPECT_THAT(e.what(), HasSubstr(path + ": "));
            return e.what();
        }
        return "(no error)";
    }

    TempDir dir;
};

TEST_F(SceneFile, EveryKeyIsApplied) {
    const float hdr[6] = {1, 2, 3, 4, 5, 6};
    ASSERT_TRUE(stbi_write_hdr(dir.file("sub/sky.hdr").c_str(), 2, 1, 3, hdr));
    const json file = {
        {"gltf", "sub/scene.gltf"},
        {"materials", {{"*", {{"pattern", {1, 2, 1}}, {"cy", 0.25}}}, {"Cloth", {{"cy", 0.75}}}}},
        {"environment", {{"image", "sub/sky.hdr"}, {"color", 0.5}, {"rotation", 90}}},
        {"lights", {{{"type", "point"}, {"position", {1, 2, 3}}, {"color", {1, 0.5, 0}}, {"intensity", 10}},
                    {{"type", "spot"}, {"position", {0, 5, 0}}, {"direction", {0, -2, 0}}, {"inner_cone_degrees", 10},
                     {"outer_cone_degrees", 30}},
                    {{"type", "directional"}, {"direction", {0, 0, -1}}, {"intensity", 3}}}},
        {"camera", {{"position", {0, 0, 5}}, {"target", {5, 0, 5}}, {"yfov_degrees", 30}}},
        {"render", {{"width", 320}, {"height", 240}, {"spp", 64}, {"integrator", "bdpt"}, {"sampler", "independent"}}}};
    const SceneDescription scene = loadScene(write(file));
    EXPECT_EQ(scene.source, dir.file("scene.json"));
    ASSERT_EQ(scene.materials.size(), 2u);
    const WovenParams& cloth = scene.materials[0].woven.value();
    EXPECT_EQ(cloth.ex, 300.0f);   // from the glTF, kept
    EXPECT_EQ(cloth.pattern, glm::ivec3(1, 2, 1));  // from "*"
    EXPECT_EQ(cloth.cy, 0.75f);    // the named entry refines "*"
    const WovenParams& floor = scene.materials[1].woven.value();
    EXPECT_EQ(floor.ex, WovenParams{}.ex);
    EXPECT_EQ(floor.cy, 0.25f);

    ASSERT_TRUE(scene.environment.image);
    EXPECT_EQ(scene.environment.image->width, 2);
    EXPECT_NEAR(scene.environment.image->at(1, 0).z, 6.0f, 0.05f);
    EXPECT_EQ(scene.environment.color, glm::vec3(0.5f));
    EXPECT_NEAR(scene.environment.rotation, 1.5707963f, 1e-6f);

    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_EQ(scene.lights[0].intensity, glm::vec3(10, 5, 0));
    EXPECT_EQ(scene.lights[1].type, PunctualLight::Type::Spot);
    EXPECT_EQ(scene.lights[1].direction, glm::vec3(0, -1, 0));  // normalised
    EXPECT_NEAR(scene.lights[1].outerConeAngle, 0.5235988f, 1e-6f);
    EXPECT_EQ(scene.lights[2].type, PunctualLight::Type::Directional);
    EXPECT_EQ(scene.lights[2].intensity, glm::vec3(3));

    ASSERT_TRUE(scene.hasCamera);
    const glm::mat4& c = scene.camera.cameraToWorld;
    // Looking from (0,0,5) towards +x: -z maps to +x, +y stays up, the origin maps to the eye.
    EXPECT_NEAR(glm::length(glm::vec3(c * glm::vec4(0, 0, -1, 0)) - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(c * glm::vec4(0, 1, 0, 0)) - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_EQ(glm::vec3(c[3]), glm::vec3(0, 0, 5));
    EXPECT_NEAR(scene.camera.yfov, 0.5235988f, 1e-6f);

    EXPECT_EQ(scene.render.width, 320);
    EXPECT_EQ(scene.render.height, 240);
    EXPECT_EQ(scene.render.spp, 64);
    EXPECT_EQ(scene.render.integrator, "bdpt");
    EXPECT_EQ(scene.render.sampler, "independent");
}

TEST_F(SceneFile, OnlyTheGltfIsRequired) {
    const SceneDescription scene = loadScene(write({{"gltf", "sub/scene.gltf"}}));
    EXPECT_EQ(scene.meshes.size(), 2u);
    EXPECT_FALSE(scene.materials[1].woven.has_value());
    EXPECT_EQ(scene.render.width, 0);  // not given
    EXPECT_TRUE(scene.render.integrator.empty());
    EXPECT_EQ(scene.environment.color, glm::vec3(0.0f));
}

TEST_F(SceneFile, EnvironmentIntensityScalesItsColourKeepingTheTint) {
    const SceneDescription tinted =
        loadScene(write({{"gltf", "sub/scene.gltf"}, {"environment", {{"color", {0.2, 0.4, 0.8}}, {"intensity", 2.5}}}}));
    EXPECT_EQ(tinted.environment.color, glm::vec3(0.2f, 0.4f, 0.8f) * 2.5f);
    // With an image and no colour: the image as it is, scaled.
    const float hdr[3] = {1.0f, 2.0f, 3.0f};
    ASSERT_TRUE(stbi_write_hdr(dir.file("sub/sky.hdr").c_str(), 1, 1, 3, hdr));
    const SceneDescription image =
        loadScene(write({{"gltf", "sub/scene.gltf"}, {"environment", {{"image", "sub/sky.hdr"}, {"intensity", 0.5}}}}));
    EXPECT_EQ(image.environment.color, glm::vec3(0.5f));
}

TEST_F(SceneFile, ErrorsNameTheFileAndTheKey) {
    const json ok = {{"gltf", "sub/scene.gltf"}};
    const auto with = [&](const std::string& key, const json& value) {
        json j = ok;
        j[key] = value;
        return j;
    };
    EXPECT_THAT(error(with("lighting", 1)), HasSubstr("lighting: unknown key"));
    EXPECT_THAT(error(with("environment", {{"colour", 1}})), HasSubstr("environment.colour: unknown key"));
    EXPECT_THAT(error(with("environment", {{"color", {1, -1, 0}}})), HasSubstr("environment.color: must not be negative"));
    EXPECT_THAT(error(with("environment", {{"image", "nothere.hdr"}})), HasSubstr("environment.image: "));
    EXPECT_THAT(error(with("environment", {{"intensity", -1}})), HasSubstr("environment.intensity: is -1, must be from 0"));
    EXPECT_THAT(error(with("environment", {{"color", 1e6}, {"intensity", 1e6}})),
                HasSubstr("environment.intensity: times environment.color is 1e+12, more than woven's limit"));
    EXPECT_THAT(error(with("materials", {{"Cloth", {{"cy", 2}}}})), HasSubstr("materials.Cloth: "));
    EXPECT_THAT(error(with("materials", {{"Cloth", {{"cy", 2}}}})), HasSubstr("cy"));
    EXPECT_THAT(error(with("materials", {{"Cloth", {{"colour", 2}}}})), HasSubstr("unknown woven material field 'colour'"));
    EXPECT_THAT(error(with("materials", {{"Silk", json::object()}})),
                HasSubstr("materials.Silk: 'Silk' names nothing: the scene has materials 'Cloth', 'Floor'"));
    EXPECT_THAT(error(with("render", {{"width", -5}})), HasSubstr("render.width: must be an integer from 1"));
    EXPECT_THAT(error(with("render", {{"spp", 2.5}})), HasSubstr("render.spp: must be an integer"));
    // An unknown render.integrator's name is refused where a render takes it
    // (RenderJob.SceneFileIntegratorOutsideTheTableNamesTheFileAndKey); its type here.
    EXPECT_THAT(error(with("render", {{"integrator", 3}})), HasSubstr("render.integrator: "));
    EXPECT_THAT(error(with("render", {{"sampler", 3}})), HasSubstr("render.sampler: "));
    EXPECT_THAT(error(with("lights", {{{"type", "point"}}})), HasSubstr("lights[0]: a point light needs \"position\""));
    EXPECT_THAT(error(with("lights", {{{"type", "area"}}})), HasSubstr("lights[0].type: must be"));
    EXPECT_THAT(error(with("lights", {{{"type", "spot"}, {"position", {0, 0, 0}}, {"direction", {0, 0, 0}}}})),
                HasSubstr("lights[0].direction: must not be zero"));
    EXPECT_THAT(error(with("camera", {{"position", {0, 0, 0}}, {"target", {0, -1, 0}}})),
                HasSubstr("camera.up: must not be parallel"));
    EXPECT_THAT(error(with("camera", {{"position", {0, 0, 0}}})), HasSubstr("camera: needs"));
    EXPECT_THAT(error(json::object()), HasSubstr("gltf: is missing"));
    EXPECT_THAT(error({{"gltf", "sub/none.glb"}}), HasSubstr("gltf: " + dir.file("sub/none.glb") + ": no such file"));
    EXPECT_THAT(error({{"gltf", 3}}), HasSubstr("gltf: must be a string"));
}

TEST_F(SceneFile, MalformedJson) {
    const std::string path = dir.file("broken.json");
    std::ofstream(path) << "{\"gltf\": ";
    try {
        loadScene(path);
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_THAT(e.what(), HasSubstr(path + ": not valid JSON"));
    }
}

}  // namespace
}  // namespace woven
