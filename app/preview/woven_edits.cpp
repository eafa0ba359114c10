#include "woven_edits.h"

#include <algorithm>

#include "scene_loader.h"
#include "uv_scale.h"
#include "woven_assignment.h"
#include "woven_params_json.h"

namespace woven {

namespace {
constexpr float kNewThreadsPerCm = 5.0f;  // 2 mm elements
}  // namespace

WovenEdits::WovenEdits(SceneDescription loaded) : scene_(std::move(loaded)), loadedMaterials_(scene_.materials) {
    for (const Mesh& m : scene_.meshes) loadedMeshMaterials_.push_back(m.material);
}

std::vector<std::string> WovenEdits::targetsFor(int mesh) const {
    const Mesh& m = scene_.meshes.at(size_t(mesh));
    std::vector<std::string> targets = {"*"};
    const int loaded = loadedMeshMaterials_.at(size_t(mesh));
    if (loaded >= 0) targets.push_back(literalTarget(TargetKind::Material, loadedMaterials_[size_t(loaded)].name));
    if (!m.meshName.empty()) targets.push_back(literalTarget(TargetKind::Mesh, m.meshName));
    for (const std::string& node : m.nodePath) targets.push_back(literalTarget(TargetKind::Node, node));
    return targets;
}

bool WovenEdits::names(const std::string& target, size_t mesh) const {
    const int loaded = loadedMeshMaterials_[mesh];
    return targetNames(target, scene_.meshes[mesh], loaded >= 0 ? &loadedMaterials_[size_t(loaded)] : nullptr);
}

std::vector<size_t> WovenEdits::meshesOf(const std::string& target) const {
    std::vector<size_t> meshes;
    for (size_t m = 0; m < scene_.meshes.size(); ++m)
        if (names(target, m)) meshes.push_back(m);
    return meshes;
}

int WovenEdits::materialOf(const std::string& target) const {
    for (size_t m = 0; m < scene_.meshes.size(); ++m)
        if (names(target, m)) return scene_.meshes[m].material;
    return -1;
}

int WovenEdits::makeWoven(const std::string& target) {
    for (size_t i = 0; i < edits_.size(); ++i)
        if (edits_[i].target == target) return int(i);
    bool named = false;
    for (size_t m = 0; m < scene_.meshes.size(); ++m) named |= names(target, m);
    if (!named) throw SceneError(scene_.source + ": make woven: '" + target + "' names nothing: " + whatTargetsCanName(scene_));
    const int material = materialOf(target);
    WovenParams start;
    if (material >= 0 && scene_.materials[size_t(material)].woven) {
        start = *scene_.materials[size_t(material)].woven;
    } else {
        // New cloth starts at a real thread size: 2 mm elements (glTF's unit is the metre).
        try {
            const glm::vec2 repeat = repeatForThreadsPerCm(scene_, meshesOf(target), glm::vec2(kNewThreadsPerCm));
            start.repeat = glm::clamp(repeat, glm::vec2(1.0f), glm::vec2(1e5f));
        } catch (const std::invalid_argument&) {
            // No UVs to measure: the default repeat.
        }
        // A glTF material keeps its colour, as assignWoven() gives it: the orange sofa, woven.
        if (material >= 0) start.warp_color = start.weft_color = glm::vec3(scene_.materials[size_t(material)].baseColor);
    }
    edits_.push_back({target, start});
    apply();
    return int(edits_.size()) - 1;
}

bool WovenEdits::revert(const std::string& target) {
    for (auto it = edits_.begin(); it != edits_.end(); ++it)
        if (it->target == target) {
            edits_.erase(it);
            apply();
            return true;
        }
    return false;
}

bool WovenEdits::apply() {
    std::vector<int> before;
    for (const Mesh& m : scene_.meshes) before.push_back(m.material);
    scene_.materials = loadedMaterials_;
    for (size_t i = 0; i < scene_.meshes.size(); ++i) scene_.meshes[i].material = loadedMeshMaterials_[i];
    std::vector<WovenAssignment> assignments;
    for (const WovenEdit& e : edits_) assignments.push_back({e.target, paramsToJson(e.params), "make woven " + e.target, ""});
    assignWoven(scene_, assignments);
    for (size_t i = 0; i < scene_.meshes.size(); ++i)
        if (scene_.meshes[i].material != before[i]) return true;
    return false;
}

}  // namespace woven
