#include "scene_materials.h"

#include <stdexcept>

#include "gltf_material.h"
#include "scene_loader.h"
#include "woven_surface_material.h"
#include "woven_uv_check.h"

namespace woven {

namespace {
std::unique_ptr<SurfaceMaterial> makeMaterial(const SceneDescription& scene, int index) {
    if (index < 0) return std::make_unique<GltfMaterial>(Material{}, scene.textures);
    const Material& m = scene.materials[size_t(index)];
    if (m.woven) return std::make_unique<WovenSurfaceMaterial>(m, scene.textures, checkWovenUvs(scene, index));
    return std::make_unique<GltfMaterial>(m, scene.textures);
}
}  // namespace

SceneMaterials::SceneMaterials(const SceneDescription& scene) {
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material& m = scene.materials[i];
        try {
            materials_.push_back(makeMaterial(scene, int(i)));
        } catch (const std::exception& e) {  // invalid woven parameters, a texture index out of range
            throw SceneError(scene.source + ": material '" + m.name + "': " + e.what());
        }
    }
    materials_.push_back(makeMaterial(scene, -1));
}

}  // namespace woven
