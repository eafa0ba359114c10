#include "material_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "atomic_file.h"
#include "file_reading.h"
#include "output_path.h"
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

bool isSceneFile(const std::string& path) {
    return path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
}

// `file` (a path as given, or relative to the working directory) as the scene file at `path`
// names it: relative to that file's folder where it can be.
std::string pathFromSceneFile(const std::string& file, const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path folder = fs::absolute(path, ec).parent_path();
    const fs::path relative = fs::absolute(file, ec).lexically_relative(folder);
    return !ec && !relative.empty() ? relative.generic_string() : fs::absolute(file, ec).generic_string();
}

// The scene file `from` as a file at `to` says it: each relative path it holds (its glTF, its
// environment image, its materials' drafts and U3M files, its photo) rebased to `to`'s folder.
nlohmann::json rebasedSceneFile(const std::string& from, const std::string& to) {
    nlohmann::json file = readJson(from);
    if (!file.is_object() || !file.contains("gltf"))
        throw std::runtime_error(from + ": not a woven scene file (no \"gltf\" key)");
    const std::filesystem::path folder = std::filesystem::path(from).parent_path();
    const auto rebase = [&](nlohmann::json& value) {
        if (!value.is_string()) return;  // the reader says what is wrong with it
        const std::filesystem::path given(value.get<std::string>());
        value = pathFromSceneFile(given.is_absolute() ? given.string() : (folder / given).string(), to);
    };
    rebase(file["gltf"]);
    for (const char* key : {"environment", "photo"})
        if (file.contains(key) && file[key].is_object() && file[key].contains("image")) rebase(file[key]["image"]);
    if (file.contains("materials") && file["materials"].is_object())
        for (auto& [name, material] : file["materials"].items())
            for (const char* key : {"wif", "u3m"})
                if (material.is_object() && material.contains(key)) rebase(material[key]);
    return file;
}

using NamedMaterials = std::vector<std::pair<std::string, nlohmann::json>>;

// What a new file at `path` starts as: the scene the window opened, else the procedural cloth's
// one material as a bare object.
nlohmann::json startingFile(const std::string& path, const NamedMaterials& materials, const std::string& scenePath) {
    if (isSceneFile(scenePath)) return rebasedSceneFile(scenePath, path);
    if (!scenePath.empty()) return nlohmann::json{{"gltf", pathFromSceneFile(scenePath, path)}};
    if (materials.size() == 1) return materials.front().second;
    throw std::runtime_error(path + ": several materials need a scene file, and the procedural cloth has no glTF");
}

// Reads the file once, sets every material (and the rest `save` holds, where given), writes it once.
void saveMaterialsJson(const std::string& path, const NamedMaterials& materials, const std::string& scenePath,
                       const SceneSave* save = nullptr) {
    nlohmann::json file;
    const bool exists = std::filesystem::exists(path);
    if (exists) {
        file = readJson(path);
        if (!file.is_object() || !file.contains("gltf"))
            throw std::runtime_error(path + ": not a woven scene file (no \"gltf\" key); not overwriting it");
    }
    if (!exists || (save && save->startAnew)) file = startingFile(path, materials, scenePath);
    if (file.contains("gltf")) {
        for (const auto& [name, material] : materials) file["materials"][name] = material;
        if (save) {
            if (const auto& view = save->camera)
                file["camera"] = {{"position", {view->position.x, view->position.y, view->position.z}},
                                  {"target", {view->target.x, view->target.y, view->target.z}},
                                  {"up", {view->up.x, view->up.y, view->up.z}},
                                  {"yfov_degrees", view->yfovDegrees}};
            nlohmann::json& render = file["render"];
            const RenderHints& hints = save->render;
            if (hints.width > 0) render["width"] = hints.width;
            if (hints.height > 0) render["height"] = hints.height;
            if (hints.spp > 0) render["spp"] = hints.spp;
            if (!hints.integrator.empty()) render["integrator"] = hints.integrator;
            if (!hints.sampler.empty()) render["sampler"] = hints.sampler;
            if (hints.noiseThreshold) render["noise_threshold"] = *hints.noiseThreshold;
            if (const auto& c = save->environmentColor) file["environment"]["color"] = {c->x, c->y, c->z};
        }
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

void saveScene(const std::string& path, const std::string& scenePath, const SceneSave& save) {
    for (const std::string& input : save.inputs)
        if (sameFile(path, input))
            throw std::runtime_error(path + ": the scene reads this file (its scene file, glTF, a buffer, an image or a "
                                            "draft): saving over it would change the scene; choose another file");
    if (!isSceneFile(path))
        throw std::runtime_error(path + ": not a woven scene file name (a scene file ends in .json); choose another file");
    NamedMaterials named;
    for (const auto& [name, params] : save.materials) named.emplace_back(name, paramsToJson(params));
    saveMaterialsJson(path, named, scenePath, &save);
}

std::string sceneGltf(const std::string& scenePath) {
    if (!isSceneFile(scenePath)) return scenePath;
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
