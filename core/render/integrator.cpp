#include "integrator.h"

#include "footprint.h"

namespace woven {

void addFootprint(SurfaceHit& hit, const RenderScene& scene, const CameraModel& camera) {
    if (!scene.materials()[hit.material].filtersByFootprint()) return;
    const CameraModel::Footprint f = camera.footprint(hit.p, hit.ng);
    setUvFootprint(hit, f.dpdx, f.dpdy);
}

FirstHit firstHitOf(const RenderScene& scene, const SurfaceHit& hit, const std::optional<Bsdf>& bsdf, const glm::vec3& eye) {
    FirstHit f;
    f.depth = glm::length(hit.p - eye);
    f.normal = bsdf ? bsdf->shadingNormal() : hit.ns;
    if (!bsdf) return f;
    f.albedo = bsdf->albedo();
    const glm::vec3 wo = (eye - hit.p) / f.depth;
    for (const int index : scene.directPassLights()) {
        // The same point of the light for every sample: a guide free of the lights' sampling noise.
        const auto ls = scene.lights()[size_t(index)].fixedPointLi(hit.p);
        if (!ls || !(ls->pdf > 0.0f) || !connects(hit, *bsdf, wo, ls->wi)) continue;
        f.direct += bsdf->eval(wo, ls->wi) * ls->L * (std::abs(glm::dot(ls->wi, cosineNormal(*bsdf, wo, ls->wi))) / ls->pdf);
    }
    return f;
}

}  // namespace woven
