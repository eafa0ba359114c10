// Which shots are backlit (Shot::backlit): every light behind the swatch as the camera sees it,
// a point lamp or a light box (an emissive surface), so that the fit takes the light through the
// yarns from them and the colours from the others.
#include <gtest/gtest.h>

#include <fstream>

#include "capture_rig.h"
#include "display_transform.h"
#include "flat_cloth.h"
#include "gltf_writer.h"
#include "shot.h"
#include "temp_dir_test.h"

namespace woven::test {
namespace {


class ShotLights : public TempDirTest {
protected:
    void SetUp() override {
        TempDirTest::SetUp();
        Image photo;
        photo.width = photo.height = 32;
        // Stripes: a photo with no signal at all is refused as nothing to fit.
        photo.pixels.assign(32 * 32, glm::vec3(0.2f));
        for (size_t i = 0; i < photo.pixels.size(); i += 2) photo.pixels[i] = glm::vec3(0.4f);
        writePng((dir_ / "photo.png").string(), photo, {0.0f, ToneMap::Clamp});
    }
    // The rig's swatch and camera, no punctual light, and a 10 cm light box `height` metres above
    // the swatch's plane (below it where negative).
    Shot withLightBox(float height) {
        SceneDescription scene;
        scene.meshes.push_back(flatCloth(glm::vec2(kSwatchMetres), "Swatch"));
        Mesh box = flatCloth(glm::vec2(0.1f), "LightBox");
        for (glm::vec3& p : box.positions) p.y = height;
        box.material = 1;
        scene.meshes.push_back(box);
        Material swatch, lamp;
        swatch.name = "Swatch";
        lamp.name = "LightBox";
        lamp.emission = glm::vec3(20.0f);
        scene.materials = {swatch, lamp};
        std::vector<std::string> warnings;
        writeGltf((dir_ / "box.gltf").string(), scene, Camera{}, warnings);
        std::ofstream f(dir_ / "box.json");
        f << "{\"gltf\": \"box.gltf\", \"lights\": [],"
          << " \"camera\": {\"position\": [0, 0.15, 0], \"target\": [0, 0, 0], \"up\": [0, 0, -1], \"yfov_degrees\": 13},"
          << " \"render\": {\"width\": 32, \"height\": 32}, \"photo\": {\"image\": \"photo.png\"}}\n";
        f.close();
        return loadShot((dir_ / "box.json").string(), "Swatch");
    }
};

TEST_F(ShotLights, PointLampBehindTheSwatchIsBacklitTheFlashIsNot) {
    RigPhoto photo;
    photo.size = 32;
    photo.spp = 1;
    EXPECT_FALSE(loadShot(writeCaptureShot(dir_.string(), "flash", photo), "Swatch").backlit);
    photo.light = {0.02f, -0.15f, 0.0f};
    EXPECT_TRUE(loadShot(writeCaptureShot(dir_.string(), "behind", photo), "Swatch").backlit);
}

TEST_F(ShotLights, LightBoxBehindTheSwatchIsBacklitInFrontIsNot) {
    EXPECT_TRUE(withLightBox(-0.05f).backlit);
    EXPECT_FALSE(withLightBox(0.05f).backlit);
}

}  // namespace
}  // namespace woven::test
