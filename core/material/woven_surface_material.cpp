#include "woven_surface_material.h"

#include "normal_map.h"

namespace woven {

WovenSurfaceMaterial::WovenSurfaceMaterial(const Material& material, const std::vector<TextureImage>& textures)
    : SurfaceMaterial(material, textures),
      model_(*material.woven),
      kept_(material.keptSurface.has_value()),
      print_(kept_ && material.keptSurface->print),
      baseColor_(material, textures),
      normalTexture_(kept_ ? material.normalTexture : TextureRef{}, textures) {}

ShadingInput WovenSurfaceMaterial::shadingInput(const SurfaceHit& hit, const glm::vec3& wo) const {
    ShadingInput in;
    in.uv = hit.tex.hasUv ? glm::dvec2(hit.tex.uv[0]) : glm::dvec2(0.5) / glm::dvec2(model_.params().repeat);
    in.ns = normalTexture_ ? normalMapped(normalTexture_, hit) : hit.ns;
    in.dpdu = hit.dpdu;
    in.dpdv = hit.dpdv;
    in.backSide = glm::dot(wo, hit.ng) < 0.0f;
    if (hit.tex.hasUv && (hit.duvdx != glm::vec2(0.0f) || hit.duvdy != glm::vec2(0.0f))) {
        in.duvdx = glm::dvec2(hit.duvdx);
        in.duvdy = glm::dvec2(hit.duvdy);
    }
    if (print_) in.print = glm::vec3(baseColor_.varying(hit.tex));
    return in;
}

std::optional<Bsdf> WovenSurfaceMaterial::bsdf(const SurfaceHit& hit, const glm::vec3& wo) const {
    const ShadingInput in = shadingInput(hit, wo);
    if (in.duvdx != glm::dvec2(0.0) || in.duvdy != glm::dvec2(0.0))
        if (const auto filtered = model_.shadeFiltered(in)) return toBsdf(*filtered);
    const auto shading = model_.shade(in);
    if (!shading) return std::nullopt;
    return toBsdf(shading->bsdf);
}

bool WovenSurfaceMaterial::mayPassThrough(const Mesh& mesh) const {
    // Gaps are found by uv: a mesh without UVs is solid cloth.
    return (model_.hasSeeThroughGaps() && !mesh.uvs.empty()) || (kept_ && baseColor_.mayPassThrough(mesh));
}

bool WovenSurfaceMaterial::passesThrough(const TexCoords& tc, float u) const {
    return (tc.hasUv && model_.isSeeThrough(glm::dvec2(tc.uv[0]))) || (kept_ && baseColor_.passesThrough(tc, u));
}

}  // namespace woven
