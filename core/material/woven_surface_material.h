#pragma once
// The woven model (core/model, MODEL.md) as a scene material: the yarn's BSDF at the hit's uv,
// its see-through gaps as points rays pass through. A mesh without texture coordinates shows
// solid cloth: every point takes the middle of the first weave element, which is on a yarn.
// A glTF material made woven (Material::keptSurface) keeps its normal map, which the weave's
// bump tilts further, its alpha cut-out (a ray passes where the weave has a gap or alpha says
// so) and its base colour texture and vertex colour as a print on the yarns. Where a hit's float uv
// cannot resolve a thread (uv_precision.h) the weave's far field shades it, and a mesh whose UVs
// are all equal is solid cloth as a mesh without them (woven_uv_check.h warns of both).
#include "base_color.h"
#include "surface_material.h"
#include "woven_material.h"

namespace woven {

class WovenSurfaceMaterial final : public SurfaceMaterial {
public:
    // Throws std::invalid_argument for parameters the model rejects. `flatMeshes`: per mesh index,
    // whether its UVs are all equal (checkWovenUvs()); none where it is shorter.
    WovenSurfaceMaterial(const Material& material, const std::vector<TextureImage>& textures,
                         std::vector<bool> flatMeshes = {});

    // The weave filtered over the hit's footprint where it has one (WovenMaterial::shadeFiltered).
    std::optional<Bsdf> bsdf(const SurfaceHit& hit, const glm::vec3& wo) const override;
    bool filtersByFootprint() const override { return true; }
    bool mayPassThrough(const Mesh& mesh) const override;
    bool passesThrough(const TexCoords& tc, float u) const override;
    bool passesRandomly() const override { return kept_ && baseColor_.blends(); }

    const WovenMaterial& model() const { return model_; }

private:
    // What the model is shaded with at a hit: uv, the normal-mapped normal, the print.
    ShadingInput shadingInput(const SurfaceHit& hit, const glm::vec3& wo) const;

    WovenMaterial model_;
    glm::dvec2 resolvedUvLimit_;  // resolvedUvLimit<float>() at the material's repeat
    std::vector<bool> flatMeshes_;
    bool kept_, print_;  // Material::keptSurface, and its print
    BaseColor baseColor_;
    TextureSampler normalTexture_;
};

}  // namespace woven
