#include "gltf_bxdf.h"

#include <algorithm>
#include <cmath>

#include "luminance.h"
#include "math_constants.h"
#include "sampling.h"
#include "thin_film.h"

namespace woven {

namespace {
constexpr float kInvPi = 1.0f / kPi;

glm::vec3 clamp01(const glm::vec3& c) { return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f)); }
float clamp01(float x) { return std::isfinite(x) ? std::clamp(x, 0.0f, 1.0f) : 0.0f; }
glm::vec3 mirrorThroughSurface(const glm::vec3& w) { return {w.x, w.y, -w.z}; }
// Whether the specular lobe reflects anything: KHR_materials_specular's specularFactor 0 zeroes
// F0 and F90, leaving a dielectric with no specular (the Lambertian walls of
// bench/render/lambert_box.py), unless it is metal or a thin film over it reflects.
bool specularReflects(float metallic, const glm::vec3& f0, float f90, float iridescence) {
    return metallic > 0.0f || f90 > 0.0f || f0.x > 0.0f || f0.y > 0.0f || f0.z > 0.0f || iridescence > 0.0f;
}

// KHR_materials_anisotropy: the alpha along the anisotropy direction, mix(alpha, 1, strength^2).
float anisotropicAlpha(float roughness, float strength) {
    const float alpha = clamp01(roughness) * clamp01(roughness), s = clamp01(strength);
    return alpha + (1.0f - alpha) * s * s;
}
}  // namespace

GltfBxdf::GltfBxdf(const GltfBxdfInputs& in)
    : baseColor_(clamp01(in.baseColor)),
      metallic_(clamp01(in.metallic)),
      ggx_(anisotropicAlpha(in.roughness, in.anisotropy), clamp01(in.roughness) * clamp01(in.roughness)),
      f0_(clamp01(in.specularF0)),
      f90_(clamp01(in.specularF90)),
      transmission_(clamp01(in.transmission)),
      transmittance_(clamp01(in.transmittance)),
      diffuseTransmission_(clamp01(in.diffuseTransmission)),
      diffuseTransmissionColor_(clamp01(in.diffuseTransmissionColor)),
      // A surface without sheen or coat builds neither lobe (the coat's frame, the tables' clamps).
      sheen_(in.sheenColor != glm::vec3(0.0f) ? SheenLobe(in.sheenColor, in.sheenRoughness) : SheenLobe()),
      clearcoat_(in.clearcoat > 0.0f ? ClearcoatLobe(in.clearcoat, clamp01(in.clearcoatRoughness), in.clearcoatNormal)
                                     : ClearcoatLobe()),
      iridescence_(clamp01(in.iridescence)),
      iridescenceIor_(std::max(in.iridescenceIor, 1.0f)),
      iridescenceThickness_(std::max(in.iridescenceThickness, 0.0f)),
      outsideIor_(1.0f + 0.5f * clamp01(in.clearcoat)),
      lambertian_(!specularReflects(metallic_, f0_, f90_, iridescence_) && transmission_ == 0.0f &&
                  diffuseTransmission_ == 0.0f && !sheen_.active() && !clearcoat_.active()) {}

GltfBxdf::Fresnel GltfBxdf::fresnel(float cosTheta) const {
    const float weight = schlickWeight(cosTheta);
    Fresnel f{f0_ + (glm::vec3(f90_) - f0_) * weight, baseColor_ + (1.0f - baseColor_) * weight};
    if (iridescence_ > 0.0f) {
        // The extension's F = mix(F_schlick, F_iridescence, iridescence), the film over each base.
        const auto film = [&](const glm::vec3& baseF0) {
            return thinFilmFresnel(outsideIor_, iridescenceIor_, cosTheta, iridescenceThickness_, baseF0);
        };
        f.dielectric = glm::mix(f.dielectric, film(f0_), iridescence_);
        f.metal = glm::mix(f.metal, film(baseColor_), iridescence_);
    }
    return f;
}

