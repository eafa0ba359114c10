#include "fabric_scene.h"

#include <algorithm>
#include <filesystem>

#include "fabric_library.h"
#include "file_reading.h"
#include "frame_io.h"
#include "scene_camera.h"
#include "scene_loader.h"
#include "untrusted_json.h"
#include "woven_assignment.h"

namespace woven {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr size_t kMaxJsonBytes = size_t(64) << 20;

json readJson(const std::string& path) {
    const std::vector<unsigned char> bytes = readRegularFile(path, kMaxJsonBytes);
    try {
        return parseUntrustedJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    } catch (const std::invalid_argument& e) {
        throw SceneError(path + ": " + e.what());
    }
}

// The default scene's drape and camera, without its material and light: the fabric in the studio
// light that woven gives a scene without any.
SceneDescription drape() {
    const std::string file = WOVEN_DEFAULT_SCENE;
    const json scene = readJson(file);
    SceneDescription drape = loadScene((fs::path(file).parent_path() / scene.at("gltf").get<std::string>()).string());
    const json& c = scene.at("camera");
    const auto point = [](const json& p) { return glm::vec3(p.at(0).get<float>(), p.at(1).get<float>(), p.at(2).get<float>()); };
    drape.camera = cameraOf({point(c.at("position")), point(c.at("target")), glm::vec3(0.0f, 1.0f, 0.0f), c.at("yfov_degrees").get<float>()});
    drape.hasCamera = true;
    return drape;
}

}  // namespace

SceneDescription loadSceneOrFabric(const std::string& argument, const LoadOptions& options) {
    const std::string extension = lowerExtension(argument);
    std::error_code ec;
    const bool isFile = fs::is_regular_file(argument, ec);
    WovenAssignment fabric{"Cloth", json::object(), "the fabric", isFile ? fs::path(argument).parent_path().string() : ""};
    std::string name = fs::path(argument).stem().string();
    if (extension == ".gltf" || extension == ".glb") return loadScene(argument, options);
    if (extension == ".json") {
        const json j = readJson(argument);
        if (j.is_object() && j.contains("gltf")) return loadScene(argument, options);  // a woven scene file
        if (j.is_object() && j.contains("material") && j.contains("name")) {  // a fabric file
            fabric.params = j["material"];
            if (j["name"].is_string()) name = j["name"].get<std::string>();
        } else {
            fabric.params = j;  // a woven material
        }
    } else if (extension == ".wif") {
        fabric.params = {{"wif", fs::path(argument).filename().string()}, {"scale", "draft"}};
    } else if (extension == ".u3ma" || extension == ".u3m") {
        fabric.params = {{"u3m", fs::path(argument).filename().string()}};
    } else if (extension.empty() && !isFile) {
        const std::vector<std::string> names = fabricNames();
        if (std::find(names.begin(), names.end(), argument) == names.end())
            throw SceneError(argument + ": no such file, nor a fabric of the library (woven fabrics lists them)");
        fabric.params = {{"preset", argument}};
    } else {
        throw SceneError(argument + ": unknown scene file type '" + extension +
                         "' (expected .gltf, .glb or .json, or a fabric: .wif, .u3ma, .u3m or a library fabric's name)");
    }
    SceneDescription scene = drape();
    scene.source = argument;
    assignWoven(scene, {fabric});
    for (Material& m : scene.materials)
        if (m.name == "Cloth") m.name = name;
    return scene;
}

}  // namespace woven
