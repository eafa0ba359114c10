#pragma once
// The woven BSDF filtered over a pixel's footprint: the exact lobe at the point blended with the
// weave's far field (WeaveFarField) by farFieldWeight(), all in the tangent frame (x = +u, y = +v,
// z = the surface normal). A mixture: eval() and pdf() sum over its lobes, sample() picks one by
// its weight, so sampling matches pdf() exactly.
//
// Each lobe has its own bumped normal, and the integrators multiply eval() by the cosine to the
// shading normal (z here): eval() returns sum_k w_k f_k cos_k / |cos|, so that product is the
// mixture of the lobes each with its own cosine, as the exact model has at each point (|cos|
// bounded below, filtered_weave_lobe.cpp).
#include <optional>

#include "ashikhmin_shirley.h"
#include "frame.h"
#include "weave_far_field.h"

namespace woven {

class FilteredWeaveLobe {
public:
    // `farField`: the face's far field (it must outlive the lobe); `colors`: the footprint's mean
    // warp and weft colours and the backing colour, `scales` the factors of their lobes' weights
    // over the footprint (both in FarFieldColor order, WeaveFarField::footprintScales());
    // `farWeight` in [0, 1];
    // `nearFrame` (in the tangent frame) and `nearLobe`: the exact model at the point, weighted
    // 1 - farWeight.
    FilteredWeaveLobe(const WeaveFarField& farField, const glm::vec3 (&colors)[3], const glm::vec3& scales,
                      float farWeight, const Frame& nearFrame, const AshikhminShirley& nearLobe);

    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const;
    std::optional<BsdfSample> sample(const glm::vec3& wo, const glm::vec2& u, float uc) const;
    bool choosesLobe() const { return true; }  // sample() reads uc
    bool transmits() const { return false; }
    // The mixture's albedo: each lobe's (AshikhminShirley::albedo()) by its weight.
    glm::vec3 albedo() const;

    float farWeight() const { return farWeight_; }

private:
    AshikhminShirley lobe(const FarFieldLobe& l) const { return AshikhminShirley(l.shape, colors_[int(l.color)], l.specularProbability); }
    // sum_k w_k f_k cos_k (not divided by |cos|) and the mixture's pdf, in one pass.
    void evalAndPdf(const glm::vec3& wo, const glm::vec3& wi, glm::vec3* fCos, float* pdf) const;

    const WeaveFarField* farField_;
    glm::vec3 colors_[3];
    float weights_[3];  // farWeight x the scales: each far lobe's weight is its share times its colour's
    float farWeight_;
    Frame nearFrame_;
    AshikhminShirley nearLobe_;
};

}  // namespace woven
