#pragma once
// glTF's base colour at a point (factor x texture x COLOR_0) and the alpha cut-out it makes:
// MASK below alphaCutoff, BLEND with probability 1 - alpha (stochastic transparency, unbiased
// for any number of layers). GltfMaterial shades with it; a glTF material made woven keeps it
// (WovenSurfaceMaterial: the print and the cut-out).
#include "scene_description.h"
#include "tex_coords.h"
#include "texture_sampler.h"

namespace woven {

class BaseColor {
public:
    BaseColor(const Material& material, const std::vector<TextureImage>& textures);

    // Linear RGB and alpha.
    glm::vec4 eval(const TexCoords& tc) const { return factor_ * texture_.eval(tc) * tc.color; }
    // What varies over the surface, the texture x COLOR_0: a woven material's print.
    glm::vec4 varying(const TexCoords& tc) const { return texture_.eval(tc) * tc.color; }

    // Whether alpha can let a ray through anywhere on `mesh`, and at a point (u as
    // SurfaceMaterial::passesThrough's).
    bool mayPassThrough(const Mesh& mesh) const;
    bool passesThrough(const TexCoords& tc, float u) const;
    bool blends() const { return alphaMode_ == AlphaMode::Blend; }
    // Whether eval() depends on the point through a texture (COLOR_0 aside, which TexCoords brings).
    bool textured() const { return bool(texture_); }

private:
    glm::vec4 factor_;
    TextureSampler texture_;
    AlphaMode alphaMode_;
    float alphaCutoff_;
};

}  // namespace woven
