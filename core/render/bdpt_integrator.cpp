#include "bdpt_integrator.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "math_constants.h"

namespace woven {

namespace {

bool isBlack(const glm::vec3& v) { return v.x <= 0.0f && v.y <= 0.0f && v.z <= 0.0f; }
float remap0(float f) { return f != 0.0f ? f : 1.0f; }

}  // namespace

// Our BSDFs have no specular (delta) lobes, so unlike pbrt-v3 no vertex carries a delta flag:
// the only degenerate vertices are delta lights.
struct BdptIntegrator::Vertex {
    enum class Type { Camera, Light, Surface } type = Type::Camera;
    glm::vec3 beta{0.0f};
    glm::vec3 p{0.0f};
    glm::vec3 n{0.0f};   // geometric normal; zero for a vertex not on a surface
    glm::vec3 ns{0.0f};  // the normal of cosine factors: the BSDF's shading normal, a light's normal
    glm::vec3 dir{0.0f};  // infinite lights: the direction light travels, into the scene
    glm::vec3 wo{0.0f};   // surfaces: unit direction towards the vertex before
    SurfaceHit hit;
    std::optional<Bsdf> bsdf;
    int light = -1;  // light vertices: index into lights(); surfaces: their area light or -1
    float pdfFwd = 0.0f, pdfRev = 0.0f;