glm::vec3 GltfBxdf::eval(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z == 0.0f) return glm::vec3(0.0f);
    const bool reflection = wi.z > 0.0f;
    if (!reflection && !transmits()) return glm::vec3(0.0f);
    if (lambertian_) return baseColor_ * kInvPi;
    // Thin-walled transmission is the reflection lobe mirrored through the surface.
    const glm::vec3 w = reflection ? wi : mirrorThroughSurface(wi);
    const glm::vec3 H = wo + w;
    const float len = glm::length(H);
    if (!(len > 1e-12f)) return glm::vec3(0.0f);
    const glm::vec3 h = H / len;
    const Fresnel F = fresnel(0.5f * len);  // wo.h = |wo + w| / 2 for unit vectors
    // The GGX lobe (reflected, and mirrored for the thin-walled transmission), whose evaluation
    // a Lambertian surface skips.
    const float specular = transmits() || specularReflects(metallic_, f0_, f90_, iridescence_)
                               ? ggx_.D(h) * ggx_.visibility(wo, w)
                               : 0.0f;
    const glm::vec3& dielectricF = F.dielectric;

    glm::vec3 f;
    if (reflection) {
        const glm::vec3 dielectric =
            (1.0f - dielectricF) * (1.0f - transmission_) * (1.0f - diffuseTransmission_) * baseColor_ * kInvPi +
            dielectricF * specular;
        const glm::vec3 metal = F.metal * specular;
        f = (1.0f - metallic_) * dielectric + metallic_ * metal;
    } else {
        f = (1.0f - metallic_) * transmission_ * (1.0f - dielectricF) * baseColor_ * transmittance_ * specular +
            (1.0f - metallic_) * (1.0f - transmission_) * diffuseTransmission_ * kInvPi * (1.0f - dielectricF) *
                diffuseTransmissionColor_;
    }
    if (sheen_.active()) {
        f *= std::min(sheen_.baseScale(wo.z), sheen_.baseScale(w.z));
        if (reflection) f += sheen_.eval(wo, wi);
    }
    if (clearcoat_.active()) {
        // wi itself, not its mirror w: light from behind a thin wall crosses the coat on that
        // side, whose normal is -n_c, at |n_c . wi|. With a tilted coat normal the mirror would
        // make the transmission non-reciprocal.
        f *= clearcoat_.baseScale(wo, wi);
        if (reflection) f += clearcoat_.eval(wo, wi);
    }
    return f;
}

GltfBxdf::LobeChoice GltfBxdf::choose(const glm::vec3& wo) const {
    if (lambertian_) return LobeChoice{0.0f, 1.0f};
    const Fresnel F = fresnel(wo.z);
    const float dielectricF = luminance(F.dielectric);
    const float metalF = luminance(F.metal);
    const float below = sheen_.baseScale(wo.z) * (1.0f - clearcoat_.reflectance(wo));
    const float base = luminance(baseColor_);
    LobeChoice c;
    c.specular = below * ((1.0f - metallic_) * dielectricF + metallic_ * metalF);
    const float diffuseShare = below * (1.0f - metallic_) * (1.0f - transmission_) * (1.0f - dielectricF);
    c.diffuse = diffuseShare * (1.0f - diffuseTransmission_) * base;
    c.transmission = below * (1.0f - metallic_) * transmission_ * (1.0f - dielectricF) * luminance(baseColor_ * transmittance_);
    c.diffuseTransmission = diffuseShare * diffuseTransmission_ * luminance(diffuseTransmissionColor_);
    c.sheen = sheen_.active() ? (1.0f - clearcoat_.reflectance(wo)) * sheen_.maxColor() * sheen_.albedo(wo.z) : 0.0f;
    c.clearcoat = clearcoat_.reflectance(wo);
    // Each lobe whose f can be non-zero keeps some probability, so pdf() never vanishes where
    // f does not (a black base colour still reflects through its Fresnel term, and so on). A
    // specular lobe that reflects nothing gets none: its samples would all be lost.
    if (specularReflects(metallic_, f0_, f90_, iridescence_)) c.specular = std::max(c.specular, 0.02f);
    if (metallic_ < 1.0f && transmission_ > 0.0f) c.transmission = std::max(c.transmission, 0.02f);
    if (metallic_ < 1.0f && transmission_ < 1.0f && diffuseTransmission_ < 1.0f) c.diffuse = std::max(c.diffuse, 0.02f);
    if (metallic_ < 1.0f && diffuseTransmits()) c.diffuseTransmission = std::max(c.diffuseTransmission, 0.02f);
    const float sum = c.specular + c.diffuse + c.transmission + c.sheen + c.diffuseTransmission + c.clearcoat;
    c.specular /= sum;
    c.diffuse /= sum;
    c.transmission /= sum;
    c.sheen /= sum;
    c.diffuseTransmission /= sum;
    c.clearcoat /= sum;
    return c;
}

