#include "capture_rig.h"

#include <atomic>
#include <filesystem>
#include <fstream>
#include <random>

#include "display_transform.h"
#include "flat_cloth.h"
#include "gltf_writer.h"
#include "photo_model.h"
#include "render_job.h"
#include "scene_loader.h"

namespace woven::test {

namespace fs = std::filesystem;

std::string writeShotFile(const std::string& dir, const std::string& name, int size, const std::string& photoJson,
                          const glm::vec3& light, float lightIntensity, int height) {
    SceneDescription swatch;
    swatch.meshes.push_back(flatCloth(glm::vec2(kSwatchMetres), "Swatch"));
    Material material;
    material.name = "Swatch";
    swatch.materials.push_back(material);
    std::vector<std::string> warnings;
    writeGltf((fs::path(dir) / "swatch.gltf").string(), swatch, Camera{}, warnings);
    // 15 cm above the swatch's centre (the origin), a 13 degree lens that sees 3.4 cm of it, v up
    // the image; the "flash" beside the lens (5 mm, as a phone's is, by default) or a lamp behind the swatch.
    std::ofstream f(fs::path(dir) / (name + ".json"));
    f << "{\"gltf\": \"swatch.gltf\",\n"
      << " \"lights\": [{\"type\": \"point\", \"position\": [" << light.x << ", " << light.y << ", " << light.z
      << "], \"intensity\": " << lightIntensity << "}],\n"
      << " \"camera\": {\"position\": [0, 0.15, 0], \"target\": [0, 0, 0], \"up\": [0, 0, -1], \"yfov_degrees\": 13},\n"
      << " \"render\": {\"width\": " << size << ", \"height\": " << (height > 0 ? height : size) << "}"
      << (photoJson.empty() ? "" : ",\n \"photo\": " + photoJson) << "}\n";
    return (fs::path(dir) / (name + ".json")).string();
}

std::string writeCaptureShot(const std::string& dir, const std::string& name, const RigPhoto& photo) {
    std::string key = "{\"image\": \"" + name + ".png\"";
    if (photo.vignetteSigmaPx > 0.0f) key += ", \"vignette_sigma_px\": " + std::to_string(photo.vignetteSigmaPx);
    key += ", \"exposure\": " + (photo.exposureKnown ? std::to_string(photo.exposure) : std::string("\"free\""));
    key += "}";
    const std::string shot = writeShotFile(dir, name, photo.size, key, photo.light, photo.lightIntensity, photo.height);

    auto scene = std::make_shared<SceneDescription>(loadScene(shot));
    for (Material& m : scene->materials)
        if (m.name == "Swatch") m.woven = photo.truth;
    const float turn = glm::radians(photo.turnDegrees);
    for (Mesh& mesh : scene->meshes) {
        if (turn == 0.0f) continue;
        mesh.tangents.clear();  // the renderer's, from the turned UVs
        for (glm::vec2& uv : mesh.uvs) {
            // About the UVs' centre (the swatch's, where the camera looks).
            const glm::vec2 c(0.5f * kSwatchMetres), d = uv - c;
            uv = c + glm::vec2(std::cos(turn) * d.x - std::sin(turn) * d.y, std::sin(turn) * d.x + std::cos(turn) * d.y);
        }
    }
    RenderSettings settings = defaultRenderSettings(*scene);
    settings.spp = photo.spp;
    settings.seed = photo.seed;
    settings.integrator = "path";
    settings.noiseThreshold = 0.0;
    RenderJob job(scene, settings);
    const std::atomic<bool> cancel{false};
    job.run(cancel);
    Image image = job.snapshot().radiance;
    applyVignette(image, photo.vignetteSigmaPx);
    std::mt19937 rng(uint32_t(photo.seed));
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    for (glm::vec3& v : image.pixels)
        for (int c = 0; c < 3; ++c) v[c] = std::max(0.0f, v[c] * photo.exposure * (1.0f + photo.noise * gauss(rng)));
    writePng((fs::path(dir) / (name + ".png")).string(), image, {0.0f, ToneMap::Clamp});
    return shot;
}

}  // namespace woven::test
