#include "render_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

#include "frame.h"
#include "light_sampler.h"
#include "mesh_instances.h"
#include "sampling.h"
#include "scene_loader.h"
#include "scene_validation.h"

namespace woven {

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

float maxAbs(const glm::vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// pbrt's gamma(n) = n u / (1 - n u), the relative error bound of n float operations. The
// barycentric interpolation of p takes 7; the factor 4 covers Embree's own rounding when it
// intersects from an origin this close to the triangle (measured with RenderSceneOffsets: a
// factor of 1 leaks light into a closed box, 2 passes, 4 keeps a margin of two).
constexpr float kUnitRoundoff = 0.5f * 1.1920929e-7f;
constexpr float kPositionError = 4.0f * (7.0f * kUnitRoundoff) / (1.0f - 7.0f * kUnitRoundoff);
// A shadow ray stops this fraction short of its target (pbrt-v3's ShadowEpsilon), or more when
// the target's own rounding error is larger.
constexpr float kShadowEpsilon = 1e-4f;

// How far spawnRay lifts a ray's origin off the surface. A hit built by hand has no error bound:
// it takes the one of a point of its magnitude.
float spawnOffset(const SurfaceHit& hit) { return std::max(hit.pError, kPositionError * maxAbs(hit.p)); }

// What an Embree filter callback needs to decide whether a candidate hit lets the ray through.
struct HitFilter {
    const Mesh* mesh;
    const SurfaceMaterial* material;
    bool random;       // the material's answer depends on a random number (blended alpha)
    bool singleSided;  // glTF's doubleSided false: camera rays cull its back (RayKind)
};

// The face of single-sided surfaces a ray passes through: camera rays the back; rays towards the
// camera the faces that are backs seen from it, so that both ways agree.
enum class Cull { Back, Front };

// An intersect context that says what its context filter culls: Embree hands the filter back the
// pointer it was given, so Embree's part comes first.
struct CullContext {
    RTCIntersectContext embree;
    Cull cull = Cull::Back;
};

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

CullContext intersectContext(std::optional<Cull> cull) {
    CullContext context;
    rtcInitIntersectContext(&context.embree);
    if (cull) {
        context.embree.filter = cullSingleSided;
        context.cull = *cull;
    }
    return context;
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

// Rejects candidate hits at points that let rays through, for intersection and occlusion rays alike.
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

void embreeError(void* userPtr, RTCError code, const char* message) {
    auto* out = static_cast<std::string*>(userPtr);
    if (out->empty()) *out = message ? message : "unknown error";
}

}  // namespace

struct RenderScene::Impl {
    std::shared_ptr<const SceneDescription> scene;
    RTCDevice device = nullptr;
    RTCScene rtcScene = nullptr;
    std::string embreeMessage;

    std::optional<SceneMaterials> materials;
    std::vector<HitFilter> hitFilters;  // per mesh, referenced by Embree
    // An instanced mesh's triangles are one Embree scene that each of its copies instances; the
    // copies have the top scene's IDs from meshes.size() on (the other meshes keep their index).
    struct InstanceRef {
        unsigned mesh, instance;
    };
    std::vector<InstanceRef> instanceRefs;  // by instance ID - meshes.size()
    // Some mesh is single-sided: only then do camera rays (and rays towards the camera) take the
    // context filter that culls backs, and the scenes Embree's support for it.
    bool culls = false;
    RTCSceneFlags sceneFlags = RTC_SCENE_FLAG_ROBUST;

    std::vector<Light> lights;
    std::vector<int> directPassLights;
    std::vector<std::vector<int>> triangleLights;  // per mesh: light index per triangle (or empty)
    int environment = -1;
    std::optional<PowerLightSampler> lightSampler;
    std::optional<BvhLightSampler> lightTree;
    Bounds bounds;

    ~Impl() {
        if (rtcScene) rtcReleaseScene(rtcScene);
        if (device) rtcReleaseDevice(device);
    }

    [[noreturn]] void fail(const std::string& what) const { throw SceneError(scene->source + ": " + what); }

    // glTF's doubleSided false.
    bool singleSided(const Mesh& mesh) const {
        return mesh.material >= 0 && !scene->materials[size_t(mesh.material)].doubleSided;
    }
    void buildGeometry();
    RTCGeometry triangleGeometry(size_t m);
    void addInstances(size_t m, RTCGeometry triangles);
    void buildLights();
    SurfaceHit makeHit(unsigned meshIndex, int instance, unsigned prim, float b1, float b2, float t,
                       const glm::vec3& dir) const;
};

namespace {
// A hit triangle's corners in world space: the mesh's own, or an instanced copy's placed by its
// matrix as the loader places a node's mesh (gltf_loader.cpp's addPrimitive: normals by the
// inverse transpose, tangents by the matrix and made perpendicular again, the winding swapped
// under a mirroring matrix), so that a copy shades as the same mesh expanded into the world would.
struct Corners {
    glm::uvec3 tri;  // the vertex indices in the world's winding
    float b1, b2;    // the hit's barycentrics in that winding
    const glm::mat4* placement;  // an instanced copy's matrix, or null
    bool mirrored;               // the placement swaps the winding
    glm::vec3 p[3];
    glm::vec3 n[3];  // where the mesh has normals (hitCorners)
    glm::vec4 t[3];  // where it has tangents (hitCorners)
};

// The corners' positions and winding alone: what finding rectangular lamps needs of them.
Corners cornerPositions(const Mesh& mesh, int instance, unsigned prim, float b1, float b2) {
    Corners c;
    c.tri = mesh.triangles[prim];
    c.b1 = b1;
    c.b2 = b2;
    c.placement = instance >= 0 ? &(*mesh.instances)[size_t(instance)] : nullptr;
    c.mirrored = c.placement && glm::determinant(glm::mat3(*c.placement)) < 0.0f;
    if (c.mirrored) {
        std::swap(c.tri.y, c.tri.z);
        std::swap(c.b1, c.b2);
    }
    const glm::mat4* m = c.placement;
    for (int k = 0; k < 3; ++k)
        c.p[k] = m ? glm::vec3(*m * glm::vec4(mesh.positions[c.tri[k]], 1.0f)) : mesh.positions[c.tri[k]];
    return c;
}

// The positions, normals and tangents.
Corners hitCorners(const Mesh& mesh, int instance, unsigned prim, float b1, float b2) {
    Corners c = cornerPositions(mesh, instance, prim, b1, b2);
    const glm::mat4* m = c.placement;
    const glm::mat3 normalMatrix = m ? glm::transpose(glm::inverse(glm::mat3(*m))) : glm::mat3(1.0f);
    for (int k = 0; k < 3; ++k) {
        const unsigned v = c.tri[k];
        if (!mesh.normals.empty()) c.n[k] = m ? glm::normalize(normalMatrix * mesh.normals[v]) : mesh.normals[v];
        if (!mesh.tangents.empty()) {
            const glm::vec4& t = mesh.tangents[v];
            c.t[k] = m ? glm::vec4(Frame::fromNormalAndAxis(c.n[k], glm::mat3(*m) * glm::vec3(t)).x,
                                   c.mirrored ? -t.w : t.w)
                       : t;
        }
    }
    return c;
}
}  // namespace

void RenderScene::Impl::buildGeometry() {
    // WOVEN_EMBREE_CONFIG is Embree's device configuration (for example "isa=sse4.2" or
    // "isa=avx2"): the test suite runs on two CPUs' kernels with it (README.md, "Tests on two
    // CPUs' kernels").
    const char* config = std::getenv("WOVEN_EMBREE_CONFIG");
    device = rtcNewDevice(config);
    if (!device)
        fail(config ? std::string("cannot create the Embree device with WOVEN_EMBREE_CONFIG=\"") + config + "\""
                    : std::string("cannot create the Embree device"));
    rtcSetDeviceErrorFunction(device, embreeError, &embreeMessage);
    rtcScene = rtcNewScene(device);
    culls = std::any_of(scene->meshes.begin(), scene->meshes.end(), [&](const Mesh& mesh) { return singleSided(mesh); });
    if (culls) sceneFlags = RTCSceneFlags(sceneFlags | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneFlags(rtcScene, sceneFlags);
    // High quality (spatial splits) costs about a second for millions of triangles, little beside
    // a final frame's tracing, which it speeds up. No quality helps coincident triangles, which
    // every ray through them tests one by one (under 100 rays/s a thread for a million copies
    // at each quality): the loader drops exact copies instead (removeDuplicateTriangles()).
    rtcSetSceneBuildQuality(rtcScene, RTC_BUILD_QUALITY_HIGH);

    hitFilters.resize(scene->meshes.size());
    for (size_t m = 0; m < scene->meshes.size(); ++m) {
        const Mesh& mesh = scene->meshes[m];
        if (mesh.triangles.empty()) continue;
        RTCGeometry geom = triangleGeometry(m);
        if (mesh.instances) {
            addInstances(m, geom);
        } else {
            rtcAttachGeometryByID(rtcScene, geom, unsigned(m));
            rtcReleaseGeometry(geom);
        }
        const MeshBox box = worldBox(mesh);
        bounds.lo = glm::min(bounds.lo, box.lo);
        bounds.hi = glm::max(bounds.hi, box.hi);
    }
    rtcCommitScene(rtcScene);
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE) fail("Embree cannot build the scene: " + embreeMessage);
}

RTCGeometry RenderScene::Impl::triangleGeometry(size_t m) {
    const Mesh& mesh = scene->meshes[m];
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<glm::vec3*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(glm::vec3), mesh.positions.size()));
    auto* indices = static_cast<glm::uvec3*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(glm::uvec3), mesh.triangles.size()));
    if (!vertices || !indices) fail("mesh '" + mesh.name + "': Embree cannot allocate it: " + embreeMessage);
    std::copy(mesh.positions.begin(), mesh.positions.end(), vertices);
    std::copy(mesh.triangles.begin(), mesh.triangles.end(), indices);
    const SurfaceMaterial& material = (*materials)[mesh.material];
    hitFilters[m] = HitFilter{&mesh, &material, material.passesRandomly(), singleSided(mesh)};
    rtcSetGeometryUserData(geom, &hitFilters[m]);
    // Only meshes whose material can let rays through pay for the geometry's filter.
    if (material.mayPassThrough(mesh)) {
        rtcSetGeometryIntersectFilterFunction(geom, rejectPassThrough);
        rtcSetGeometryOccludedFilterFunction(geom, rejectPassThrough);
    }
    rtcCommitGeometry(geom);
    return geom;
}

