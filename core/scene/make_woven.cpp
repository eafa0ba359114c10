#include "make_woven.h"

#include "scene_loader.h"

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

void makeWoven(SceneDescription& scene, const std::string& materialName, const WovenParams& params) {
    try {
        validate(params);
    } catch (const std::invalid_argument& e) {
        throw SceneError(scene.source + ": woven material for '" + materialName + "': " + e.what());
    }
    for (int m : selectMaterials(scene, materialName)) scene.materials[m].woven = params;
}

}  // namespace woven
