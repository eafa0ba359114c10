#include "surface_material.h"

namespace woven {

SurfaceMaterial::SurfaceMaterial(const Material& material, const std::vector<TextureImage>& textures)
    : emission_(glm::max(material.emission, glm::vec3(0.0f))),
      emissiveTexture_(material.emissiveTexture, textures),
      twoSided_(material.doubleSided),
      emits_(material.emits()) {}

}  // namespace woven
