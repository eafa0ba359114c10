#pragma once
// Every material of a scene ready to shade, built once from its SceneDescription: a
// WovenSurfaceMaterial where the material is woven, else a GltfMaterial; index -1 is the default
// material of primitives that have none. This is where the renderer turns a hit into a BSDF.
#include <memory>
#include <vector>

#include "surface_material.h"

namespace woven {

class SceneMaterials {
public:
    // Throws SceneError naming the scene and the material whose parameters are invalid.
    explicit SceneMaterials(const SceneDescription& scene);

    const SurfaceMaterial& operator[](int index) const {
        return *materials_[index >= 0 ? size_t(index) : materials_.size() - 1];
    }
    std::optional<Bsdf> bsdf(const SurfaceHit& hit, const glm::vec3& wo) const {
        return (*this)[hit.material].bsdf(hit, wo);
    }

private:
    std::vector<std::unique_ptr<SurfaceMaterial>> materials_;  // the default last
};

}  // namespace woven
