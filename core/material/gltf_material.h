#pragma once
// The glTF 2.0 metallic-roughness material with the extensions woven renders (docs/MATERIALS.md):
// every texture looked up at the hit, the normal map applied, and the result handed to GltfBxdf.
// Alpha cuts out as BaseColor says. KHR_materials_unlit shows the base colour and reflects
// nothing. The occlusion texture is ignored: a path tracer computes the occlusion it stands for.
#include "base_color.h"
#include "surface_material.h"

namespace woven {

class GltfMaterial final : public SurfaceMaterial {
public:
    GltfMaterial(const Material& material, const std::vector<TextureImage>& textures);

    std::optional<Bsdf> bsdf(const SurfaceHit& hit, const glm::vec3& wo) const override;
    bool mayPassThrough(const Mesh& mesh) const override;
    bool passesThrough(const TexCoords& tc, float u) const override;
    bool passesRandomly() const override { return baseColor_.blends(); }
    glm::vec3 unlitRadiance(const TexCoords& tc) const override;

    // The BSDF's inputs at a point, textures applied (the preview's tests compare with them).
    GltfBxdfInputs inputs(const TexCoords& tc) const;
    // The shading normal at a hit after the normal map, on the side of hit.ns.
    glm::vec3 shadingNormal(const SurfaceHit& hit) const;
    // KHR_materials_anisotropy's direction at a hit, in world space along the tangent plane
    // (rotation and texture applied); meaningful where inputs() gives a strength above 0.
    glm::vec3 anisotropyDirection(const SurfaceHit& hit) const;

private:
    Material m_;
    BaseColor baseColor_;
    TextureSampler metallicRoughnessTexture_, normalTexture_;
    TextureSampler specularTexture_, specularColorTexture_;
    TextureSampler sheenColorTexture_, sheenRoughnessTexture_;
    TextureSampler anisotropyTexture_;
    TextureSampler clearcoatTexture_, clearcoatRoughnessTexture_, clearcoatNormalTexture_;
    TextureSampler transmissionTexture_, thicknessTexture_;
    TextureSampler diffuseTransmissionTexture_, diffuseTransmissionColorTexture_;
    TextureSampler iridescenceTexture_, iridescenceThicknessTexture_;
    float dielectricF0_;  // from the IOR
    // The lobes where no texture or coat makes them vary over the surface, built once: a surface
    // whose vertices carry no colour then copies them rather than building them at every hit,
    // which in a room of plain walls is a twentieth of a path's time. (A normal map turns their
    // frame alone, which is built per hit.)
    struct UniformLobes {
        GltfBxdf bxdf;
        float anisotropy;  // the strength its inputs had, which picks its frame
    };
    std::optional<UniformLobes> uniform_;

    // The lobe's frame about the shading normal n: its x axis is the anisotropy direction where
    // `anisotropy` (the inputs' strength) is above 0, any axis otherwise.
    Frame lobeFrame(const SurfaceHit& hit, const glm::vec3& n, float anisotropy) const;
};

}  // namespace woven