// The filters see an instanced copy's rays in the mesh's own space, where its winding is the
// file's: a mirroring matrix turns both the ray and the front, so the cull's sign holds.
void RenderScene::Impl::addInstances(size_t m, RTCGeometry triangles) {
    RTCScene own = rtcNewScene(device);
    rtcSetSceneFlags(own, sceneFlags);
    rtcSetSceneBuildQuality(own, RTC_BUILD_QUALITY_HIGH);
    rtcAttachGeometryByID(own, triangles, 0);
    rtcReleaseGeometry(triangles);
    rtcCommitScene(own);
    const std::vector<glm::mat4>& placements = *scene->meshes[m].instances;
    for (size_t i = 0; i < placements.size(); ++i) {
        RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(instance, own);
        rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &placements[i][0][0]);
        rtcCommitGeometry(instance);
        rtcAttachGeometryByID(rtcScene, instance, unsigned(scene->meshes.size() + instanceRefs.size()));
        rtcReleaseGeometry(instance);
        instanceRefs.push_back({unsigned(m), unsigned(i)});
    }
    rtcReleaseScene(own);  // its instances hold it
}

namespace {
// Two triangles that together make a rectangle, as a modeller splits a quad: sharing a diagonal
// (two vertex indices), wound alike, and the far corners mirror images about the diagonal's
// midpoint with a right angle there. Returns the rectangle's corner and edges (their cross
// product along the first triangle's normal). The tolerance is relative to the edges, far below
// anything a render could show; a quad whose placed corners round beyond it stays two triangles,
// which is always right.
struct RectangleShape {
    glm::vec3 corner, ex, ey;
};
std::optional<RectangleShape> rectangleOf(const Corners& first, const Corners& second) {
    constexpr float kTolerance = 1e-5f;
    int shared = 0, lone1 = -1, lone2 = -1;
    for (int i = 0; i < 3; ++i) {
        bool inSecond = false;
        for (int j = 0; j < 3; ++j) inSecond = inSecond || first.tri[i] == second.tri[j];
        if (inSecond) ++shared;
        else lone1 = i;
    }
    for (int j = 0; j < 3; ++j)
        if (second.tri[j] != first.tri[0] && second.tri[j] != first.tri[1] && second.tri[j] != first.tri[2]) lone2 = j;
    if (shared != 2 || lone1 < 0 || lone2 < 0) return std::nullopt;
    const glm::vec3 u = first.p[lone1], v = second.p[lone2];
    const glm::vec3 x = first.p[(lone1 + 1) % 3], y = first.p[(lone1 + 2) % 3];
    const glm::vec3 ex = x - u, ey = y - u;
    const float width = glm::length(ex), height = glm::length(ey);
    // Relative to the shorter edge and to both, so that a long thin strip is held as tightly.
    if (!(std::min(width, height) > 0.0f) || glm::length(u + v - x - y) > kTolerance * std::min(width, height) ||
        std::abs(glm::dot(ex, ey)) > kTolerance * width * height)
        return std::nullopt;
    const glm::vec3 n1 = glm::cross(first.p[1] - first.p[0], first.p[2] - first.p[0]);
    const glm::vec3 n2 = glm::cross(second.p[1] - second.p[0], second.p[2] - second.p[0]);
    if (!(glm::dot(n1, n2) > 0.0f)) return std::nullopt;
    // (u, x, y) is the first triangle's winding, so ex x ey is along its normal.
    return RectangleShape{u, ex, ey};
}
}  // namespace

