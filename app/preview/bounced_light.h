#pragma once
// One bounce of light for the preview's ambient term. The path tracer lights a point also by
// light that came off other surfaces (a room lit off its ceiling, a hem lit by the floor, the
// inside of a lampshade); the preview's lights and sky do not. Per vertex and side, rays cast as
// sky_visibility.h's that meet geometry bring what leaves the hit towards the vertex,
// approximated as diffuse: the hit's albedo times the irradiance there (the preview's lights,
// each behind a shadow ray, plus the ambient times the hit's share of the sky) over pi. Their
// mean is a radiance the shader adds to the ambient the vertex sees (lighting.glsl's ambientAt()).
// Light off woven cloth is kept apart, as irradiance / pi with the share of it that left the
// cloth's front faces, and multiplied by the albedo of each face (wovenAlbedos()) when drawn: a
// woven edit traces nothing; a change of the geometry, of a mesh's material or of the lights
// traces again. The faces differ on most cloth (a denim's blue front, its white back), and a fold's
// inside sees the face the fold turned towards it. Traced on core's BVH (RenderScene); plain
// data, no GL.
#include <glm/glm.hpp>
#include <cstdint>
#include <vector>

#include "preview_lights.h"
#include "scene_description.h"

namespace woven {

constexpr int kBounceRays = 16;  // a side
constexpr int kHitSkyRays = 4;   // at each hit, for its share of the sky

// The first lights whose shadow rays a vertex keeps (VERTEX_SHADOW_LIGHTS in lighting.glsl): a
// byte each, four to a word.
constexpr int kVertexShadowLights = 8;

// What a vertex sees bounced, on the normal's side [0] and on the other [1], and, on finely meshed
// woven cloth (a drape, not a curtain of two triangles), which of the preview's first kVertexShadowLights lights it sees: light i reaches it where byte i % 4 of
// lightsSeen[i / 4] is 255, is blocked where it is 0. The shader takes the smaller of that,
// interpolated, and the shadow maps': a fold shading the cloth beside it is finer than a map's
// texel and its offset, and a triangle larger than a shadow's edge keeps the map's.
struct BouncedVertex {
    glm::vec3 radiance[2] = {glm::vec3(0.0f), glm::vec3(0.0f)};  // off every surface but woven cloth
    // Off woven cloth, before its albedo (rgb), and the share of that which left a front face
    // (a: core's side, by the hit triangle's winding).
    glm::vec4 offCloth[2] = {glm::vec4(0.0f), glm::vec4(0.0f)};
    uint32_t lightsSeen[kVertexShadowLights / 4] = {0xFFFFFFFFU, 0xFFFFFFFFU};
};

struct BouncedLight {
    // Per mesh of the scene, per vertex; zero for an instanced mesh and a mesh without normals
    // (as skyVisibility() leaves them at (1, 1)).
    std::vector<std::vector<BouncedVertex>> meshes;
    // Per material, its share of the rays that met woven cloth: the weights of the woven
    // materials' wovenAlbedos() in the albedos offCloth is multiplied by.
    std::vector<float> clothShares;
    size_t rays = 0;  // traced, the shadow rays included
};

BouncedLight bouncedLight(const SceneDescription& scene, const PreviewLights& lights);

// The cloth's albedo on each face to light from the whole hemisphere, as core's BSDF (the point
// model, what the Render button renders) reflects it averaged over the cloth: the mean of pi f over
// uv uniform across kAlbedoThreads threads each way and outgoing and incoming directions each
// cosine-distributed (Monte Carlo, a fixed seed). Not the lobes' own albedo(), R_d (1 - rs) + rs,
// which is what they reflect before the yarns shade and mask each other (docs/RESULTS.md).
constexpr float kAlbedoThreads = 1024.0f;  // past a tartan's repeat of colours
struct FaceAlbedos {
    glm::vec3 front = glm::vec3(0.0f), back = glm::vec3(0.0f);
};
FaceAlbedos wovenAlbedos(const WovenParams& params, int samples = 16384);

}  // namespace woven
