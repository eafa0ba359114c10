#include "woven_surface_material.h"

#include "normal_map.h"
#include "uv_precision.h"
#include "woven_uv_check.h"

namespace woven {

WovenSurfaceMaterial::WovenSurfaceMaterial(const Material& material, const std::vector<TextureImage>& textures,
                                           std::vector<bool> flatMeshes)
    : SurfaceMaterial(material, textures),
      model_(*material.woven),
      resolvedUvLimit_(resolvedUvLimit<float>(material.woven->repeat)),
      flatMeshes_(std::move(flatMeshes)),
      kept_(material.keptSurface.has_value()),
      print_(kept_ && material.keptSurface->print),
      baseColor_(material, textures),
      normalTexture_(kept_ ? material.normalTexture : TextureRef{}, textures) {}

ShadingInput WovenSurfaceMaterial::shadingInput(const SurfaceHit& hit, const glm::vec3& wo) const {
    ShadingInput in;
    const bool hasUv = hit.tex.hasUv && !(hit.mesh >= 0 && size_t(hit.mesh) < flatMeshes_.size() && flatMeshes_[size_t(hit.mesh)]);
    in.uv = hasUv ? glm::dvec2(hit.tex.uv[0]) : glm::dvec2(0.5) / glm::dvec2(model_.params().repeat);
    if (!resolvesThreads(in.uv, resolvedUvLimit_)) in.uvSpacing = uvSpacing<float>(in.uv);
    in.ns = normalTexture_ ? normalMapped(normalTexture_, hit) : hit.ns;
    in.dpdu = hit.dpdu;
    in.dpdv = hit.dpdv;
    in.backSide = glm::dot(wo, hit.ng) < 0.0f;
    if (hasUv && (hit.duvdx != glm::vec2(0.0f) || hit.duvdy != glm::vec2(0.0f))) {
        in.duvdx = glm::dvec2(hit.duvdx);
        in.duvdy = glm::dvec2(hit.duvdy);
    }
    if (print_) in.print = glm::vec3(baseColor_.varying(hit.tex));
    return in;
}

std::optional<Bsdf> WovenSurfaceMaterial::bsdf(const SurfaceHit& hit, const glm::vec3& wo) const {
    const ShadingInput in = shadingInput(hit, wo);
    // The filtered weave reflects only (MODEL_TRANSMISSION.md section 6): a material whose yarns
    // transmit is filtered only where its uv cannot resolve a thread, where nothing else can shade it.
    const bool footprint = !model_.transmits() && (in.duvdx != glm::dvec2(0.0) || in.duvdy != glm::dvec2(0.0));
    if (footprint || in.uvSpacing != glm::dvec2(0.0))
        if (const auto filtered = model_.shadeFiltered(in)) return toBsdf(*filtered);
    const auto shading = model_.shade(in);
    if (!shading) return std::nullopt;
    if (shading->transmission) return toBsdf(transmittingYarn(shading->bsdf, *shading->transmission));
    return toBsdf(shading->bsdf);
}

bool WovenSurfaceMaterial::mayPassThrough(const Mesh& mesh) const {
    // Gaps are found by uv: a mesh without UVs is solid cloth.
    return (model_.hasSeeThroughGaps() && !mesh.uvs.empty() && !uvsAllEqual(mesh)) || (kept_ && baseColor_.mayPassThrough(mesh));
}

bool WovenSurfaceMaterial::passesThrough(const TexCoords& tc, float u) const {
    // Where the uv cannot resolve a thread the far field shades the opaque part (WeaveFarField).
    const glm::dvec2 uv(tc.uv[0]);
    return (tc.hasUv && resolvesThreads(uv, resolvedUvLimit_) && model_.isSeeThrough(uv)) || (kept_ && baseColor_.passesThrough(tc, u));
}

}  // namespace woven