void RenderScene::Impl::buildLights() {
    triangleLights.resize(scene->meshes.size());
    for (size_t m = 0; m < scene->meshes.size(); ++m) {
        const Mesh& mesh = scene->meshes[m];
        const SurfaceMaterial& material = (*materials)[mesh.material];
        if (!material.emits()) continue;
        // An instanced emitter's copies are each a light (by instance, then triangle).
        const size_t n = mesh.triangles.size();
        triangleLights[m].assign(copies(mesh) * n, -1);
        for (size_t i = 0; i < copies(mesh); ++i)
            for (size_t t = 0; t < n; ++t) {
                const int instance = mesh.instances ? int(i) : -1;
                if (material.uniformEmission() && t + 1 < n) {
                    // A rectangle of one radiance is one light, sampled whole (spherical_rectangle.h).
                    const std::optional<RectangleShape> r = rectangleOf(cornerPositions(mesh, instance, unsigned(t), 0.0f, 0.0f),
                                                                        cornerPositions(mesh, instance, unsigned(t + 1), 0.0f, 0.0f));
                    if (r) {
                        Light light = Light::rectangle(r->corner, r->ex, r->ey, material.emission(TexCoords{}),
                                                       material.twoSidedEmission());
                        if (light.power() != glm::vec3(0.0f)) {
                            triangleLights[m][i * n + t] = triangleLights[m][i * n + t + 1] = int(lights.size());
                            lights.push_back(std::move(light));
                        }
                        ++t;
                        continue;
                    }
                }
                const Corners c = hitCorners(mesh, instance, unsigned(t), 0.0f, 0.0f);
                const std::array<TexCoords, 3> corners = {interpolateTexCoords(mesh, unsigned(t), 0.0f, 0.0f),
                                                          interpolateTexCoords(mesh, unsigned(t), 1.0f, 0.0f),
                                                          interpolateTexCoords(mesh, unsigned(t), 0.0f, 1.0f)};
                const bool mirrored = c.tri != mesh.triangles[t];
                Light light = Light::triangle(c.p[0], c.p[1], c.p[2], material,
                                              mirrored ? std::array<TexCoords, 3>{corners[0], corners[2], corners[1]} : corners);
                if (!(light.power() != glm::vec3(0.0f))) continue;  // degenerate: never hit, never sampled
                triangleLights[m][i * n + t] = int(lights.size());
                lights.push_back(std::move(light));
            }
    }
    for (const PunctualLight& p : scene->lights) lights.push_back(Light::punctual(p));
    const Environment& env = scene->environment;
    bool envShines = glm::max(env.color.r, glm::max(env.color.g, env.color.b)) > 0.0f;
    if (envShines && env.image)
        envShines = std::any_of(env.image->pixels.begin(), env.image->pixels.end(),
                                [](const glm::vec3& p) { return glm::max(p.r, glm::max(p.g, p.b)) > 0.0f; });
    if (envShines) {
        environment = int(lights.size());
        lights.push_back(Light::environment(env));
    }
    for (Light& light : lights) light.setSceneBounds(bounds);
    // The direct-light pass's lights: the most powerful, each a BSDF evaluation per camera sample;
    // ties go to the lower index, so the choice is the same on every machine.
    std::vector<std::pair<float, int>> byPower;
    for (size_t i = 0; i < lights.size(); ++i)
        if (int(i) != environment) byPower.push_back({-luminance(lights[i].power()), int(i)});
    const size_t kept = std::min(byPower.size(), size_t(kDirectPassLights));
    std::partial_sort(byPower.begin(), byPower.begin() + ptrdiff_t(kept), byPower.end());
    for (size_t i = 0; i < kept; ++i) directPassLights.push_back(byPower[i].second);
    lightSampler.emplace(lights);
    lightTree.emplace(lights);
}

