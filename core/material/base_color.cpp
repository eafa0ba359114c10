#include "base_color.h"

namespace woven {

BaseColor::BaseColor(const Material& material, const std::vector<TextureImage>& textures)
    : factor_(material.baseColor),
      texture_(material.baseColorTexture, textures),
      alphaMode_(material.alphaMode),
      alphaCutoff_(material.alphaCutoff) {}

bool BaseColor::mayPassThrough(const Mesh& mesh) const {
    if (alphaMode_ == AlphaMode::Opaque) return false;
    return factor_.a < 1.0f || bool(texture_) || !mesh.colors.empty() ||
           (alphaMode_ == AlphaMode::Mask && alphaCutoff_ > 1.0f);
}

bool BaseColor::passesThrough(const TexCoords& tc, float u) const {
    switch (alphaMode_) {
        case AlphaMode::Opaque: return false;
        case AlphaMode::Mask: return eval(tc).a < alphaCutoff_;
        case AlphaMode::Blend: return u >= eval(tc).a;
    }
    return false;
}

}  // namespace woven
