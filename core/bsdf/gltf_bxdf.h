#pragma once
// The glTF 2.0 metallic-roughness BSDF (the specification's appendix B) with the KHR material
// extensions woven renders, at one shading point, in a local frame with z = the shading normal
// on the viewer's side and x = KHR_materials_anisotropy's direction:
//   base  = mix(dielectric, metal, metallic)
//   dielectric = fresnel_mix(F0, F90; (1 - T) diffuse + T thinBtdf, GGX)
//   diffuse = (1 - D) Lambert(baseColor) + D LambertBtdf(diffuseTransmissionColor)
//   metal = conductor_fresnel(baseColor; GGX)
//   f = clearcoat over (sheen over base), each layer scaling the one below by what it reflects.
// F0 and F90 come from KHR_materials_ior and KHR_materials_specular; KHR_materials_iridescence
// mixes both Fresnel terms towards a thin film's (thin_film.h). KHR_materials_anisotropy
// makes the GGX lobe (of the base, not of the coat) rougher along x: alpha_x =
// mix(roughness^2, 1, strength^2), alpha_y = roughness^2. Transmission is thin-walled
// (KHR_materials_transmission without refraction): the GGX lobe mirrored through the surface,
// tinted by the base colour and by KHR_materials_volume's attenuation. GGX's energy loss to
// multiple scattering at high roughness is not compensated, as in the specification's
// reference; docs/MATERIALS.md gives its size. KHR_materials_diffuse_transmission's D moves that
// share of the diffuse base to the other side: a Lambertian BTDF, whose Fresnel weight is taken
// at the half vector of wo and wi mirrored through the surface (as the thin transmission's is),
// so that it stays reciprocal.
// Sampling picks one lobe by its estimated reflectance towards wo (GGX by its visible normals,
// diffuse and sheen by the cosine), and pdf() is the mixture density of all of them.
#include <optional>

#include "bsdf_sample.h"
#include "clearcoat_lobe.h"
#include "ggx.h"
#include "sheen_lobe.h"

namespace woven {

// Every input of the BSDF after texture lookups.
struct GltfBxdfInputs {
    glm::vec3 baseColor{1.0f};
    float metallic = 1.0f, roughness = 1.0f;
    float anisotropy = 0.0f;  // KHR_materials_anisotropy's strength, along the local x axis
    glm::vec3 specularF0{0.04f};  // dielectric reflectance at normal incidence
    float specularF90 = 1.0f;
    float transmission = 0.0f;
    glm::vec3 transmittance{1.0f};  // volume attenuation of one crossing
    float diffuseTransmission = 0.0f;  // KHR_materials_diffuse_transmission's D
    glm::vec3 diffuseTransmissionColor{1.0f};
    glm::vec3 sheenColor{0.0f};
    float sheenRoughness = 0.0f;
    float clearcoat = 0.0f, clearcoatRoughness = 0.0f;
    glm::vec3 clearcoatNormal{0.0f, 0.0f, 1.0f};  // in the local frame
    float iridescence = 0.0f;  // KHR_materials_iridescence's strength
    float iridescenceIor = 1.3f;
    float iridescenceThickness = 0.0f;  // nm
};

class GltfBxdf {
public:
    explicit GltfBxdf(const GltfBxdfInputs& in);

    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const;
    std::optional<BsdfSample> sample(const glm::vec3& wo, const glm::vec2& u, float uc) const;
    // Whether sample() reads uc: a Lambertian surface has one lobe to sample.
    bool choosesLobe() const { return !lambertian_; }
    // The reflectance the albedo render pass shows (sample_contributions.h's FirstHit): the Fresnel mix at
    // normal incidence of F0 over the base colour (tinted by the thin transmission's
    // attenuation as far as it transmits) and the metal's base colour; the sheen and the coat
    // above it are left out.
    glm::vec3 albedo() const;
    bool transmits() const { return metallic_ < 1.0f && (transmission_ > 0.0f || diffuseTransmits()); }

private:
    // Probabilities of sampling each lobe towards wo; they sum to 1.
    struct LobeChoice {
        float specular = 1.0f, diffuse = 0.0f, transmission = 0.0f, sheen = 0.0f, diffuseTransmission = 0.0f,
              clearcoat = 0.0f;
    };
    // Whether the diffuse base passes light through (the thin transmission does not cover it all).
    bool diffuseTransmits() const { return diffuseTransmission_ > 0.0f && transmission_ < 1.0f; }
    LobeChoice choose(const glm::vec3& wo) const;
    // The dielectric's and the metal's Fresnel reflectance at cosTheta to the microfacet normal.
    struct Fresnel {
        glm::vec3 dielectric, metal;
    };
    Fresnel fresnel(float cosTheta) const;

    glm::vec3 baseColor_;
    float metallic_;
    TrowbridgeReitz ggx_;
    glm::vec3 f0_;
    float f90_;
    float transmission_;
    glm::vec3 transmittance_;
    float diffuseTransmission_;
    glm::vec3 diffuseTransmissionColor_;
    SheenLobe sheen_;
    ClearcoatLobe clearcoat_;
    float iridescence_, iridescenceIor_, iridescenceThickness_;
    float outsideIor_;  // over the film: air, or the clearcoat's 1.5 as far as it covers it
    // Only the Lambertian base reflects (no specular, transmission, sheen or coat): choose()
    // and eval() then skip the Fresnel terms and lobes that would only add zeros, with the same
    // result to the bit, so a matte wall costs what a Lambertian BSDF does.
    bool lambertian_;
};

}  // namespace woven