SurfaceHit RenderScene::Impl::makeHit(unsigned meshIndex, int instance, unsigned prim, float u, float v, float t,
                                      const glm::vec3& dir) const {
    const Mesh& mesh = scene->meshes[meshIndex];
    const Corners c = hitCorners(mesh, instance, prim, u, v);
    const glm::uvec3 tri = c.tri;
    const float b1 = c.b1, b2 = c.b2;
    const float b0 = 1.0f - b1 - b2;
    const glm::vec3 &p0 = c.p[0], &p1 = c.p[1], &p2 = c.p[2];

    SurfaceHit hit;
    hit.t = t;
    hit.mesh = int(meshIndex);
    hit.triangle = int(prim);
    hit.instance = instance;
    hit.material = mesh.material;
    hit.p = b0 * p0 + b1 * p1 + b2 * p2;
    const glm::vec3 cr = glm::cross(p1 - p0, p2 - p0);
    const float crLen = glm::length(cr);
    hit.ng = crLen > 0.0f && std::isfinite(crLen) ? cr / crLen : -glm::normalize(dir);
    const glm::vec3 absSum = glm::abs(b0 * p0) + glm::abs(b1 * p1) + glm::abs(b2 * p2);
    // The largest component, not just the one along ng: Embree's own rounding when it meets the
    // triangle again mixes all three.
    hit.pError = kPositionError * std::max({absSum.x, absSum.y, absSum.z});
    const float offset = spawnOffset(hit);
    const glm::vec3 toCentroid = (p0 + p1 + p2) / 3.0f - hit.p;
    const float toCentroidLength = glm::length(toCentroid);
    if (toCentroidLength > offset) hit.towardsCentroid = toCentroid * (offset / toCentroidLength);

    glm::vec3 nFile = hit.ng;  // the file's normal, unflipped: glTF's bitangent is built from it
    if (!mesh.normals.empty()) {
        const glm::vec3 n = b0 * c.n[0] + b1 * c.n[1] + b2 * c.n[2];
        const float len = glm::length(n);
        if (len > 0.0f && std::isfinite(len)) nFile = n / len;
    }
    hit.nsFlipped = glm::dot(nFile, hit.ng) < 0.0f;
    hit.ns = hit.nsFlipped ? -nFile : nFile;
    hit.tex = interpolateTexCoords(mesh, prim, u, v);

    if (mesh.uvs.empty()) {
        // No UVs: tangents from an arbitrary frame around ng.
        const Frame f = Frame::fromNormal(hit.ng);
        hit.dpdu = f.x;
        hit.dpdv = f.y;
    } else {
        const glm::vec2 duv02 = mesh.uvs[tri.x] - mesh.uvs[tri.z], duv12 = mesh.uvs[tri.y] - mesh.uvs[tri.z];
        const glm::vec3 dp02 = p0 - p2, dp12 = p1 - p2;
        const float det = duv02.x * duv12.y - duv02.y * duv12.x;
        // Relative to the UV edges, so a tiny but sound parameterisation still counts.
        if (std::abs(det) > 1e-6f * (glm::dot(duv02, duv02) + glm::dot(duv12, duv12)) && std::isfinite(det)) {
            const float inv = 1.0f / det;
            const glm::vec3 dpdu = (duv12.y * dp02 - duv02.y * dp12) * inv;
            const glm::vec3 dpdv = (duv02.x * dp12 - duv12.x * dp02) * inv;
            if (finite(dpdu) && finite(dpdv)) {
                hit.dpdu = dpdu;
                hit.dpdv = dpdv;
            }
        }
    }
    if (!mesh.tangents.empty()) {
        // Smoothly interpolated tangents keep an anisotropic highlight continuous across
        // triangles; the per-triangle dp/du would facet it.
        const glm::vec4 &t0 = c.t[0], &t1 = c.t[1], &t2 = c.t[2];
        glm::vec3 tangent = b0 * glm::vec3(t0) + b1 * glm::vec3(t1) + b2 * glm::vec3(t2);
        tangent -= glm::dot(tangent, nFile) * nFile;
        const float len = glm::length(tangent);
        if (len > 1e-12f && std::isfinite(len)) {
            tangent /= len;
            const float handedness = t0.w < 0.0f ? -1.0f : 1.0f;
            const glm::vec3 bitangent = handedness * glm::cross(nFile, tangent);
            const float du = glm::length(hit.dpdu), dv = glm::length(hit.dpdv);
            hit.dpdu = tangent * (du > 0.0f ? du : 1.0f);
            hit.dpdv = bitangent * (dv > 0.0f ? dv : 1.0f);
        }
    }
    return hit;
}

