#include "material_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "atomic_file.h"
#include "file_reading.h"
#include "untrusted_json.h"
#include "draft_material.h"
#include "woven_params_json.h"

namespace woven {

namespace {

constexpr size_t kMaxMaterialFileBytes = size_t(64) << 20;

nlohmann::json readJson(const std::string& path) {
    try {
        const std::vector<unsigned char> bytes = readRegularFile(path, kMaxMaterialFileBytes);
        return parseUntrustedJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    } catch (const FileReadError& e) {
        throw std::runtime_error(e.what());
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

// `gltf` as the scene file at `path` names it: relative to that file's folder where it can be.
std::string gltfFromSceneFile(const std::string& gltf, const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path folder = fs::absolute(path, ec).parent_path();
    const fs::path relative = fs::absolute(gltf, ec).lexically_relative(folder);
    return !ec && !relative.empty() ? relative.generic_string() : fs::absolute(gltf, ec).generic_string();
}

using NamedMaterials = std::vector<std::pair<std::string, nlohmann::json>>;

// Reads the file once, sets every material (and the camera, where given), writes it once.
void saveMaterialsJson(const std::string& path, const NamedMaterials& materials, const std::string& gltf,
                       const nlohmann::json& camera = nullptr) {
    nlohmann::json file;
    if (std::filesystem::exists(path)) {
        file = readJson(path);
        if (!file.is_object() || !file.contains("gltf"))
            throw std::runtime_error(path + ": not a woven scene file (no \"gltf\" key); not overwriting it");
    } else if (!gltf.empty()) {
        file = {{"gltf", gltfFromSceneFile(gltf, path)}};
    } else if (materials.size() == 1) {
        file = materials.front().second;  // the procedural cloth's one material, as a bare object
    } else {
        throw std::runtime_error(path + ": several materials need a scene file, and the procedural cloth has no glTF");
    }
    if (file.contains("gltf")) {
        for (const auto& [name, material] : materials) file["materials"][name] = material;
        if (!camera.is_null()) file["camera"] = camera;
    }
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp);
        out << file.dump(2) << "\n";
        if (!out) throw std::runtime_error(path + ": write failed");
    });
}

}  // namespace

void saveMaterial(const std::string& path, const std::string& materialName, const WovenParams& params,
                  const std::string& gltf) {
    saveMaterialsJson(path, {{materialName, paramsToJson(params)}}, gltf);
}

void saveScene(const std::string& path, const std::vector<std::pair<std::string, WovenParams>>& materials,
               const std::string& gltf, const Camera& camera) {
    const glm::vec3 position(camera.cameraToWorld[3]), forward(-camera.cameraToWorld[2]), up(camera.cameraToWorld[1]);
    const glm::vec3 target = position + forward;
    const nlohmann::json view = {{"position", {position.x, position.y, position.z}},
                                 {"target", {target.x, target.y, target.z}},
                                 {"up", {up.x, up.y, up.z}},
                                 {"yfov_degrees", glm::degrees(double(camera.yfov))}};
    NamedMaterials named;
    for (const auto& [name, params] : materials) named.emplace_back(name, paramsToJson(params));
    saveMaterialsJson(path, named, gltf, view);
}

std::string sceneGltf(const std::string& scenePath) {
    if (scenePath.size() < 5 || scenePath.compare(scenePath.size() - 5, 5, ".json") != 0) return scenePath;
    const nlohmann::json scene = readJson(scenePath);
    if (!scene.is_object() || !scene.contains("gltf") || !scene["gltf"].is_string())
        throw std::runtime_error(scenePath + ": not a woven scene file (no \"gltf\" key)");
    const std::filesystem::path gltf(scene["gltf"].get<std::string>());
    return gltf.is_absolute() ? gltf.string() : (std::filesystem::path(scenePath).parent_path() / gltf).string();
}

std::string saveMaterialWithDraft(const std::string& path, const std::string& materialName, const WovenParams& params,
                                  const std::string& gltf, DraftEditor& draft) {
    const std::filesystem::path wif = std::filesystem::path(path).replace_extension(".wif");
    nlohmann::json material = paramsToJson(params);
    // What the draft sets, and the keys that would replace it (materialFromJson(): `pattern` a
    // draft's tile, a side's colour its per-thread colours).
    static const std::map<std::string, std::string> replacing = {
        {"tile", "pattern"}, {"weft_colors", "weft_color"}, {"warp_colors", "warp_color"}};
    for (const std::string& field : fieldsSetByDraft(draft.draft())) {
        material.erase(field);
        if (const auto key = replacing.find(field); key != replacing.end()) material.erase(key->second);
    }
    material["wif"] = wif.filename().string();  // beside the material file
    draft.save(wif.string());
    saveMaterialsJson(path, {{materialName, material}}, gltf);
    return wif.string();
}

MaterialJson loadMaterial(const std::string& path, const std::string& materialName, const WovenParams& base,
                          std::vector<std::string>& warnings) {
    const nlohmann::json file = readJson(path);
    const std::string directory = std::filesystem::path(path).parent_path().string();
    try {
        if (!file.is_object() || !file.contains("materials")) return materialFromJson(file, base, directory, warnings);
        const nlohmann::json& materials = file.at("materials");
        MaterialJson m;
        m.params = base;
        for (const char* key : {"*", materialName.c_str()}) {
            if (!materials.contains(key)) continue;
            MaterialJson next = materialFromJson(materials.at(key), m.params, directory, warnings);
            if (next.wif.empty()) next.wif = m.wif;  // a named entry refines "*"'s draft
            if (!next.threadsPerCm) next.threadsPerCm = m.threadsPerCm;
            m = next;
        }
        return m;
    } catch (const std::exception& e) {  // a bad key, or a draft (whose message names its file)
        throw std::runtime_error(path + ": " + e.what());
    }
}

}  // namespace woven