    bool onSurface() const { return n != glm::vec3(0.0f); }
    bool isLight() const { return type == Type::Light || (type == Type::Surface && light >= 0); }
};

namespace {

using Vertex = BdptIntegrator::Vertex;

// The normal of the cosine factors at v between wo and wi: a light's normal, a surface's
// cosineNormal() (the shading normal but where a yarn transmits, bsdf.h).
glm::vec3 cosineNormal(const Vertex& v, const glm::vec3& wo, const glm::vec3& wi) {
    return v.type == Vertex::Type::Surface && v.bsdf ? cosineNormal(*v.bsdf, wo, wi) : v.ns;
}

// Adjoint BSDF with shading normals (Veach 1997, 5.3): light subpaths scale by this factor.
float shadingNormalCorrection(const Vertex& v, const glm::vec3& wo, const glm::vec3& wi) {
    const glm::vec3 ns = cosineNormal(v, wo, wi);
    const float num = std::abs(glm::dot(wo, ns)) * std::abs(glm::dot(wi, v.n));
    const float den = std::abs(glm::dot(wo, v.n)) * std::abs(glm::dot(wi, ns));
    return den > 0.0f ? num / den : 0.0f;
}

// f at surface vertex v towards wi (unit); zero across the geometric surface.
glm::vec3 vertexF(const Vertex& v, const glm::vec3& wi, bool importance) {
    if (v.type != Vertex::Type::Surface || !v.bsdf || !connects(v.hit, *v.bsdf, v.wo, wi)) return glm::vec3(0.0f);
    glm::vec3 f = v.bsdf->eval(v.wo, wi);
    if (importance) f *= shadingNormalCorrection(v, v.wo, wi);
    return f;
}

glm::vec3 directionTo(const Vertex& from, const Vertex& to) { return glm::normalize(to.p - from.p); }

// The per-sample subpath storage, reused by each thread: no allocation per sample.
std::vector<Vertex>& scratch(int which, size_t size) {
    thread_local std::vector<Vertex> buffers[2];
    if (buffers[which].size() < size) buffers[which].resize(size);
    return buffers[which];
}

}  // namespace

bool BdptIntegrator::isInfiniteLight(const Vertex& v) const {
    // An escaped camera ray is a vertex on the environment even when there is none (light -1).
    return v.type == Vertex::Type::Light && (v.light < 0 || scene_.lights()[size_t(v.light)].isInfinite());
}

bool BdptIntegrator::isDeltaLight(const Vertex& v) const {
    return v.type == Vertex::Type::Light && v.light >= 0 && scene_.lights()[size_t(v.light)].isDelta();
}

bool BdptIntegrator::isConnectible(const Vertex& v) const {
    switch (v.type) {
        case Vertex::Type::Camera: return true;
        case Vertex::Type::Light: return v.light >= 0 && !scene_.lights()[size_t(v.light)].isDeltaDirection();
        case Vertex::Type::Surface: return v.bsdf.has_value();
    }
    return false;
}

float BdptIntegrator::convertDensity(const Vertex& from, float pdfSolidAngle, const Vertex& next) const {
    if (isInfiniteLight(next)) return pdfSolidAngle;
    const glm::vec3 w = next.p - from.p;
    const float dist2 = glm::dot(w, w);
    if (!(dist2 > 0.0f)) return 0.0f;
    float pdf = pdfSolidAngle / dist2;
    if (next.onSurface()) pdf *= std::abs(glm::dot(next.n, w / std::sqrt(dist2)));
    return pdf;
}

float BdptIntegrator::pdf(const Vertex& v, const Vertex* prev, const Vertex& next) const {
    if (v.type == Vertex::Type::Light) return pdfLight(v, next);
    const glm::vec3 toNext = next.p - v.p;
    if (!(glm::dot(toNext, toNext) > 0.0f)) return 0.0f;
    const glm::vec3 wn = glm::normalize(toNext);
    float pdfDir = 0.0f;
    if (v.type == Vertex::Type::Camera) {
        float pdfPos;
        camera_.pdfWe(Ray{v.p, wn}, &pdfPos, &pdfDir);
    } else {
        const glm::vec3 toPrev = prev->p - v.p;
        if (!v.bsdf || !(glm::dot(toPrev, toPrev) > 0.0f)) return 0.0f;
        const glm::vec3 wp = glm::normalize(toPrev);
        if (!connects(v.hit, *v.bsdf, wp, wn)) return 0.0f;
        pdfDir = v.bsdf->pdf(wp, wn);
    }
    return convertDensity(v, pdfDir, next);
}

float BdptIntegrator::pdfLight(const Vertex& v, const Vertex& next) const {
    float pdf;
    glm::vec3 w;
    if (isInfiniteLight(v)) {
        // Parallel rays through a disk of the scene's radius: a planar density, no 1/r^2.
        w = v.dir;
        if (v.light >= 0) {
            float pdfDir;
            scene_.lights()[size_t(v.light)].pdfLe(Ray{v.p, w}, v.n, &pdf, &pdfDir);
        } else {
            const float r = scene_.bounds().radius();  // the disk light sampling would use
            pdf = 1.0f / (kPi * r * r);
        }
    } else {
        const glm::vec3 d = next.p - v.p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return 0.0f;
        w = d / std::sqrt(dist2);
        float pdfPos, pdfDir;
        scene_.lights()[size_t(v.light)].pdfLe(Ray{v.p, w}, v.n, &pdfPos, &pdfDir);
        pdf = pdfDir / dist2;
    }
    if (next.onSurface()) pdf *= std::abs(glm::dot(next.n, w));
    return pdf;
}

float BdptIntegrator::infiniteLightDensity(const glm::vec3& dirFromLight) const {
    const int env = scene_.environmentLight();  // directional lights have no density over directions
    if (env < 0) return 0.0f;
    return scene_.lightPmf(env) *
           scene_.lights()[size_t(env)].pdfLi(glm::vec3(0.0f), -dirFromLight, glm::vec3(0.0f), glm::vec3(0.0f));
}

float BdptIntegrator::pdfLightOrigin(const Vertex& v, const Vertex& next) const {
    if (isInfiniteLight(v)) return infiniteLightDensity(v.dir);
    const glm::vec3 d = next.p - v.p;
    if (!(glm::dot(d, d) > 0.0f)) return 0.0f;
    float pdfPos, pdfDir;
    scene_.lights()[size_t(v.light)].pdfLe(Ray{v.p, glm::normalize(d)}, v.n, &pdfPos, &pdfDir);
    return pdfPos * scene_.lightPmf(v.light);
}

glm::vec3 BdptIntegrator::Le(const Vertex& v, const Vertex& towards) const {
    if (!v.isLight()) return glm::vec3(0.0f);
    if (isInfiniteLight(v)) {
        const int env = scene_.environmentLight();
        return env >= 0 ? scene_.lights()[size_t(env)].Le(-v.dir) : glm::vec3(0.0f);
    }
    return scene_.emitted(v.hit, directionTo(v, towards));
}

int BdptIntegrator::randomWalk(Ray ray, glm::vec3 beta, float pdfFwd, int maxVertices, bool importance, Sampler& sampler,
                               SampleSink& sink, Vertex* path) const {
    if (maxVertices <= 0) return 0;
    const Subpath subpath = importance ? Subpath::Light : Subpath::Camera;
    int count = 0;
    while (true) {
        ++sink.rays;
        auto hit = scene_.intersect(ray, !importance && count == 0 ? RayKind::Camera : RayKind::Scattered);
        Vertex& v = path[count];
        Vertex& prev = path[count - 1];  // the path's start sits before path[0]
        if (!hit) {
            // A camera ray escaping is a vertex on the environment (s = 0 strategies).
            if (!importance) {
                v = Vertex{};
                v.type = Vertex::Type::Light;
                v.light = scene_.environmentLight();
                v.p = ray.o + ray.d;
                v.dir = -ray.d;
                v.beta = beta;
                v.pdfFwd = pdfFwd;
                ++count;
            }
            break;
        }
        if (filterWeave_) addFootprint(*hit, scene_, camera_);
        v = Vertex{};
        v.type = Vertex::Type::Surface;
        v.hit = *hit;
        v.p = hit->p;
        v.n = hit->ng;
        v.wo = -ray.d;
        v.bsdf = scene_.materials().bsdf(*hit, v.wo);
        v.ns = v.bsdf ? v.bsdf->shadingNormal() : hit->ns;
        if (!importance && count == 0 && sink.recordsFirstHit) sink.firstHit = firstHitOf(scene_, v.hit, v.bsdf, ray.o);
        v.light = scene_.lightIndex(*hit);
        v.beta = beta;
        v.pdfFwd = convertDensity(prev, pdfFwd, v);
        if (++count >= maxVertices || !v.bsdf) break;

        const glm::vec2 u = sampler.get2D(sampleDimension(subpath, count, SampleUse::BsdfDirection));
        const auto bs = v.bsdf->sample(v.wo, u, lobeNumber(*v.bsdf, sampler, sampleDimension(subpath, count, SampleUse::BsdfLobe)));
        if (!bs || !connects(v.hit, *v.bsdf, v.wo, bs->wi)) break;
        beta *= bs->weight;
        if (importance) beta *= shadingNormalCorrection(v, v.wo, bs->wi);
        if (isBlack(beta) || !std::isfinite(beta.x + beta.y + beta.z)) break;
        pdfFwd = bs->pdf;
        prev.pdfRev = convertDensity(v, v.bsdf->pdf(bs->wi, v.wo), prev);
        ray = scene_.spawnRay(v.hit, bs->wi);
    }
    return count;
}

int BdptIntegrator::cameraSubpath(const glm::vec2& pRaster, Sampler& sampler, SampleSink& sink, Vertex* path) const {
    const Ray ray = camera_.generateRay(pRaster);
    path[0] = Vertex{};
    path[0].type = Vertex::Type::Camera;
    path[0].p = ray.o;
    path[0].beta = glm::vec3(1.0f);
    float pdfPos, pdfDir;
    camera_.pdfWe(ray, &pdfPos, &pdfDir);
    return 1 + randomWalk(ray, path[0].beta, pdfDir, maxDepth_ + 1, false, sampler, sink, path + 1);
}

int BdptIntegrator::lightSubpath(Sampler& sampler, SampleSink& sink, Vertex* path) const {
    float pmf = 0.0f;
    const int index = scene_.sampleLight(lightChoiceNumber(scene_, sampler, sampleDimension(Subpath::Light, 0, SampleUse::LightChoice)), &pmf);
    const glm::vec2 u1 = sampler.get2D(sampleDimension(Subpath::Light, 0, SampleUse::LightPoint)),
                    u2 = sampler.get2D(sampleDimension(Subpath::Light, 0, SampleUse::LightDirection));
    if (index < 0 || !(pmf > 0.0f)) return 0;
    const Light& light = scene_.lights()[size_t(index)];
    const auto le = light.sampleLe(u1, u2);
    if (!le || !(le->pdfPos > 0.0f) || !(le->pdfDir > 0.0f) || isBlack(le->L)) return 0;

    Vertex& v = path[0];
    v = Vertex{};
    v.type = Vertex::Type::Light;
    v.light = index;
    v.p = le->ray.o;
    if (!light.isDeltaPosition()) v.n = v.ns = le->nLight;  // point lights have no surface
    v.dir = le->ray.d;
    v.beta = le->L;
    v.pdfFwd = le->pdfPos * pmf;
    const float cosLight = light.isDeltaPosition() ? 1.0f : std::abs(glm::dot(le->nLight, le->ray.d));
    const glm::vec3 beta = le->L * (cosLight / (pmf * le->pdfPos * le->pdfDir));
    Ray ray = le->ray;
    if (light.planar()) {
        // Leave an area light like any surface, lifted off it, or the ray may hit its own triangle.
        SurfaceHit origin;
        origin.p = ray.o;
        origin.ng = v.n;
        ray = scene_.spawnRay(origin, ray.d);
    }
    const int count = randomWalk(ray, beta, le->pdfDir, maxDepth_, true, sampler, sink, path + 1);

    if (light.isInfinite()) {
        // The walk converted pdfDir as if from a point; from a disk of parallel rays the first
        // hit's density is the disk's (planar) one, and the light vertex's own is directional.
        if (count > 0) {
            path[1].pdfFwd = le->pdfPos;
            if (path[1].onSurface()) path[1].pdfFwd *= std::abs(glm::dot(le->ray.d, path[1].n));
        }
        path[0].pdfFwd = infiniteLightDensity(le->ray.d);
    }
    return count + 1;
}

float BdptIntegrator::misWeight(const Vertex* light, const Vertex* camera, const Vertex& sampled, int s, int t) const {
    if (s + t == 2) return 1.0f;
    // The vertices on both sides of the connection (the freshly sampled one for s = 1 or t = 1).
    const Vertex* qs = s > 0 ? (s == 1 ? &sampled : &light[s - 1]) : nullptr;
    const Vertex* pt = t == 1 ? &sampled : &camera[t - 1];
    const Vertex* qsMinus = s > 1 ? &light[s - 2] : nullptr;
    const Vertex* ptMinus = t > 1 ? &camera[t - 2] : nullptr;

    // Reverse densities of these four vertices had the path been made by this connection.
    const float ptRev = s > 0 ? pdf(*qs, qsMinus, *pt) : pdfLightOrigin(*pt, *ptMinus);
    const float ptMinusRev = ptMinus ? (s > 0 ? pdf(*pt, qs, *ptMinus) : pdfLight(*pt, *ptMinus)) : 0.0f;
    const float qsRev = qs ? pdf(*pt, ptMinus, *qs) : 0.0f;
    const float qsMinusRev = qsMinus ? pdf(*qs, pt, *qsMinus) : 0.0f;

    // Power heuristic: sum over the other strategies of (p_other / p_this)^2, each ratio built up
    // one vertex at a time along either subpath.
    float sumRatios = 0.0f, ratio = 1.0f;
    for (int i = t - 1; i > 0; --i) {
        const float rev = i == t - 1 ? ptRev : i == t - 2 ? ptMinusRev : camera[i].pdfRev;
        const float fwd = i == t - 1 ? pt->pdfFwd : camera[i].pdfFwd;
        ratio *= remap0(rev) / remap0(fwd);
        sumRatios += ratio * ratio;
    }
    ratio = 1.0f;
    for (int i = s - 1; i >= 0; --i) {
        const Vertex& v = i == s - 1 ? *qs : light[i];
        const float rev = i == s - 1 ? qsRev : i == s - 2 ? qsMinusRev : light[i].pdfRev;
        ratio *= remap0(rev) / remap0(v.pdfFwd);
        // Strategy s = i: i = 0 means hitting the light, impossible for a delta light.
        const bool impossible = i == 0 && isDeltaLight(s == 1 ? sampled : light[0]);
        if (!impossible) sumRatios += ratio * ratio;
    }
    const float w = 1.0f / (1.0f + sumRatios);
    return std::isfinite(w) ? w : 0.0f;
}

glm::vec3 BdptIntegrator::connect(Vertex* light, Vertex* camera, int s, int t, Sampler& sampler, SampleSink& sink,
                                  glm::vec2* pRaster) const {
    // An escaped camera ray only ends a path by itself (s = 0).
    if (t > 1 && s != 0 && camera[t - 1].type == Vertex::Type::Light) return glm::vec3(0.0f);
    glm::vec3 L(0.0f);
    Vertex sampled;
    if (s == 0) {
        const Vertex& pt = camera[t - 1];
        if (pt.isLight()) L = Le(pt, camera[t - 2]) * pt.beta;
    } else if (t == 1) {
        const Vertex& qs = light[s - 1];
        const glm::vec2 u = sampler.get2D(sampleDimension(Subpath::Light, s - 1, SampleUse::CameraPoint));
        if (!isConnectible(qs)) return glm::vec3(0.0f);
        const auto ws = camera_.sampleWi(qs.p, u);
        if (!ws || !(ws->pdf > 0.0f) || isBlack(ws->We)) return glm::vec3(0.0f);
        sampled.type = Vertex::Type::Camera;
        sampled.p = ws->pCamera;
        sampled.beta = ws->We / ws->pdf;
        L = qs.beta * vertexF(qs, ws->wi, true) * sampled.beta * std::abs(glm::dot(ws->wi, cosineNormal(qs, qs.wo, ws->wi)));
        if (isBlack(L)) return glm::vec3(0.0f);
        ++sink.rays;
        if (!scene_.seenFromCamera(qs.hit, ws->pCamera)) return glm::vec3(0.0f);
        *pRaster = ws->pRaster;
    } else if (s == 1) {
        const Vertex& pt = camera[t - 1];
        float pmf = 0.0f;
        const int index = scene_.sampleLight(
            lightChoiceNumber(scene_, sampler, sampleDimension(Subpath::Camera, t - 1, SampleUse::LightChoice)), &pmf);
        const glm::vec2 u = sampler.get2D(sampleDimension(Subpath::Camera, t - 1, SampleUse::LightPoint));
        if (!isConnectible(pt) || index < 0 || !(pmf > 0.0f)) return glm::vec3(0.0f);
        const Light& lightSource = scene_.lights()[size_t(index)];
        const auto ls = lightSource.sampleLi(pt.p, u);
        if (!ls || !(ls->pdf > 0.0f) || isBlack(ls->L)) return glm::vec3(0.0f);
        sampled.type = Vertex::Type::Light;
        sampled.light = index;
        sampled.p = ls->pLight;
        sampled.n = sampled.ns = ls->nLight;
        sampled.dir = -ls->wi;
        sampled.beta = ls->L / (ls->pdf * pmf);
        sampled.pdfFwd = pdfLightOrigin(sampled, pt);
        L = pt.beta * vertexF(pt, ls->wi, false) * sampled.beta * std::abs(glm::dot(ls->wi, cosineNormal(pt, pt.wo, ls->wi)));
        if (isBlack(L)) return glm::vec3(0.0f);
        ++sink.rays;
        const bool blocked = lightSource.isInfinite() ? scene_.occludedToInfinity(pt.hit, ls->wi)
                                                       : scene_.occluded(pt.hit, ls->pLight);
        if (blocked) return glm::vec3(0.0f);
    } else {
        const Vertex& qs = light[s - 1];
        const Vertex& pt = camera[t - 1];
        if (!isConnectible(qs) || !isConnectible(pt)) return glm::vec3(0.0f);
        const glm::vec3 d = qs.p - pt.p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return glm::vec3(0.0f);
        const glm::vec3 w = d / std::sqrt(dist2);  // from pt towards qs
        L = qs.beta * vertexF(qs, -w, true) * vertexF(pt, w, false) * pt.beta;
        if (isBlack(L)) return glm::vec3(0.0f);
        L *= std::abs(glm::dot(cosineNormal(pt, pt.wo, w), w)) * std::abs(glm::dot(cosineNormal(qs, qs.wo, -w), w)) / dist2;
        ++sink.rays;
        if (isBlack(L) || scene_.occluded(pt.hit, qs.p)) return glm::vec3(0.0f);
    }
    if (isBlack(L)) return glm::vec3(0.0f);
    return L * misWeight(light, camera, sampled, s, t);
}

glm::vec3 BdptIntegrator::Li(const glm::vec2& pRaster, Sampler& sampler, SampleSink& sink) const {
    // Camera subpaths have up to maxDepth + 2 vertices (camera, bounces, a light), light
    // subpaths up to maxDepth + 1; strategies are limited to maxDepth bounces.
    Vertex* camera = scratch(0, size_t(maxDepth_) + 2).data();
    Vertex* light = scratch(1, size_t(maxDepth_) + 1).data();
    const int nCamera = cameraSubpath(pRaster, sampler, sink, camera);
    const int nLight = lightSubpath(sampler, sink, light);
    glm::vec3 L(0.0f);
    // s = 1 samples a light vertex of its own: it exists even where the light subpath does not
    // (its origin emitted nothing, say on a black texel of a textured emitter), and its MIS
    // weight counts on it.
    const int maxS = std::max(nLight, 1);
    for (int t = 1; t <= nCamera; ++t)
        for (int s = 0; s <= maxS; ++s) {
            const int depth = s + t - 2;
            if ((s == 1 && t == 1) || depth < 0 || depth > maxDepth_) continue;
            glm::vec2 pSplat(0.0f);
            const glm::vec3 contribution = connect(light, camera, s, t, sampler, sink, &pSplat);
            if (!std::isfinite(contribution.x + contribution.y + contribution.z)) continue;
            if (t != 1) L += contribution;
            else if (!isBlack(contribution)) sink.splats.push_back({pSplat, contribution});
        }
    return L;
}

}  // namespace woven
