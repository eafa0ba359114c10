#include "embree_filters.h"

#include <cstdint>
#include <cstring>
#include <vector>

#include "sampling.h"
#include "tex_coords.h"

namespace woven {

namespace {

// The context filter of camera rays (and of rays towards the camera): only they pay for it, and
// only in a scene where some mesh is single-sided (Impl::culls).
void cullSingleSided(const RTCFilterFunctionNArguments* args) {
    const auto* filter = static_cast<const HitFilter*>(args->geometryUserPtr);
    if (!filter->singleSided) return;
    const Cull cull = reinterpret_cast<const CullContext*>(args->context)->cull;
    const std::vector<glm::vec3>& p = filter->mesh->positions;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const glm::uvec3 t = filter->mesh->triangles[RTCHitN_primID(args->hit, args->N, i)];
        const glm::vec3 front = glm::cross(p[t.y] - p[t.x], p[t.z] - p[t.x]);  // makeHit's ng
        const glm::vec3 d(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                          RTCRayN_dir_z(args->ray, args->N, i));
        const float towardsBack = glm::dot(front, d);
        if (cull == Cull::Back ? towardsBack > 0.0f : towardsBack < 0.0f) args->valid[i] = 0;
    }
}

// A uniform number for stochastic transparency from the ray and the candidate hit: a pure
// function of the path, so a frame stays a pure function of (scene, seed, sample range).
float transparencyRandom(const RTCFilterFunctionNArguments* args, unsigned i) {
    uint64_t h = mix64(uint64_t(RTCHitN_primID(args->hit, args->N, i)) * 0x9e3779b97f4a7c15ULL);
    // Copies of an instanced mesh see the ray in their own space; their instance keeps them apart.
    if (args->context->instID[0] != RTC_INVALID_GEOMETRY_ID) h = mix64(h ^ args->context->instID[0]);
    const float values[] = {RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i),
                            RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                            RTCRayN_dir_z(args->ray, args->N, i), RTCRayN_org_x(args->ray, args->N, i)};
    for (float v : values) {
        uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        h = mix64(h ^ bits);
    }
    return float(h >> 40) * 0x1p-24f;
}

}  // namespace

CullContext intersectContext(std::optional<Cull> cull) {
    CullContext context;
    rtcInitIntersectContext(&context.embree);
    if (cull) {
        context.embree.filter = cullSingleSided;
        context.cull = *cull;
    }
    return context;
}

void rejectPassThrough(const RTCFilterFunctionNArguments* args) {
    const auto* filter = static_cast<const HitFilter*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const TexCoords tc = interpolateTexCoords(*filter->mesh, RTCHitN_primID(args->hit, args->N, i),
                                                  RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
        // The hash costs more than most answers: only blended alpha asks for it.
        const float u = filter->random ? transparencyRandom(args, i) : 0.0f;
        if (filter->material->passesThrough(tc, u)) args->valid[i] = 0;
    }
}

}  // namespace woven