RenderScene::RenderScene(std::shared_ptr<const SceneDescription> scene) : impl_(std::make_unique<Impl>()) {
    impl_->scene = std::move(scene);
    validateScene(*impl_->scene);
    impl_->materials.emplace(*impl_->scene);
    impl_->buildGeometry();
    impl_->buildLights();
}

RenderScene::~RenderScene() = default;

namespace {
RTCRay toRtcRay(const glm::vec3& o, const glm::vec3& d, float tMax) {
    RTCRay r;
    r.org_x = o.x;
    r.org_y = o.y;
    r.org_z = o.z;
    r.tnear = 0.0f;
    r.dir_x = d.x;
    r.dir_y = d.y;
    r.dir_z = d.z;
    r.time = 0.0f;
    r.tfar = tMax;
    r.mask = 0xFFFFFFFFu;
    r.id = 0;
    r.flags = 0;
    return r;
}

// The fraction of a segment to drop at its far end so that it cannot reach the target's surface.
float segmentEnd(const glm::vec3& from, const glm::vec3& target) {
    const float length = glm::length(target - from);
    if (!(length > 0.0f)) return 0.0f;  // nothing in between
    return 1.0f - std::max(kShadowEpsilon, kPositionError * maxAbs(target) / length);
}
}  // namespace

