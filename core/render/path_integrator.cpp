#include "path_integrator.h"

#include <algorithm>
#include <cmath>

namespace woven {

namespace {

// Russian roulette starts after this many bounces, and a path survives it with probability
// sqrt(max throughput), as Cycles' rule: a path is ended later on average than by the throughput
// itself (pbrt-v4's rule). Early bounces carry most of the image; in a closed room of bright walls
// the later ones still carry much of it. On the Lambert box (docs/RESULTS.md) this start and rule
// gave a lower relMSE at equal spp than the throughput's rule from bounce 5 (0.00328 and 0.00331
// against 0.00337 at 256 spp) for 4 % fewer rays a sample; from bounce 3, 11 % fewer rays but a
// relMSE of 0.00353; from bounce 5, 3 % more rays for 0.00316.
constexpr int kRouletteDepth = 4;

float maxComponent(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
bool isBlack(const glm::vec3& v) { return v.x <= 0.0f && v.y <= 0.0f && v.z <= 0.0f; }

}  // namespace

PathIntegrator::PathIntegrator(const RenderScene& scene, const CameraModel& camera, int maxDepth, bool filterWeave)
    : scene_(scene), camera_(camera), maxDepth_(maxDepth), filterWeave_(filterWeave) {
    for (const Light& light : scene.lights()) lightsHittable_ = lightsHittable_ || !light.isDelta();
}

glm::vec3 PathIntegrator::sampleOneLight(const SurfaceHit& hit, int vertex, const Bsdf& bsdf, const glm::vec3& wo,
                                         Sampler& sampler, SampleSink& sink) const {
    float pmf = 0.0f;
    const int index = scene_.sampleLight(
        LightSampleContext{hit.p, hit.ns},
        lightChoiceNumber(scene_, sampler, sampleDimension(Subpath::Camera, vertex, SampleUse::LightChoice)), &pmf);
    const glm::vec2 u = sampler.get2D(sampleDimension(Subpath::Camera, vertex, SampleUse::LightPoint));
    if (index < 0 || !(pmf > 0.0f)) return glm::vec3(0.0f);
    const Light& light = scene_.lights()[size_t(index)];
    const auto ls = light.sampleLi(hit.p, u);
    if (!ls || !(ls->pdf > 0.0f) || isBlack(ls->L)) return glm::vec3(0.0f);
    if (!connects(hit, bsdf, wo, ls->wi)) return glm::vec3(0.0f);
    const glm::vec3 f = bsdf.eval(wo, ls->wi) * std::abs(glm::dot(ls->wi, cosineNormal(bsdf, wo, ls->wi)));
    if (isBlack(f)) return glm::vec3(0.0f);
    ++sink.rays;
    const bool blocked = light.isInfinite() ? scene_.occludedToInfinity(hit, ls->wi) : scene_.occluded(hit, ls->pLight);
    if (blocked) return glm::vec3(0.0f);
    const float lightPdf = pmf * ls->pdf;
    const float weight = light.isDelta() ? 1.0f : powerHeuristic(lightPdf, bsdf.pdf(wo, ls->wi));
    return f * ls->L * (weight / lightPdf);
}

glm::vec3 PathIntegrator::Li(const glm::vec2& pRaster, Sampler& sampler, SampleSink& sink) const {
    glm::vec3 L(0.0f), beta(1.0f);
    Ray ray = camera_.generateRay(pRaster);
    // The previous scattering vertex and the BSDF density of the direction sampled there, for
    // weighting emission found by BSDF sampling against next-event estimation.
    LightSampleContext prev;
    float prevBsdfPdf = 0.0f;
    for (int bounces = 0;; ++bounces) {
        ++sink.rays;
        auto hit = scene_.intersect(ray, bounces == 0 ? RayKind::Camera : RayKind::Scattered);
        if (!hit) {
            const int env = scene_.environmentLight();
            if (env >= 0) {
                const Light& light = scene_.lights()[size_t(env)];
                float weight = 1.0f;
                if (bounces > 0) {
                    const float lightPdf = scene_.lightPmf(prev, env) * light.pdfLi(prev.p, ray.d, glm::vec3(0.0f), glm::vec3(0.0f));
                    weight = powerHeuristic(prevBsdfPdf, lightPdf);
                }
                L += beta * light.Le(ray.d) * weight;
            }
            break;
        }
        const glm::vec3 wo = -ray.d;
        const glm::vec3 Le = scene_.emitted(*hit, wo);
        if (!isBlack(Le)) {
            float weight = 1.0f;
            const int index = scene_.lightIndex(*hit);
            if (bounces > 0 && index >= 0) {
                const float lightPdf = scene_.lightPmf(prev, index) *
                                       scene_.lights()[size_t(index)].pdfLi(prev.p, ray.d, hit->p, hit->ng);
                weight = powerHeuristic(prevBsdfPdf, lightPdf);
            }
            L += beta * Le * weight;
        }
        if (bounces >= maxDepth_) break;
        if (filterWeave_) addFootprint(*hit, scene_, camera_);
        const auto bsdf = scene_.materials().bsdf(*hit, wo);
        if (bounces == 0 && sink.recordsFirstHit) sink.firstHit = firstHitOf(scene_, *hit, bsdf, ray.o);
        if (!bsdf) break;

        const int vertex = bounces + 1;  // the camera is vertex 0
        L += beta * sampleOneLight(*hit, vertex, *bsdf, wo, sampler, sink);
        // The last vertex's BSDF sample adds only the light its ray hits: none where every light
        // is a point, spot or directional one (a render of woven fit's, of depth 1, spent a fifth
        // of its time sampling that ray). The sampler's numbers are per dimension, so the rest of
        // the path is the same.
        if (bounces + 1 >= maxDepth_ && !lightsHittable_) break;

        const glm::vec2 u = sampler.get2D(sampleDimension(Subpath::Camera, vertex, SampleUse::BsdfDirection));
        const auto bs = bsdf->sample(wo, u, lobeNumber(*bsdf, sampler, sampleDimension(Subpath::Camera, vertex, SampleUse::BsdfLobe)));
        if (!bs || !connects(*hit, *bsdf, wo, bs->wi)) break;
        beta *= bs->weight;
        if (isBlack(beta) || !std::isfinite(beta.x + beta.y + beta.z)) break;
        prev = {hit->p, hit->ns};
        prevBsdfPdf = bs->pdf;
        ray = scene_.spawnRay(*hit, bs->wi);

        if (bounces + 1 >= kRouletteDepth) {
            const float survive = std::min(1.0f, std::sqrt(maxComponent(beta)));
            if (sampler.get1D(sampleDimension(Subpath::Camera, vertex, SampleUse::Roulette)) >= survive) break;
            beta /= survive;
        }
    }
    return L;
}

}  // namespace woven
