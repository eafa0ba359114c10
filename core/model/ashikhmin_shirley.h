#pragma once
// The anisotropic Ashikhmin-Shirley BRDF (MODEL.md section 4) in its local frame: z = normal,
// x = the e_x axis. Specular lobe with Schlick Fresnel plus the coupled diffuse term; sampling
// mixes the half-vector sampling of the specular lobe with cosine-weighted diffuse sampling
// (one-sample MIS, so pdf() is the mixture density).
#include <glm/glm.hpp>
#include <optional>

#include "bsdf_sample.h"

namespace woven {

// What a lobe's evaluation needs besides its colour, with the roots it takes: built once per yarn
// (a material precomputes them), so a shading point only adds the colour.
struct LobeShape {
    LobeShape() = default;
    LobeShape(float ex, float ey, float rs);
    float ex = 0.0f, ey = 0.0f, rs = 0.0f;
    float sqrtEx1 = 1.0f, sqrtEy1 = 1.0f;  // sqrt(e_x + 1), sqrt(e_y + 1): the sampling's tan mapping
    float specNorm = 1.0f;                 // sqrt((e_x + 1)(e_y + 1))
};

class AshikhminShirley {
public:
    AshikhminShirley(float ex, float ey, float rs, const glm::vec3& rd) : AshikhminShirley(LobeShape(ex, ey, rs), rd) {}
    AshikhminShirley(const LobeShape& shape, const glm::vec3& rd)
        : AshikhminShirley(shape, rd, specularProbability(shape.rs, rd)) {}
    // With the probability of sampling the specular lobe chosen by the caller (any in (0, 1] with
    // a diffuse term, 1 without: sample() and pdf() agree for each).
    AshikhminShirley(const LobeShape& shape, const glm::vec3& rd, float specularProbability)
        : shape_(shape), rd_(rd), specularProb_(specularProbability) {}
    // The default choice: by the reflectance each lobe carries.
    static float specularProbability(float rs, const glm::vec3& rd);

    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const;
    // u: two uniform numbers in [0, 1) for the direction, uc one more for the lobe choice.
    std::optional<BsdfSample> sample(const glm::vec3& wo, const glm::vec2& u, float uc) const;
    bool choosesLobe() const { return true; }  // sample() reads uc

    bool transmits() const { return false; }
    // The reflectance a denoiser's albedo pass shows (sample_contributions.h's FirstHit): the specular
    // lobe's at normal incidence (Schlick's F(0) = R_s) over the diffuse colour it leaves.
    glm::vec3 albedo() const { return rd_ * (1.0f - shape_.rs) + shape_.rs; }
    const LobeShape& shape() const { return shape_; }
    const glm::vec3& rd() const { return rd_; }  // the diffuse reflectance R_d
    float specularProbability() const { return specularProb_; }
    // Density of half vector h for the specular lobe (the source's eq. 1, p_h).
    float halfVectorPdf(const glm::vec3& h) const;
    // A half vector drawn from halfVectorPdf (MODEL.md section 4's sampling).
    glm::vec3 sampleHalfVector(const glm::vec2& u) const;

private:
    float cosPowN(const glm::vec3& H, float invLen2) const;  // (n.h)^N, N = e_x cos^2 phi + e_y sin^2 phi

    LobeShape shape_;
    glm::vec3 rd_;
    float specularProb_;
};

}  // namespace woven
