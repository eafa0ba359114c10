#include "woven_surface_material.h"

namespace woven {

WovenSurfaceMaterial::WovenSurfaceMaterial(const Material& material, const std::vector<TextureImage>& textures)
    : SurfaceMaterial(material, textures), model_(*material.woven) {}

std::optional<Bsdf> WovenSurfaceMaterial::bsdf(const SurfaceHit& hit, const glm::vec3& wo) const {
    ShadingInput in;
    in.uv = hit.tex.hasUv ? glm::dvec2(hit.tex.uv[0]) : glm::dvec2(0.5) / glm::dvec2(model_.params().repeat);
    in.ns = hit.ns;
    in.dpdu = hit.dpdu;
    in.dpdv = hit.dpdv;
    in.backSide = glm::dot(wo, hit.ng) < 0.0f;
    if (hit.tex.hasUv && (hit.duvdx != glm::vec2(0.0f) || hit.duvdy != glm::vec2(0.0f))) {
        in.duvdx = glm::dvec2(hit.duvdx);
        in.duvdy = glm::dvec2(hit.duvdy);
        if (const auto filtered = model_.shadeFiltered(in)) return toBsdf(*filtered);
    }
    const auto shading = model_.shade(in);
    if (!shading) return std::nullopt;
    return toBsdf(shading->bsdf);
}

bool WovenSurfaceMaterial::mayPassThrough(const Mesh& mesh) const {
    // Gaps are found by uv: a mesh without UVs is solid cloth.
    return model_.hasSeeThroughGaps() && !mesh.uvs.empty();
}

bool WovenSurfaceMaterial::passesThrough(const TexCoords& tc, float) const {
    return model_.isSeeThrough(glm::dvec2(tc.uv[0]));
}

}  // namespace woven