float GltfBxdf::pdf(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z == 0.0f) return 0.0f;
    // The cosine lobe alone, as below with its choice of 1 (the same number to the bit).
    if (lambertian_) return wi.z > 0.0f ? wi.z * kInvPi : 0.0f;
    const LobeChoice c = choose(wo);
    if (wi.z < 0.0f) {
        if (!transmits()) return 0.0f;
        float p = c.diffuseTransmission * -wi.z * kInvPi;
        if (c.transmission > 0.0f) p += c.transmission * ggx_.reflectionPdf(wo, mirrorThroughSurface(wi));
        return p;
    }
    float p = (c.diffuse + c.sheen) * wi.z * kInvPi;
    if (c.specular > 0.0f) p += c.specular * ggx_.reflectionPdf(wo, wi);
    if (c.clearcoat > 0.0f) p += c.clearcoat * clearcoat_.pdf(wo, wi);
    return p;
}

std::optional<BsdfSample> GltfBxdf::sample(const glm::vec3& wo, const glm::vec2& u, float uc) const {
    if (wo.z <= 0.0f) return std::nullopt;
    if (lambertian_) {
        // The one lobe: choose(), pdf() and eval() would only confirm it, at a third of a
        // bounce's BSDF cost; the same sample to the bit.
        BsdfSample s;
        s.wi = sampleCosineHemisphere(u);
        s.pdf = s.wi.z * kInvPi;
        if (!(s.pdf > 0.0f)) return std::nullopt;
        s.f = baseColor_ * kInvPi;
        s.weight = s.f * (s.wi.z / s.pdf);
        return s;
    }
    const LobeChoice c = choose(wo);
    // The lobes' intervals of uc end at the running sums of their probabilities, which rounding
    // can leave a hair under 1: a uc past the last of them belongs to the last lobe that can be
    // chosen, not to the clearcoat's branch whatever its probability (an inactive coat then
    // gave directions pdf() does not count). Only such a uc pays for nextafter()'s call.
    const float toReflectedCosine = c.specular + c.transmission + c.diffuse + c.sheen;
    const float toCosine = toReflectedCosine + c.diffuseTransmission;
    if (uc >= toCosine + c.clearcoat) uc = std::nextafter(toCosine + c.clearcoat, 0.0f);
    glm::vec3 wi;
    if (uc < c.specular + c.transmission) {
        const glm::vec3 h = ggx_.sampleVisibleNormal(wo, u);
        wi = 2.0f * glm::dot(wo, h) * h - wo;
        if (wi.z <= 0.0f) return std::nullopt;
        if (uc >= c.specular) wi = mirrorThroughSurface(wi);
    } else if (uc < toCosine) {
        wi = sampleCosineHemisphere(u);
        if (uc >= toReflectedCosine) wi = mirrorThroughSurface(wi);
    } else {
        const auto coat = clearcoat_.sample(wo, u);
        // A tilted coat normal can reflect below the base's horizon: the coat only reflects,
        // and pdf() counts it above the surface alone, so such a direction is no sample (it
        // would pass for a transmitted one, weighted by the transmission's density).
        if (!coat || coat->z <= 0.0f) return std::nullopt;
        wi = *coat;
    }
    if (wi.z == 0.0f) return std::nullopt;
    BsdfSample s;
    s.wi = wi;
    s.pdf = pdf(wo, wi);
    if (!(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return std::nullopt;
    s.f = eval(wo, wi);
    s.weight = s.f * (std::abs(wi.z) / s.pdf);
    return s;
}

glm::vec3 GltfBxdf::albedo() const {
    const glm::vec3 below = baseColor_ * glm::mix(glm::vec3(1.0f), transmittance_, transmission_);
    const glm::vec3 dielectric = f0_ + (1.0f - f0_) * below;
    return glm::mix(dielectric, baseColor_, metallic_);
}

}  // namespace woven
