#include "bounced_light.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <mutex>

#include "frame.h"
#include "math_constants.h"
#include "render_scene.h"
#include "sampling.h"
#include "scene_camera.h"
#include "sky_visibility.h"
#include "woven_material.h"

namespace woven {

namespace {

bool emits(const SceneDescription& scene, int material) {
    return material >= 0 && material < int(scene.materials.size()) && scene.materials[size_t(material)].emits();
}

// Whether light leaving `from` along unit `wi` gets `distance` far (infinitely far: a
// directional light). Emitters are passed, as the shadow maps leave them out: an area light's
// samples sit on (or in) its own surface.
bool unblocked(const RenderScene& traced, const SceneDescription& scene, SurfaceHit from, const glm::vec3& wi,
               float distance) {
    constexpr int kMostEmittersPassed = 8;
    for (int i = 0; i < kMostEmittersPassed; ++i) {
        Ray ray = traced.spawnRay(from, wi);
        ray.tMax = distance * (1.0f - 1e-4f);
        const std::optional<SurfaceHit> hit = traced.intersect(ray);
        if (!hit) return true;
        if (!emits(scene, hit->material)) return false;
        distance -= hit->t;
        from = *hit;
    }
    return false;
}

// Where light `l` comes from at p: the unit direction towards it and its distance (infinite for a
// directional light).
void towardsLight(const PreviewLight& l, const glm::vec3& p, glm::vec3& wi, float& distance) {
    if (l.type == PreviewLight::Directional) {
        wi = -glm::normalize(l.position);
        distance = std::numeric_limits<float>::infinity();
        return;
    }
    const glm::vec3 d = l.position - p;
    distance = std::max(std::sqrt(glm::dot(d, d)), 1e-6f);
    wi = d / distance;
}

// Which of the first kVertexShadowLights lights reach the vertex at p with unit normal n, into
// `out.lightsSeen`: a shadow ray each, from the side the light is on. Returns the rays cast.
int seenLights(const RenderScene& traced, const SceneDescription& scene, const PreviewLights& lights, const glm::vec3& p,
               const glm::vec3& n, BouncedVertex& out) {
    std::fill(std::begin(out.lightsSeen), std::end(out.lightsSeen), 0xFFFFFFFFU);
    const int count = std::min<int>(kVertexShadowLights, int(lights.lights.size()));
    for (int i = 0; i < count; ++i) {
        glm::vec3 wi;
        float distance;
        towardsLight(lights.lights[size_t(i)], p, wi, distance);
        SurfaceHit from;
        from.p = p;
        from.ng = from.ns = glm::dot(wi, n) >= 0.0f ? n : -n;
        if (!unblocked(traced, scene, from, wi, distance)) out.lightsSeen[i / 4] &= ~(0xFFU << (8 * (i % 4)));
    }
    return count;
}

bool isWoven(const SceneDescription& scene, int material) {
    return material >= 0 && material < int(scene.materials.size()) && scene.materials[size_t(material)].woven.has_value();
}

// Whether a mesh's triangles are small enough for its vertices' shadow rays to draw a shadow
// (their mean edge under 1 % of the scene's size): a simulated drape or a sphere is, where a wall
// of two triangles would spread one corner's shadow over the room.
bool finelyMeshed(const Mesh& mesh, float sceneSize) {
    if (mesh.triangles.empty()) return false;
    double edges = 0.0;
    for (const glm::uvec3& t : mesh.triangles) {
        const glm::vec3 &a = mesh.positions[t.x], &b = mesh.positions[t.y], &c = mesh.positions[t.z];
        edges += double(glm::distance(a, b) + glm::distance(b, c) + glm::distance(c, a));
    }
    return edges / double(3 * mesh.triangles.size()) < 0.01 * double(sceneSize);
}

// Irradiance at `hit` about unit `n` (on the side light is gathered from) from the preview's
// lights, as lighting.glsl's incidentLight() has them, a shadow ray each.
glm::vec3 lightIrradiance(const RenderScene& traced, const SceneDescription& scene, const PreviewLights& lights,
                          const SurfaceHit& hit, const glm::vec3& n, size_t& rays) {
    glm::vec3 sum(0.0f);
    for (const PreviewLight& l : lights.lights) {
        glm::vec3 wi, intensity = l.intensity;
        float distance;
        towardsLight(l, hit.p, wi, distance);
        // An area sample as a disc of its area seen along its axis, L A / (d^2 + A / pi): at most
        // pi L however close a wall next to a lamp is, where a point's 1 / d^2 is not.
        if (l.type != PreviewLight::Directional) intensity /= distance * distance + l.area / kPi;
        const float cosine = glm::dot(wi, n);
        if (cosine <= 0.0f) continue;
        if (l.type == PreviewLight::Spot) {
            const float t = glm::clamp((glm::dot(-wi, l.axis) - l.cosOuter) / std::max(l.cosInner - l.cosOuter, 1e-4f), 0.0f, 1.0f);
            intensity *= t * t;
        } else if (l.type == PreviewLight::Area || l.type == PreviewLight::AreaTwoSided) {
            const float cosLight = glm::dot(-wi, l.axis);
            intensity *= l.type == PreviewLight::AreaTwoSided ? std::abs(cosLight) : std::max(cosLight, 0.0f);
        }
        if (std::max({intensity.r, intensity.g, intensity.b}) <= 0.0f) continue;
        ++rays;
        if (!unblocked(traced, scene, hit, wi, distance)) continue;
        sum += intensity * cosine;
    }
    return sum;
}

struct Gathered {
    BouncedVertex vertex;
    std::vector<int> clothHits;  // per material
    size_t rays = 0;
};

// What kBounceRays rays about unit n from p bring, into side `side` of `out`.
void gather(const RenderScene& traced, const SceneDescription& scene, const PreviewLights& lights, const glm::vec3& p,
            const glm::vec3& n, uint32_t key, int side, Gathered& out) {
    SurfaceHit from;
    from.p = p;
    from.ng = from.ns = n;
    const Frame frame = Frame::fromNormal(n);
    const float turn = vertexTurn(key);
    glm::vec3 radiance(0.0f), offCloth(0.0f), offFronts(0.0f);
    for (int i = 0; i < kBounceRays; ++i) {
        const glm::vec3 d = frame.toWorld(spiralDirection(i, kBounceRays, turn));
        ++out.rays;
        const std::optional<SurfaceHit> hit = traced.intersect(traced.spawnRay(from, d));
        if (!hit) continue;
        const glm::vec3 towards = -d;
        const glm::vec3 facing = glm::dot(hit->ns, towards) >= 0.0f ? hit->ns : -hit->ns;
        const float hitTurn = vertexTurn(key ^ (uint32_t(i + 1) * 0x85EBCA6BU));
        out.rays += kHitSkyRays;
        const glm::vec3 irradiance = lightIrradiance(traced, scene, lights, *hit, facing, out.rays) +
                                     kPi * lights.ambient * openShare(traced, *hit, facing, kHitSkyRays, hitTurn);
        const int m = hit->material;
        if (isWoven(scene, m)) {
            offCloth += irradiance / kPi;
            if (glm::dot(hit->ng, towards) >= 0.0f) offFronts += irradiance / kPi;
            ++out.clothHits[size_t(m)];
        } else {
            radiance += traced.materials()[m].unlitRadiance(hit->tex);
            if (const std::optional<Bsdf> bsdf = traced.materials().bsdf(*hit, towards))
                radiance += bsdf->albedo() * irradiance / kPi;
        }
    }
    out.vertex.radiance[side] = radiance / float(kBounceRays);
    const float total = offCloth.r + offCloth.g + offCloth.b;
    const float fronts = total > 0.0f ? (offFronts.r + offFronts.g + offFronts.b) / total : 1.0f;
    out.vertex.offCloth[side] = glm::vec4(offCloth / float(kBounceRays), fronts);
}

}  // namespace

BouncedLight bouncedLight(const SceneDescription& scene, const PreviewLights& lights) {
    BouncedLight out;
    out.clothShares.assign(scene.materials.size(), 0.0f);
    for (const Mesh& mesh : scene.meshes) out.meshes.emplace_back(mesh.positions.size());
    if (std::none_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.triangles.empty(); }))
        return out;  // the environment alone: nothing to bounce off
    const RenderScene traced(std::make_shared<const SceneDescription>(scene));
    const float sceneSize = 2.0f * sceneBounds(scene).radius();
    std::vector<int> clothHits(scene.materials.size(), 0);
    std::mutex mutex;
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        if (mesh.instances || mesh.normals.size() != mesh.positions.size()) continue;
        // Woven cloth alone: its folds shading it are what the maps miss. Another surface keeps the
        // maps: a cloth over it that lets light through its gaps may open or close them by an
        // edit, which traces nothing again.
        const bool keepsShadowRays = isWoven(scene, mesh.material) && finelyMeshed(mesh, sceneSize);
        // Each vertex is its own task: the same figures on any number of threads.
        tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.positions.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
            Gathered g{{}, std::vector<int>(scene.materials.size(), 0), 0};
            for (size_t i = r.begin(); i != r.end(); ++i) {
                const glm::vec3 n = mesh.normals[i];
                if (!(glm::dot(n, n) > 0.0f)) continue;
                const glm::vec3 unit = glm::normalize(n);
                const uint32_t key = uint32_t(i) * 2U + uint32_t(m) * 0x9E3779B9U;
                gather(traced, scene, lights, mesh.positions[i], unit, key, 0, g);
                gather(traced, scene, lights, mesh.positions[i], -unit, key + 1U, 1, g);
                if (keepsShadowRays) g.rays += size_t(seenLights(traced, scene, lights, mesh.positions[i], unit, g.vertex));
                out.meshes[m][i] = g.vertex;
            }
            const std::lock_guard<std::mutex> lock(mutex);
            for (size_t k = 0; k < clothHits.size(); ++k) clothHits[k] += g.clothHits[k];
            out.rays += g.rays;
        });
    }
    int total = 0;
    for (int c : clothHits) total += c;
    for (size_t k = 0; k < clothHits.size() && total > 0; ++k) out.clothShares[k] = float(clothHits[k]) / float(total);
    return out;
}

FaceAlbedos wovenAlbedos(const WovenParams& params, int samples) {
    const WovenMaterial model(params);
    const auto albedo = [&](bool back) {
        Rng rng(back ? 2 : 1);
        const glm::vec3 side(1.0f, 1.0f, back ? -1.0f : 1.0f);
        glm::dvec3 sum(0.0);
        for (int k = 0; k < samples; ++k) {
            ShadingInput in;
            in.uv = glm::dvec2(kAlbedoThreads * rng.uniform2());
            in.backSide = back;
            const glm::vec3 wo = side * sampleCosineHemisphere(rng.uniform2());
            const glm::vec3 wi = side * sampleCosineHemisphere(rng.uniform2());
            // A see-through gap reflects nothing.
            if (const std::optional<WovenShading> s = model.shade(in)) sum += glm::dvec3(s->bsdf.eval(wo, wi));
        }
        return glm::vec3(double(kPi) * sum / double(samples));
    };
    return {albedo(false), albedo(true)};
}

}  // namespace woven
