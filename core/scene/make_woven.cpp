#include "make_woven.h"

#include <nlohmann/json.hpp>

#include <iostream>

#include "material_json.h"
#include "scene_loader.h"
#include "uv_scale.h"

namespace woven {

std::vector<int> selectMaterials(const SceneDescription& scene, const std::string& materialName) {
    std::vector<int> selected;
    for (size_t m = 0; m < scene.materials.size(); ++m)
        if (materialName == "*" || scene.materials[m].name == materialName) selected.push_back(int(m));
    if (!selected.empty()) return selected;
    std::string names;
    for (const Material& material : scene.materials) names += (names.empty() ? "'" : ", '") + material.name + "'";
    throw SceneError(scene.source + ": no material named '" + materialName + "' (the scene has " +
                     (names.empty() ? std::string("no materials") : names) + ")");
}

WovenParams onMaterial(const SceneDescription& scene, int m, const MaterialJson& read) {
    if (!read.threadsPerCm) return read.params;
    WovenParams params = read.params;
    params.repeat = repeatForThreadsPerCm(scene, m, *read.threadsPerCm);
    try {
        validate(params);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("'scale': \"draft\" on material '") + scene.materials[size_t(m)].name +
                                    "' gives " + e.what());
    }
    return params;
}

void makeWoven(SceneDescription& scene, const std::string& materialName, const WovenParams& params) {
    try {
        validate(params);
    } catch (const std::invalid_argument& e) {
        throw SceneError(scene.source + ": woven material for '" + materialName + "': " + e.what());
    }
    for (int m : selectMaterials(scene, materialName)) scene.materials[m].woven = params;
}

void applyWovenOption(SceneDescription& scene, const std::string& option) {
    const size_t eq = option.find('=');
    if (eq == std::string::npos || eq == 0)
        throw SceneError(scene.source + ": --woven '" + option + "': expected NAME=JSON, e.g. cloth='{\"ex\":100}'");
    const std::string name = option.substr(0, eq);
    const std::string where = scene.source + ": --woven " + name;
    const Material& first = scene.materials[size_t(selectMaterials(scene, name).front())];
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(option.substr(eq + 1));
    } catch (const std::exception& e) {
        throw SceneError(where + ": not valid JSON: " + e.what());
    }
    // Every selected material gets the first one's result, but for a draft's scale, which is
    // measured on each material's own meshes.
    std::vector<std::string> warnings;
    try {
        const MaterialJson read = materialFromJson(j, first.woven.value_or(WovenParams{}), "", warnings);
        for (int m : selectMaterials(scene, name)) {
            scene.materials[size_t(m)].woven = onMaterial(scene, m, read);
            if (!read.wif.empty()) scene.materials[size_t(m)].draft = read.wif;
        }
    } catch (const std::exception& e) {  // a bad key (invalid_argument), draft (DraftError) or mesh (SceneError)
        throw SceneError(where + ": " + e.what());
    }
    for (const std::string& w : warnings) {
        scene.warnings.push_back(where + ": " + w);
        std::cerr << "warning: " << where << ": " << w << "\n";
    }
}

}  // namespace woven