std::optional<SurfaceHit> RenderScene::intersect(const Ray& ray, RayKind kind) const {
    CullContext context =
        intersectContext(kind == RayKind::Camera && impl_->culls ? std::optional(Cull::Back) : std::nullopt);
    RTCRayHit rh;
    rh.ray = toRtcRay(ray.o, ray.d, ray.tMax);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->rtcScene, &context.embree, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    if (rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID)
        return impl_->makeHit(rh.hit.geomID, -1, rh.hit.primID, rh.hit.u, rh.hit.v, rh.ray.tfar, ray.d);
    const Impl::InstanceRef& copy = impl_->instanceRefs[rh.hit.instID[0] - impl_->scene->meshes.size()];
    return impl_->makeHit(copy.mesh, int(copy.instance), rh.hit.primID, rh.hit.u, rh.hit.v, rh.ray.tfar, ray.d);
}

namespace {
bool occludedRay(RTCScene scene, const glm::vec3& o, const glm::vec3& d, float tMax,
                 std::optional<Cull> cull = std::nullopt) {
    if (!(tMax > 0.0f)) return false;
    CullContext context = intersectContext(cull);
    RTCRay r = toRtcRay(o, d, tMax);
    rtcOccluded1(scene, &context.embree, &r);
    return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}
}  // namespace

