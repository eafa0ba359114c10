#pragma once
// A material as the renderer uses it: the BSDF at a hit, whether a ray passes through a point
// (alpha cut-outs, blended alpha, a weave's see-through gaps), and what the surface emits. One
// class per kind: GltfMaterial (glTF 2.0 PBR and its extensions), WovenSurfaceMaterial (the
// woven model). SceneMaterials builds them from a SceneDescription.
#include <optional>

#include "bsdf.h"
#include "interaction.h"
#include "scene_description.h"
#include "texture_sampler.h"

namespace woven {

class SurfaceMaterial {
public:
    // Emission is common to every kind: `material`'s emissive factor and texture.
    SurfaceMaterial(const Material& material, const std::vector<TextureImage>& textures);
    virtual ~SurfaceMaterial() = default;

    // The BSDF seen from wo (unit, pointing away from the surface); nullopt where the surface
    // reflects nothing (a see-through point, an unlit material).
    virtual std::optional<Bsdf> bsdf(const SurfaceHit& hit, const glm::vec3& wo) const = 0;
    // Whether bsdf() reads the hit's pixel footprint (SurfaceHit::duvdx): only then do the
    // integrators compute it.
    virtual bool filtersByFootprint() const { return false; }

    // Whether any point of `mesh` can let a ray through: only then does the ray tracer ask
    // passesThrough() for every candidate hit.
    virtual bool mayPassThrough(const Mesh& mesh) const { return false; }
    // Whether a ray passes through the point; u is a uniform number for stochastic (blended)
    // transparency, the same for every ray that reaches the point along the same path, and 0
    // unless passesRandomly().
    virtual bool passesThrough(const TexCoords& tc, float u) const { return false; }
    virtual bool passesRandomly() const { return false; }

    // Emitted radiance of the front face (and of the back when twoSidedEmission()) at a point;
    // emits() says whether it can be non-zero anywhere, making the surface an area light.
    bool emits() const { return emits_; }
    glm::vec3 emission(const TexCoords& tc) const {
        return emits_ ? emission_ * glm::vec3(emissiveTexture_.eval(tc)) : glm::vec3(0.0f);
    }
    bool twoSidedEmission() const { return twoSided_; }
    // The same emission everywhere: no emissive texture.
    bool uniformEmission() const { return !emissiveTexture_; }
    // Radiance the surface shows without being a light (KHR_materials_unlit): seen by camera and
    // bounce rays, never sampled as a light.
    virtual glm::vec3 unlitRadiance(const TexCoords& tc) const { return glm::vec3(0.0f); }

private:
    glm::vec3 emission_;
    TextureSampler emissiveTexture_;
    bool twoSided_, emits_;
};

}  // namespace woven
