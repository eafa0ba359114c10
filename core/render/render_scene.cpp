#include "render_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <utility>

#include "frame.h"
#include "mesh_instances.h"
#include "render_scene_impl.h"
#include "sampling.h"
#include "scene_loader.h"
#include "scene_validation.h"
#include "triangle_corners.h"

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

void embreeError(void* userPtr, RTCError code, const char* message) {
    auto* out = static_cast<std::string*>(userPtr);
    if (out->empty()) *out = message ? message : "unknown error";
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

bool RenderScene::Impl::sameGeometry(const SceneDescription& next, const SceneMaterials& nextMaterials) const {
    if (!rtcScene || next.meshes.size() != scene->meshes.size()) return false;
    for (size_t m = 0; m < next.meshes.size(); ++m) {
        const Mesh &was = scene->meshes[m], &is = next.meshes[m];
        const bool sameInstances =
            was.instances == is.instances || (was.instances && is.instances && *was.instances == *is.instances);
        if (!sameInstances || was.positions != is.positions || was.triangles != is.triangles ||
            singleSided(was) != singleSided(next, is) ||
            (*materials)[was.material].mayPassThrough(was) != nextMaterials[is.material].mayPassThrough(is))
            return false;
    }
    return true;
}

void RenderScene::Impl::takeGeometry(Impl& from) {
    device = std::exchange(from.device, nullptr);
    rtcScene = std::exchange(from.rtcScene, nullptr);
    rtcSetDeviceErrorFunction(device, embreeError, &embreeMessage);
    hitFilters = std::move(from.hitFilters);  // the same elements, whose addresses Embree holds
    instanceRefs = std::move(from.instanceRefs);
    culls = from.culls;
    sceneFlags = from.sceneFlags;
    bounds = from.bounds;
    for (size_t m = 0; m < scene->meshes.size(); ++m) {
        const Mesh& mesh = scene->meshes[m];
        const SurfaceMaterial& material = (*materials)[mesh.material];
        hitFilters[m] = HitFilter{&mesh, &material, material.passesRandomly(), singleSided(mesh)};
    }
    tookGeometry = true;
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

RenderScene::RenderScene(std::shared_ptr<const SceneDescription> scene, RenderScene&& previous)
    : impl_(std::make_unique<Impl>()) {
    impl_->scene = std::move(scene);
    validateScene(*impl_->scene);
    impl_->materials.emplace(*impl_->scene);
    if (previous.impl_ && previous.impl_->sameGeometry(*impl_->scene, *impl_->materials)) {
        impl_->takeGeometry(*previous.impl_);
        previous.impl_.reset();
    } else {
        previous.impl_.reset();  // first: two BVHs need not fit in memory together
        impl_->buildGeometry();
    }
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
bool RenderScene::tookGeometry() const { return impl_->tookGeometry; }
const SceneDescription& RenderScene::description() const { return *impl_->scene; }

}  // namespace woven