Ray RenderScene::spawnRay(const SurfaceHit& from, const glm::vec3& d) const {
    const float offset = spawnOffset(from);
    Ray ray;
    ray.o = from.p + (glm::dot(d, from.ng) < 0.0f ? -offset : offset) * from.ng;
    ray.o += from.towardsCentroid;
    ray.d = d;
    return ray;
}

bool RenderScene::occluded(const SurfaceHit& from, const glm::vec3& target) const {
    const Ray ray = spawnRay(from, target - from.p);
    return occludedRay(impl_->rtcScene, ray.o, target - ray.o, segmentEnd(ray.o, target));
}

bool RenderScene::occludedToInfinity(const SurfaceHit& from, const glm::vec3& dir) const {
    const Ray ray = spawnRay(from, dir);
    return occludedRay(impl_->rtcScene, ray.o, ray.d, std::numeric_limits<float>::infinity());
}

bool RenderScene::seenFromCamera(const SurfaceHit& from, const glm::vec3& camera) const {
    const std::vector<Material>& materials = impl_->scene->materials;
    const bool singleSided = from.material >= 0 && !materials[size_t(from.material)].doubleSided;
    if (singleSided && glm::dot(from.ng, camera - from.p) < 0.0f) return false;  // the camera sees its back
    const Ray ray = spawnRay(from, camera - from.p);
    return !occludedRay(impl_->rtcScene, ray.o, camera - ray.o, segmentEnd(ray.o, camera),
                        impl_->culls ? std::optional(Cull::Front) : std::nullopt);
}

const SceneMaterials& RenderScene::materials() const { return *impl_->materials; }

int RenderScene::lightIndex(const SurfaceHit& hit) const {
    if (hit.mesh < 0 || hit.mesh >= int(impl_->triangleLights.size())) return -1;
    const std::vector<int>& perTriangle = impl_->triangleLights[hit.mesh];
    if (perTriangle.empty()) return -1;
    const size_t triangles = impl_->scene->meshes[size_t(hit.mesh)].triangles.size();
    return perTriangle[size_t(std::max(hit.instance, 0)) * triangles + size_t(hit.triangle)];
}

glm::vec3 RenderScene::emitted(const SurfaceHit& hit, const glm::vec3& w) const {
    const int light = lightIndex(hit);
    return light >= 0 ? impl_->lights[light].L(hit.ng, w, hit.tex) : materials()[hit.material].unlitRadiance(hit.tex);
}

const std::vector<Light>& RenderScene::lights() const { return impl_->lights; }
const std::vector<int>& RenderScene::directPassLights() const { return impl_->directPassLights; }
int RenderScene::environmentLight() const { return impl_->environment; }

int RenderScene::sampleLight(float u, float* pmf) const {
    if (!impl_->lightSampler) {
        *pmf = 0.0f;
        return -1;
    }
    return impl_->lightSampler->sample(u, pmf);
}

float RenderScene::lightPmf(int index) const { return impl_->lightSampler ? impl_->lightSampler->pmf(index) : 0.0f; }

int RenderScene::sampleLight(const LightSampleContext& ctx, float u, float* pmf) const {
    if (!impl_->lightTree) {
        *pmf = 0.0f;
        return -1;
    }
    return impl_->lightTree->sample(ctx, u, pmf);
}

float RenderScene::lightPmf(const LightSampleContext& ctx, int index) const {
    return impl_->lightTree ? impl_->lightTree->pmf(ctx, index) : 0.0f;
}

RenderScene::GeometryCounts RenderScene::geometryCounts() const {
    GeometryCounts counts;
    for (const Mesh& mesh : impl_->scene->meshes) counts.triangles += mesh.triangles.size();
    counts.instances = impl_->instanceRefs.size();
    return counts;
}

const Bounds& RenderScene::bounds() const { return impl_->bounds; }
const SceneDescription& RenderScene::description() const { return *impl_->scene; }

}  // namespace woven
