#pragma once
// The anisotropic Ashikhmin-Shirley BRDF (MODEL.md section 4) in its local frame: z = normal,
// x = the e_x axis. Specular lobe with Schlick Fresnel plus the coupled diffuse term; sampling
// mixes the half-vector sampling of the specular lobe with cosine-weighted diffuse sampling
// (one-sample MIS, so pdf() is the mixture density).
#include <glm/glm.hpp>
#include <optional>

#include "bsdf_sample.h"

namespace woven {

class AshikhminShirley {
public:
    AshikhminShirley(float ex, float ey, float rs, const glm::vec3& rd);

    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const;
    // u: two uniform numbers in [0, 1) for the direction, uc one more for the lobe choice.
    std::optional<BsdfSample> sample(const glm::vec3& wo, const glm::vec2& u, float uc) const;

    bool transmits() const { return false; }
    float ex() const { return ex_; }
    float ey() const { return ey_; }
    float rs() const { return rs_; }
    const glm::vec3& rd() const { return rd_; }  // the diffuse reflectance R_d
    float specularProbability() const { return specularProb_; }
    // Density of half vector h for the specular lobe (the source's eq. 1, p_h).
    float halfVectorPdf(const glm::vec3& h) const;

private:
    float exponent(const glm::vec3& h) const;  // N = e_x cos^2 phi + e_y sin^2 phi
    glm::vec3 sampleHalfVector(const glm::vec2& u) const;

    float ex_, ey_, rs_;
    glm::vec3 rd_;
    float specNorm_;  // sqrt((e_x + 1)(e_y + 1))
    float specularProb_;
};

}  // namespace woven
