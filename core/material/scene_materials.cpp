#include "scene_materials.h"

#include <stdexcept>

#include "gltf_material.h"
#include "scene_loader.h"
#include "woven_surface_material.h"

namespace woven {

namespace {
std::unique_ptr<SurfaceMaterial> makeMaterial(const Material& m, const std::vector<TextureImage>& textures) {
    if (m.woven) return std::make_unique<WovenSurfaceMaterial>(m, textures);
    return std::make_unique<GltfMaterial>(m, textures);
}
}  // namespace

SceneMaterials::SceneMaterials(const SceneDescription& scene) {
    for (const Material& m : scene.materials) {
        try {
            materials_.push_back(makeMaterial(m, scene.textures));
        } catch (const std::exception& e) {  // invalid woven parameters, a texture index out of range
            throw SceneError(scene.source + ": material '" + m.name + "': " + e.what());
        }
    }
    materials_.push_back(makeMaterial(Material{}, scene.textures));
}

}  // namespace woven
