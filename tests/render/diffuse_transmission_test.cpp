// KHR_materials_diffuse_transmission end to end: `woven render` of a glTF sheet lit only from
// behind by a directional light, against the radiance the extension's definition gives.
//
// With specularFactor 0 (KHR_materials_specular: F0 = F90 = 0) the material is the extension's
// diffuse mix alone, f = (1 - D) base / pi above and D colour / pi below, so under irradiance E
// from behind the camera side shows L = D colour E / pi and the lit side L = (1 - D) base E / pi,
// uniformly (a directional light, a flat sheet, nothing else in the scene to bounce light back).
// The path tracer samples the delta light directly, the same value at every point, so its frame
// equals that to float rounding (1e-5 relative); BDPT adds the light's paths through the sheet to
// the camera, unbiased but random: its mean over the 1024 pixels x 16 samples came out 2e-4
// off, held to 1 %. A lost (1 - D), a transmission of the base colour instead of its own, a
// missing 1 / pi or a strategy MIS counts twice is off by far more.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../common/run_woven.h"
#include "../scene/gltf_builder.h"
#include "frame_io.h"

namespace woven {
namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kIrradiance = 2.0f;  // W/m^2: the light's 1366 lux / 683 lm/W
const glm::vec3 kBase(0.6f, 0.5f, 0.4f), kColor(0.9f, 0.6f, 0.3f);
constexpr float kFactor = 0.7f;

// The 2 x 2 sheet on z = 0 facing +z, the light travelling +z from behind it, camera 0 on the
// +z side (the side the light passes to) and camera 1 on the lit side, each seeing only the sheet.
void writeSheet(const std::string& path) {
    test::GltfBuilder b;
    const int material = b.addMaterial(
        {{"name", "leaf"},
         {"doubleSided", true},
         {"pbrMetallicRoughness", {{"baseColorFactor", {kBase.r, kBase.g, kBase.b, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 1.0}}},
         {"extensions",
          {{"KHR_materials_specular", {{"specularFactor", 0.0}}},
           {"KHR_materials_diffuse_transmission",
            {{"diffuseTransmissionFactor", kFactor}, {"diffuseTransmissionColorFactor", {kColor.r, kColor.g, kColor.b}}}}}}});
    b.useExtension("KHR_materials_specular");
    b.useExtension("KHR_materials_diffuse_transmission");
    b.useExtension("KHR_lights_punctual");
    const int mesh = b.addMesh({{"attributes",
                                 {{"POSITION", b.addPositions({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}})},
                                  {"NORMAL", b.addVec3(std::vector<glm::vec3>(4, glm::vec3(0, 0, 1)))}}},
                                {"indices", b.addIndices({0, 1, 2, 0, 2, 3})},
                                {"material", material}});
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "directional"}, {"intensity", kIrradiance * 683.0}}};
    b.json()["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.4}, {"znear", 0.01}}}}};
    // Half a turn about y: the node's -z (where lights shine and cameras look) becomes +z.
    const nlohmann::json halfTurn = {0.0, 1.0, 0.0, 0.0};
    b.setScene({b.addNode({{"mesh", mesh}}),
                b.addNode({{"rotation", halfTurn}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}),
                b.addNode({{"camera", 0}, {"translation", {0.0, 0.0, 3.0}}}),
                b.addNode({{"camera", 0}, {"translation", {0.0, 0.0, -3.0}}, {"rotation", halfTurn}})});
    b.writeGltf(path, test::GltfBuilder::Storage::DataUri);
}

class DiffuseTransmission : public test::CommandTest {
protected:
    glm::dvec3 meanOf(const std::string& camera, const std::string& integrator, int spp) {
        const std::string out = file(camera + integrator + ".exr");
        const test::RunResult r = test::runWovenCommand("render " + file("sheet.gltf") + " --camera " + camera + " --integrator " +
                                                        integrator + " --spp " + std::to_string(spp) +
                                                        " --noise-threshold 0 --no-denoise --width 32 --height 32 -o " + out);
        EXPECT_EQ(r.exitCode, 0) << r.out;
        glm::dvec3 sum(0.0);
        const Image image = readExr(out).image;
        for (const glm::vec3& p : image.pixels) sum += glm::dvec3(p);
        return sum / double(image.pixels.size());
    }
};

TEST_F(DiffuseTransmission, ASheetLitFromBehindShowsTheExtensionsRadianceOnBothSides) {
    writeSheet(file("sheet.gltf"));
    const glm::dvec3 through = glm::dvec3(kFactor * kColor * kIrradiance / kPi);
    const glm::dvec3 lit = glm::dvec3((1.0f - kFactor) * kBase * kIrradiance / kPi);
    const glm::dvec3 pathThrough = meanOf("0", "path", 4), pathLit = meanOf("1", "path", 4);
    const glm::dvec3 bdptThrough = meanOf("0", "bdpt", 16);
    std::printf("[ diffuse transmission ] green: expected %.6f through, %.6f lit; path %.6f, %.6f; BDPT %.6f\n", through.g, lit.g,
                pathThrough.g, pathLit.g, bdptThrough.g);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(pathThrough[c], through[c], 1e-5 * through[c]) << "camera side, channel " << c;
        EXPECT_NEAR(pathLit[c], lit[c], 1e-5 * lit[c]) << "lit side, channel " << c;
        EXPECT_NEAR(bdptThrough[c], through[c], 0.01 * through[c]) << "BDPT, camera side, channel " << c;
    }
}

}  // namespace
}  // namespace woven
