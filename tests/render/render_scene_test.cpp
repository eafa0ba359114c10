#include "render_scene.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "math_constants.h"
#include "sampling.h"
#include "scene_loader.h"
#include "test_scenes.h"
#include "woven_material.h"

namespace woven {
namespace {

using test::occludedFrom;
using test::quad;
using test::sceneWith;


float dist(const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b); }

Ray rayDown(float x, float y, float z = 3.0f) {
    Ray ray;
    ray.o = {x, y, z};
    ray.d = {0.0f, 0.0f, -1.0f};
    return ray;
}

// A 2 x 1 quad in the z = 0 plane facing +z, uv over [0, 1]^2: dp/du = (2, 0, 0), dp/dv = (0, 1, 0).
std::shared_ptr<SceneDescription> flatQuadScene() {
    return sceneWith({quad("quad", {0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0})});
}

// The unit right triangle (0,0,0), (1,0,0), (0,1,0): at (x, y) the barycentrics of the second and
// third vertex are x and y.
Mesh unitTriangle() {
    Mesh m;
    m.name = "tri";
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.triangles = {glm::uvec3(0, 1, 2)};
    return m;
}

// ---------------------------------------------------------------------------------------------
// Intersection

TEST(RenderSceneIntersect, KnownQuadGivesDistancePointNormalsUvAndDerivatives) {
    RenderScene scene(flatQuadScene());
    const auto hit = scene.intersect(rayDown(0.5f, 0.1f));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.0f, 1e-6f);
    EXPECT_NEAR(dist(hit->p, {0.5f, 0.1f, 0.0f}), 0.0f, 1e-6f);
    EXPECT_NEAR(dist(hit->ng, {0, 0, 1}), 0.0f, 1e-6f);
    EXPECT_NEAR(dist(hit->ns, {0, 0, 1}), 0.0f, 1e-6f);  // no normals: ns = ng
    EXPECT_NEAR(glm::distance(hit->tex.uv[0], glm::vec2(0.25f, 0.1f)), 0.0f, 1e-6f);
    EXPECT_NEAR(dist(hit->dpdu, {2, 0, 0}), 0.0f, 1e-5f);
    EXPECT_NEAR(dist(hit->dpdv, {0, 1, 0}), 0.0f, 1e-5f);
    EXPECT_EQ(hit->mesh, 0);
    EXPECT_EQ(hit->triangle, 0);  // below the diagonal from (0, 0) to (2, 1)
    EXPECT_EQ(hit->material, -1);
    EXPECT_GT(hit->pError, 0.0f);
    EXPECT_LT(hit->pError, 1e-5f);
}

TEST(RenderSceneIntersect, MissesBesideTheQuadAndPastTMax) {
    RenderScene scene(flatQuadScene());
    EXPECT_FALSE(scene.intersect(rayDown(2.5f, 0.5f, 1.0f)));
    Ray ray = rayDown(1.0f, 0.5f, 1.0f);
    ray.tMax = 0.99f;
    EXPECT_FALSE(scene.intersect(ray));
    ray.tMax = 1.01f;
    EXPECT_TRUE(scene.intersect(ray));
}

TEST(RenderSceneIntersect, ShadingNormalIsInterpolatedAndOnTheGeometricSide) {
    Mesh m = unitTriangle();
    const glm::vec3 n0{0, 0, 1}, n1 = glm::normalize(glm::vec3(1, 0, 1)), n2 = glm::normalize(glm::vec3(0, 1, 2));
    m.normals = {n0, n1, n2};
    Mesh flipped = m;  // the same normals authored against the winding
    flipped.name = "flipped";
    for (glm::vec3& n : flipped.normals) n = -n;
    for (glm::vec3& p : flipped.positions) p.z -= 1.0f;
    RenderScene scene(sceneWith({m, flipped}));
    const glm::vec3 expected = glm::normalize(0.5f * n0 + 0.2f * n1 + 0.3f * n2);
    const auto hit = scene.intersect(rayDown(0.2f, 0.3f));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(dist(hit->ns, expected), 0.0f, 1e-5f);
    Ray below = rayDown(0.2f, 0.3f, -0.5f);
    const auto back = scene.intersect(below);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->mesh, 1);
    EXPECT_NEAR(dist(back->ng, {0, 0, 1}), 0.0f, 1e-6f);
    EXPECT_NEAR(dist(back->ns, expected), 0.0f, 1e-5f);
    // Clockwise winding seen from +z: the front faces -z, and so does ns.
    Mesh cw = unitTriangle();
    std::swap(cw.triangles[0].y, cw.triangles[0].z);
    cw.normals = {n0, n1, n2};
    RenderScene cwScene(sceneWith({cw}));
    const auto cwHit = cwScene.intersect(rayDown(0.2f, 0.3f));
    ASSERT_TRUE(cwHit);
    EXPECT_NEAR(dist(cwHit->ng, {0, 0, -1}), 0.0f, 1e-6f);
    EXPECT_NEAR(dist(cwHit->ns, -expected), 0.0f, 1e-5f);
}

TEST(RenderSceneIntersect, MissingOrDegenerateUvsFallBackAsDocumented) {
    // No UVs: uv 0 and an orthonormal tangent frame around ng.
    RenderScene noUv(sceneWith({unitTriangle()}));
    const auto a = noUv.intersect(rayDown(0.2f, 0.3f));
    ASSERT_TRUE(a);
    EXPECT_EQ(a->tex.uv[0], glm::vec2(0.0f));
    EXPECT_NEAR(glm::length(a->dpdu), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(a->dpdv), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(a->dpdu, a->dpdv), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(a->dpdu, a->ng), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(a->dpdv, a->ng), 0.0f, 1e-6f);
    // All three UVs equal: no parameterisation, zero derivatives.
    Mesh m = unitTriangle();
    m.uvs.assign(3, glm::vec2(0.3f, 0.7f));
    RenderScene degenerate(sceneWith({m}));
    const auto b = degenerate.intersect(rayDown(0.2f, 0.3f));
    ASSERT_TRUE(b);
    EXPECT_NEAR(glm::distance(b->tex.uv[0], glm::vec2(0.3f, 0.7f)), 0.0f, 1e-6f);
    EXPECT_EQ(b->dpdu, glm::vec3(0.0f));
    EXPECT_EQ(b->dpdv, glm::vec3(0.0f));
}

TEST(RenderSceneIntersect, MeshTangentsSetTheDerivativeDirections) {
    Mesh m = unitTriangle();
    m.uvs = {{0, 0}, {1, 0}, {0, 1}};
    m.normals.assign(3, glm::vec3(0, 0, 1));
    // A tangent at 45 degrees to the UV's dp/du, with negative handedness (dp/dv = -(n x t)).
    m.tangents.assign(3, glm::vec4(glm::normalize(glm::vec3(1, 1, 0)), -1.0f));
    RenderScene scene(sceneWith({m}));
    const auto hit = scene.intersect(rayDown(0.2f, 0.3f));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(dist(glm::normalize(hit->dpdu), glm::normalize(glm::vec3(1, 1, 0))), 0.0f, 1e-5f);
    EXPECT_NEAR(dist(glm::normalize(hit->dpdv), glm::normalize(glm::vec3(1, -1, 0))), 0.0f, 1e-5f);
}

// ---------------------------------------------------------------------------------------------
// Validation

void expectSceneError(const std::shared_ptr<SceneDescription>& scene, const std::vector<std::string>& parts) {
    try {
        RenderScene rs(scene);
        ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
        for (const std::string& part : parts)
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << "'" << part << "' not in: " << e.what();
    }
}

TEST(RenderSceneValidation, NonFiniteVertexNamesFileMeshAndVertex) {
    auto scene = flatQuadScene();
    scene->meshes[0].positions[2].y = std::nanf("");
    expectSceneError(scene, {"test.gltf", "'quad'", "vertex 2"});
    scene = flatQuadScene();
    scene->meshes[0].positions[3].x = std::numeric_limits<float>::infinity();
    expectSceneError(scene, {"test.gltf", "'quad'", "vertex 3"});
}

TEST(RenderSceneValidation, IndexOutOfRangeNamesTheMesh) {
    auto scene = flatQuadScene();
    scene->meshes[0].triangles[1].z = 4;
    expectSceneError(scene, {"test.gltf", "'quad'", "triangle 1"});
}

TEST(RenderSceneValidation, BadMaterialsAndEmptyScenes) {
    auto scene = flatQuadScene();
    scene->meshes[0].material = 3;
    expectSceneError(scene, {"'quad'", "material 3"});
    scene = flatQuadScene();
    Material bad;
    bad.name = "cloth";
    bad.woven = WovenParams{};
    bad.woven->yarn_width = -1.0f;
    scene->materials = {bad};
    scene->meshes[0].material = 0;
    expectSceneError(scene, {"test.gltf", "'cloth'"});
    expectSceneError(sceneWith({}), {"test.gltf", "no triangles"});
}

TEST(RenderSceneValidation, DegenerateTrianglesAreHarmless) {
    Mesh m = unitTriangle();
    m.positions.push_back({0.5f, 0.5f, 0.0f});
    m.triangles.push_back(glm::uvec3(0, 3, 3));        // repeated index
    m.triangles.push_back(glm::uvec3(0, 1, 1));        // zero area on an edge
    m.triangles.push_back(glm::uvec3(1, 3, 2));        // collinear: (1,0), (0.5,0.5), (0,1)
    Material glow;
    glow.emission = glm::vec3(1.0f);
    m.material = 0;
    RenderScene scene(sceneWith({m}, {glow}));
    EXPECT_EQ(scene.lights().size(), 1u);  // only the real triangle emits
    const auto hit = scene.intersect(rayDown(0.2f, 0.3f));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->triangle, 0);
    EXPECT_EQ(scene.lightIndex(*hit), 0);
}

// ---------------------------------------------------------------------------------------------
// See-through woven gaps

// One weave element over the unit quad: yarns half as wide as the element, so the four corners
// of the element (|s - 1/2| > 1/4 and |t - 1/2| > 1/4) are covered by neither yarn.
WovenParams gappyWeave() {
    WovenParams p;
    p.yarn_width = 0.5f;
    p.warp_width = 0.5f;
    p.backing = 0;
    return p;
}

std::shared_ptr<SceneDescription> clothOverFloor(const WovenParams& params, bool clothHasUvs = true) {
    Material cloth;
    cloth.name = "cloth";
    cloth.woven = params;
    std::vector<Mesh> meshes = {quad("cloth", {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0),
                                quad("floor", {-1, -1, -1}, {2, -1, -1}, {2, 2, -1}, {-1, 2, -1})};
    if (!clothHasUvs) meshes[0].uvs.clear();
    return sceneWith(meshes, {cloth});
}

// A scene built as an edit of another (the rendered viewport's slider): a material edit keeps the
// BVH, and the scene then answers every ray and renders every pixel as one built whole; anything
// that changes what Embree holds builds it again.
TEST(RenderSceneEdits, AMaterialEditKeepsTheBvhAndRendersAsASceneBuiltWhole) {
    const std::shared_ptr<SceneDescription> before = clothOverFloor(gappyWeave());
    WovenParams wider = gappyWeave();
    wider.yarn_width = wider.warp_width = 0.8f;  // other gaps, still gaps
    std::shared_ptr<SceneDescription> after = clothOverFloor(wider);
    after->environment.color = glm::vec3(1.0f);
    auto edited = std::make_shared<RenderScene>(after, RenderScene(before));
    EXPECT_TRUE(edited->tookGeometry());
    const RenderScene whole(after);
    EXPECT_FALSE(whole.tookGeometry());
    int throughGaps = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            const Ray ray = rayDown((x + 0.5f) / 40.0f, (y + 0.5f) / 40.0f);
            const std::optional<SurfaceHit> a = edited->intersect(ray), b = whole.intersect(ray);
            ASSERT_TRUE(a && b);
            EXPECT_EQ(a->mesh, b->mesh);
            EXPECT_EQ(a->t, b->t);
            throughGaps += a->mesh == 1;
        }
    EXPECT_GT(throughGaps, 0);
    RenderSettings settings;
    settings.width = settings.height = 24;
    settings.spp = 2;
    settings.integrator = "path";
    settings.camera = Camera{glm::inverse(glm::lookAt(glm::vec3(0.5f, 0.5f, 3.0f), glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0, 1, 0))), 0.4f};
    RenderJob job(std::shared_ptr<const RenderScene>(edited), settings);
    std::atomic<bool> cancel{false};
    job.run(cancel);
    EXPECT_TRUE(job.snapshot().radiance.pixels == test::render(after, settings).radiance.pixels);
}

TEST(RenderSceneEdits, AGeometryEditOrAMaterialEditThatChangesWhatEmbreeHoldsBuildsTheBvh) {
    const std::shared_ptr<SceneDescription> before = clothOverFloor(gappyWeave());
    std::shared_ptr<SceneDescription> moved = clothOverFloor(gappyWeave());
    moved->meshes[1].positions[0].z = -1.5f;
    const RenderScene afterMove(moved, RenderScene(before));
    EXPECT_FALSE(afterMove.tookGeometry());
    Ray corner = rayDown(-0.99f, -0.99f);
    ASSERT_TRUE(afterMove.intersect(corner));
    EXPECT_GT(afterMove.intersect(corner)->t, 4.0f);  // the floor's corner moved down
    WovenParams backed = gappyWeave();
    backed.backing = 1;  // no gaps: the cloth's triangles no longer take the pass-through filter
    EXPECT_FALSE(RenderScene(clothOverFloor(backed), RenderScene(before)).tookGeometry());
    std::shared_ptr<SceneDescription> singleSided = clothOverFloor(gappyWeave());
    singleSided->materials[0].doubleSided = false;  // camera rays cull its back
    EXPECT_FALSE(RenderScene(singleSided, RenderScene(before)).tookGeometry());
}

// glTF's doubleSided false: camera rays pass through the back (glTF viewers cull it); bounces
// and shadow rays meet both faces (as Cycles shows them).
TEST(RenderSceneSides, CameraRaysPassTheBackOfSingleSidedSurfacesOnly) {
    Material single;
    single.doubleSided = false;
    const Material both;
    // Facing +z at z = 1: "single" over x in [0, 1], "both" over [2, 3]; a double-sided sky at z = 2.
    RenderScene scene(sceneWith({quad("single", {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, 0),
                                 quad("both", {2, 0, 1}, {3, 0, 1}, {3, 1, 1}, {2, 1, 1}, 1),
                                 quad("sky", {-1, -1, 2}, {4, -1, 2}, {4, 2, 2}, {-1, 2, 2})},
                                {single, both}));
    const Ray up{{0.5f, 0.5f, 0.0f}, {0, 0, 1}};
    EXPECT_EQ(scene.intersect(rayDown(0.5f, 0.5f, 1.5f), RayKind::Camera)->mesh, 0);  // the front
    EXPECT_EQ(scene.intersect(up, RayKind::Camera)->mesh, 2);  // the back is culled: the sky behind
    EXPECT_EQ(scene.intersect(up)->mesh, 0);                   // a bounce meets it
    EXPECT_TRUE(occludedFrom(scene, up.o, {0.5f, 0.5f, 1.5f}));  // and so does a shadow ray
    EXPECT_EQ(scene.intersect(Ray{{2.5f, 0.5f, 0.0f}, {0, 0, 1}}, RayKind::Camera)->mesh, 1);
    EXPECT_EQ(scene.intersect(rayDown(2.5f, 0.5f, 1.5f), RayKind::Camera)->mesh, 1);

    // BDPT's light paths ending on the camera agree with its rays: from below, a camera sees the
    // sky through "single" (not through "both"), and not the back of "single" itself.
    const SurfaceHit skyOverSingle = *scene.intersect(rayDown(0.5f, 0.5f));
    const SurfaceHit skyOverBoth = *scene.intersect(rayDown(2.5f, 0.5f));
    const SurfaceHit onSingle = *scene.intersect(rayDown(0.5f, 0.5f, 1.5f));
    EXPECT_TRUE(scene.seenFromCamera(skyOverSingle, up.o));
    EXPECT_FALSE(scene.seenFromCamera(skyOverBoth, {2.5f, 0.5f, 0.0f}));
    EXPECT_FALSE(scene.seenFromCamera(onSingle, up.o));               // its back
    EXPECT_TRUE(scene.seenFromCamera(onSingle, {0.5f, 0.5f, 1.5f}));  // its front
}

TEST(RenderSceneGaps, RaysAndShadowRaysPassThroughGapsOnly) {
    RenderScene scene(clothOverFloor(gappyWeave()));
    // In a gap: the ray reaches the floor, and so does a shadow ray; from below as well.
    const auto throughGap = scene.intersect(rayDown(0.1f, 0.1f));
    ASSERT_TRUE(throughGap);
    EXPECT_EQ(throughGap->mesh, 1);
    EXPECT_NEAR(throughGap->t, 4.0f, 1e-5f);
    EXPECT_FALSE(occludedFrom(scene, {0.1f, 0.1f, 3.0f}, {0.1f, 0.1f, -0.5f}));
    EXPECT_FALSE(occludedFrom(scene, {0.1f, 0.1f, -0.5f}, {0.1f, 0.1f, 3.0f}));
    EXPECT_FALSE(scene.occluded(*throughGap, {0.1f, 0.1f, 3.0f}));
    // On a yarn (the weft at t = 1/2, the warp at s = 1/2): blocked.
    const auto onYarn = scene.intersect(rayDown(0.5f, 0.1f));
    ASSERT_TRUE(onYarn);
    EXPECT_EQ(onYarn->mesh, 0);
    EXPECT_TRUE(occludedFrom(scene, {0.1f, 0.5f, 3.0f}, {0.1f, 0.5f, -0.5f}));
    // With a backing colour the gaps are solid.
    WovenParams backed = gappyWeave();
    backed.backing = 1;
    RenderScene solid(clothOverFloor(backed));
    EXPECT_EQ(solid.intersect(rayDown(0.1f, 0.1f))->mesh, 0);
    EXPECT_TRUE(occludedFrom(solid, {0.1f, 0.1f, 3.0f}, {0.1f, 0.1f, -0.5f}));
    // Without UVs there is no weave to find gaps in: the documented fallback is solid cloth,
    // shaded everywhere like the middle of a weave element (on a yarn, so it reflects).
    RenderScene noUv(clothOverFloor(gappyWeave(), false));
    const auto solidHit = noUv.intersect(rayDown(0.1f, 0.1f));
    ASSERT_TRUE(solidHit);
    EXPECT_EQ(solidHit->mesh, 0);
    EXPECT_TRUE(noUv.materials().bsdf(*solidHit, {0, 0, 1}));
}

TEST(RenderSceneGaps, IntersectionAndOcclusionAgreeWithTheWeaveEverywhere) {
    WovenParams p = gappyWeave();
    p.repeat = glm::vec2(7.0f, 5.0f);
    p.yarn_width = 0.7f;
    RenderScene scene(clothOverFloor(p));
    const WovenMaterial weave(p);
    Rng rng(30);
    int gaps = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const glm::vec2 xy = rng.uniform2();
        // Slanted rays, so they cross the cloth at (x, y) from above and from below.
        const glm::vec3 onCloth{xy.x, xy.y, 0.0f};
        const glm::vec3 d = glm::normalize(glm::vec3(0.3f, -0.2f, -1.0f));
        const bool fromBelow = i % 2 == 1;
        Ray ray;
        ray.d = fromBelow ? -d : d;
        ray.o = onCloth - 0.5f * ray.d;
        const bool gap = weave.isSeeThrough(glm::dvec2(xy));
        gaps += gap;
        const auto hit = scene.intersect(ray);
        const bool hitCloth = hit && hit->mesh == 0;
        ASSERT_EQ(hitCloth, !gap) << xy.x << ", " << xy.y;
        ASSERT_EQ(occludedFrom(scene, ray.o, onCloth + 0.5f * ray.d), !gap) << xy.x << ", " << xy.y;
    }
    // The gaps' share of the area: (1 - 0.7)(1 - 0.5) = 15 %; binomial, 5 sigma.
    EXPECT_NEAR(gaps, 0.15 * n, 5.0 * std::sqrt(0.15 * 0.85 * n));
}

// ---------------------------------------------------------------------------------------------
// Materials

TEST(RenderSceneBsdf, GltfMaterialIsTheGltfBsdfAroundTheShadingNormalOnTheViewersSide) {
    Material m;
    m.baseColor = glm::vec4(0.6f, 0.3f, 0.2f, 1.0f);
    m.roughness = 0.4f;
    m.metallic = 0.25f;
    GltfBxdfInputs in;
    in.baseColor = glm::vec3(m.baseColor);
    in.roughness = m.roughness;
    in.metallic = m.metallic;
    in.specularF0 = glm::vec3(0.04f);
    const GltfBxdf expectedLobe(in);
    const glm::vec3 n = glm::normalize(glm::vec3(0.2f, -0.1f, 1.0f));
    const glm::vec3 wo = glm::normalize(glm::vec3(0.5f, 0.2f, 1.0f)), wi = glm::normalize(glm::vec3(-0.4f, -0.1f, 1.0f));
    RenderScene scene(sceneWith({unitTriangle()}, {m}));
    SurfaceHit hit;
    hit.ng = glm::vec3(0, 0, 1);
    hit.ns = n;
    hit.material = 0;
    const auto bsdf = scene.materials().bsdf(hit, wo);
    ASSERT_TRUE(bsdf);
    const Frame f = Frame::fromNormal(n);
    const glm::vec3 expected = expectedLobe.eval(f.toLocal(wo), f.toLocal(wi));
    ASSERT_GT(glm::length(expected), 0.0f);
    EXPECT_NEAR(dist(bsdf->eval(wo, wi), expected), 0.0f, 1e-5f * glm::length(expected));
    // Seen from below, the lobe turns over to the back face.
    const auto back = scene.materials().bsdf(hit, -wo);
    ASSERT_TRUE(back);
    EXPECT_NEAR(dist(back->eval(-wo, -wi), expected), 0.0f, 1e-5f * glm::length(expected));
    EXPECT_EQ(back->eval(-wo, wi), glm::vec3(0.0f));
}

TEST(RenderSceneBsdf, WovenMaterialShadesTheSideTheViewerIsOn) {
    WovenParams p;
    p.pattern = glm::ivec3(1, 2, 1);  // twill: the back shows the other yarn on top
    p.repeat = glm::vec2(4.0f);
    RenderScene scene(clothOverFloor(p));
    const WovenMaterial weave(p);
    const auto hit = scene.intersect(rayDown(0.3f, 0.6f));
    ASSERT_TRUE(hit);
    ASSERT_EQ(hit->mesh, 0);
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f)), wi = glm::normalize(glm::vec3(-0.5f, 0.2f, 1.0f));
    for (bool backSide : {false, true}) {
        ShadingInput in;
        in.uv = glm::dvec2(hit->tex.uv[0]);
        in.ns = hit->ns;
        in.dpdu = hit->dpdu;
        in.dpdv = hit->dpdv;
        in.backSide = backSide;
        const auto expected = weave.shade(in);
        ASSERT_TRUE(expected);
        const glm::vec3 o = backSide ? -wo : wo, i = backSide ? -wi : wi;
        const auto bsdf = scene.materials().bsdf(*hit, o);
        ASSERT_TRUE(bsdf);
        EXPECT_EQ(bsdf->eval(o, i), expected->bsdf.eval(o, i));
        EXPECT_GT(glm::length(bsdf->eval(o, i)), 0.0f);
    }
}

// ---------------------------------------------------------------------------------------------
// Emission and light choice

TEST(RenderSceneLights, EmissiveTrianglesPunctualLightsAndEnvironment) {
    Material glow;
    glow.emission = glm::vec3(3.0f);
    glow.doubleSided = false;
    auto desc = sceneWith({quad("lamp", {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}, 0),  // faces -z
                           quad("floor", {-1, -1, 0}, {2, -1, 0}, {2, 2, 0}, {-1, 2, 0})},
                          {glow});
    PunctualLight point;
    point.position = {0.5f, 0.5f, 0.5f};
    point.intensity = glm::vec3(2.0f);
    desc->lights = {point};
    desc->environment.color = glm::vec3(0.1f);
    RenderScene scene(desc);
    ASSERT_EQ(scene.lights().size(), 3u);  // the square lamp is one rectangle
    EXPECT_EQ(scene.environmentLight(), 2);
    EXPECT_TRUE(scene.lights()[0].is<RectangleLight>());
    EXPECT_TRUE(scene.lights()[1].is<PointLight>());
    EXPECT_TRUE(scene.lights()[2].is<EnvironmentLight>());

    Ray up;
    up.o = {0.3f, 0.6f, 0.5f};
    up.d = {0.0f, 0.0f, 1.0f};
    const auto below = scene.intersect(up);
    ASSERT_TRUE(below);
    EXPECT_EQ(below->mesh, 0);
    EXPECT_EQ(scene.lightIndex(*below), 0);
    EXPECT_EQ(scene.emitted(*below, {0, 0, -1}), glm::vec3(3.0f));  // front face, towards -z
    const auto above = scene.intersect(rayDown(0.3f, 0.6f, 2.0f));
    ASSERT_TRUE(above);
    EXPECT_EQ(scene.emitted(*above, {0, 0, 1}), glm::vec3(0.0f));  // one-sided: the back is dark
    const auto floor = scene.intersect(rayDown(1.5f, 1.5f, 2.0f));
    ASSERT_TRUE(floor);
    EXPECT_EQ(scene.lightIndex(*floor), -1);
    EXPECT_EQ(scene.emitted(*floor, {0, 0, 1}), glm::vec3(0.0f));

    // Chosen by power: the lamp pi L A = 3 pi, the point light 4 pi I = 8 pi, the environment
    // 4 pi^2 r^2 L with r the bounding sphere's radius.
    const float r = scene.bounds().radius();
    EXPECT_NEAR(r, 0.5f * std::sqrt(3.0f * 3.0f * 2.0f + 1.0f), 1e-5f);
    const double powers[3] = {3.0 * kPi, 8.0 * kPi, 4.0 * kPi * kPi * r * r * 0.1};
    const double total = powers[0] + powers[1] + powers[2];
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(scene.lightPmf(i), powers[i] / total, 1e-5) << i;
    std::vector<int> counts(3, 0);
    Rng rng(31);
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        float pmf;
        const int l = scene.sampleLight(rng.uniform(), &pmf);
        ASSERT_GE(l, 0);
        ASSERT_LT(l, 3);
        ASSERT_FLOAT_EQ(pmf, scene.lightPmf(l));
        ++counts[l];
    }
    for (int i = 0; i < 3; ++i) {
        const double p = powers[i] / total;
        EXPECT_NEAR(counts[i], n * p, 5.0 * std::sqrt(n * p * (1.0 - p))) << i;  // binomial, 5 sigma
    }
}

TEST(RenderSceneLights, ARectangularLampOfOneRadianceIsOneLightAndOtherQuadsAreTriangles) {
    Material glow;
    glow.emission = glm::vec3(2.0f);
    glow.doubleSided = false;
    Material textured = glow;
    textured.emissiveTexture.image = 0;
    const auto lightsOf = [&](const Mesh& lamp, const Material& material) {
        auto desc = sceneWith({lamp}, {material});
        TextureImage image;
        image.name = "grey";
        image.width = image.height = 1;
        image.bytes = {glm::u8vec4(128, 128, 128, 255)};
        desc->textures = {image};
        RenderScene scene(desc);
        std::vector<int> kinds;  // 0: triangle, 1: rectangle
        for (const Light& light : scene.lights()) kinds.push_back(light.is<RectangleLight>() ? 1 : 0);
        return std::make_pair(kinds, scene.lights().empty() ? 0.0f : scene.lights()[0].power().r);
    };
    // A tilted rectangle: one light, with both triangles' power, facing as they do.
    const glm::vec3 a{0, 0, 1}, b{2, 0, 1.5f}, d{0, 1, 1};
    const auto [rectangle, power] = lightsOf(quad("lamp", a, b, b + d - a, d, 0), glow);
    EXPECT_EQ(rectangle, std::vector<int>{1});
    EXPECT_NEAR(power, 2.0f * glm::length(b - a) * glm::length(d - a) * kPi, 1e-4f);
    RenderScene scene(sceneWith({quad("lamp", a, b, b + d - a, d, 0)}, {glow}));
    const RectangleLight* r = scene.lights()[0].get<RectangleLight>();
    EXPECT_GT(glm::dot(r->n, glm::cross(b - a, d - a)), 0.0f);
    EXPECT_FLOAT_EQ(r->area, glm::length(b - a) * glm::length(d - a));
    Ray up;
    up.o = {0.5f, 0.2f, 0.0f};
    up.d = {0.0f, 0.0f, 1.0f};
    Ray upOtherHalf = up;
    upOtherHalf.o = {0.2f, 0.8f, 0.0f};
    const auto first = scene.intersect(up), second = scene.intersect(upOtherHalf);
    ASSERT_TRUE(first && second);
    EXPECT_NE(first->triangle, second->triangle);
    EXPECT_EQ(scene.lightIndex(*first), 0);
    EXPECT_EQ(scene.lightIndex(*second), 0);

    // A parallelogram that is not a rectangle, a trapezoid, and a textured emission stay two triangles.
    const glm::vec3 shear{0.5f, 0, 0};
    EXPECT_EQ(lightsOf(quad("lamp", a, b, b + d - a + shear, d + shear, 0), glow).first, (std::vector<int>{0, 0}));
    EXPECT_EQ(lightsOf(quad("lamp", a, b, b + d - a + shear, d, 0), glow).first, (std::vector<int>{0, 0}));
    EXPECT_EQ(lightsOf(quad("lamp", a, b, b + d - a, d, 0), textured).first, (std::vector<int>{0, 0}));
    // Two halves wound opposite ways.
    Mesh apart = quad("lamp", a, b, b + d - a, d, 0);
    apart.triangles[1] = glm::uvec3(0, 3, 2);  // the same square, its second half flipped
    EXPECT_EQ(lightsOf(apart, glow).first, (std::vector<int>{0, 0}));
    // Split along the other diagonal, corners listed from another one: still one rectangle.
    Mesh otherDiagonal = quad("lamp", a, b, b + d - a, d, 0);
    otherDiagonal.triangles = {glm::uvec3(1, 3, 0), glm::uvec3(3, 1, 2)};
    EXPECT_EQ(lightsOf(otherDiagonal, glow).first, std::vector<int>{1});
    // A 10 m x 1 mm strip skewed by 0.1 degree: a right angle within 1e-5 of its long edge alone,
    // not of both edges, so it stays two triangles.
    const float skew = 0.1f * kPi / 180.0f;
    const glm::vec3 along{10, 0, 0}, across{0.001f * std::sin(skew), 0.001f * std::cos(skew), 0};
    EXPECT_EQ(lightsOf(quad("lamp", a, a + along, a + along + across, a + across, 0), glow).first, (std::vector<int>{0, 0}));
}

TEST(RenderSceneLights, DoubleSidedEmittersShineBothWaysAndDarkScenesHaveNoLights) {
    Material glow;
    glow.emission = glm::vec3(2.0f);
    glow.doubleSided = true;
    RenderScene lit(sceneWith({quad("lamp", {0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}, 0)}, {glow}));
    const auto top = lit.intersect(rayDown(0.3f, 0.6f, 2.0f));
    ASSERT_TRUE(top);
    EXPECT_EQ(lit.emitted(*top, {0, 0, 1}), glm::vec3(2.0f));
    EXPECT_EQ(lit.emitted(*top, {0, 0, -1}), glm::vec3(2.0f));

    // No emitters, no punctual lights, a black environment: the scene builds, with no light.
    auto dark = flatQuadScene();
    dark->environment.color = glm::vec3(1.0f);
    dark->environment.image = std::make_shared<Image>();
    dark->environment.image->width = 2;
    dark->environment.image->height = 1;
    dark->environment.image->pixels.assign(2, glm::vec3(0.0f));
    RenderScene scene(dark);
    EXPECT_TRUE(scene.lights().empty());
    EXPECT_EQ(scene.environmentLight(), -1);
    float pmf = 1.0f;
    EXPECT_EQ(scene.sampleLight(0.5f, &pmf), -1);
    EXPECT_EQ(pmf, 0.0f);
    EXPECT_EQ(scene.lightPmf(0), 0.0f);
}

// ---------------------------------------------------------------------------------------------
// Robust ray offsets

// A bumpy heightfield z = h(x, y) over [0, 1]^2, n x n quads, moved by `offset`.
Mesh bumpySurface(int n, const glm::vec3& offset) {
    Mesh m;
    m.name = "bumps";
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = float(i) / n, y = float(j) / n;
            const float h = 0.03f * std::sin(37.0f * x) * std::cos(29.0f * y) + 0.01f * std::sin(151.0f * (x + y));
            m.positions.push_back(offset + glm::vec3(x, y, h));
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const unsigned a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            m.triangles.push_back({a, b, d});
            m.triangles.push_back({a, d, c});
        }
    return m;
}

// Rays spawned from a hit, at grazing angles on both sides, must never find their own triangle
// again (a planar triangle cannot be re-entered by a ray leaving it). Near the origin and a
// thousand units away, where float spacing is 2^10 times coarser.
TEST(RenderSceneOffsets, SpawnedRaysNeverRehitTheirOwnTriangle) {
    for (const glm::vec3 offset : {glm::vec3(0.0f), glm::vec3(1000.0f, -700.0f, 500.0f)}) {
        RenderScene scene(sceneWith({bumpySurface(150, offset)}));
        Rng rng(32);
        int othersHit = 0;
        for (int i = 0; i < 20000; ++i) {
            const glm::vec2 xy = rng.uniform2();
            const auto hit = scene.intersect(rayDown(offset.x + xy.x, offset.y + xy.y, offset.z + 1.0f));
            ASSERT_TRUE(hit);
            const Frame f = Frame::fromNormal(hit->ng);
            const float phi = 2.0f * kPi * rng.uniform();
            const float elevation = std::pow(10.0f, -4.0f + 3.0f * rng.uniform());  // 1e-4 to 0.1 rad
            const float side = rng.uniform() < 0.5f ? 1.0f : -1.0f;
            const glm::vec3 d = f.toWorld({std::cos(elevation) * std::cos(phi), std::cos(elevation) * std::sin(phi),
                                           side * std::sin(elevation)});
            const auto again = scene.intersect(scene.spawnRay(*hit, d));
            ASSERT_FALSE(again && again->triangle == hit->triangle) << "offset " << offset.x << " elevation " << elevation;
            othersHit += again.has_value();
        }
        // The bumps are steep enough that many grazing rays run into a neighbouring bump: the
        // test exercises rays that stay close to the surface, not only ones that escape at once.
        EXPECT_GT(othersHit, 5000);  // measured: about 14,000 of 20,000
    }
}

// A flat but finely tessellated floor, tilted so its vertices are not exactly representable on
// the plane, lit by a light at a grazing 0.5 degrees: no point may shadow itself.
TEST(RenderSceneOffsets, GrazingLightOnATessellatedPlaneCastsNoSelfShadow) {
    for (const glm::vec3 offset : {glm::vec3(0.0f), glm::vec3(-1000.0f, 300.0f, 800.0f)}) {
        Mesh m;
        m.name = "floor";
        const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.4f, 0.866f));
        const Frame f = Frame::fromNormal(n);
        const int k = 100;
        for (int j = 0; j <= k; ++j)
            for (int i = 0; i <= k; ++i) m.positions.push_back(offset + f.toWorld({float(i) / k, float(j) / k, 0.0f}));
        for (int j = 0; j < k; ++j)
            for (int i = 0; i < k; ++i) {
                const unsigned a = j * (k + 1) + i;
                m.triangles.push_back({a, a + 1, a + k + 2});
                m.triangles.push_back({a, a + k + 2, a + k + 1});
            }
        RenderScene scene(sceneWith({m}));
        const float elevation = 0.5f * kPi / 180.0f;
        Rng rng(33);
        for (int i = 0; i < 5000; ++i) {
            const glm::vec2 st = rng.uniform2();
            Ray probe;
            probe.o = offset + f.toWorld({st.x, st.y, 1.0f});
            probe.d = -n;
            const auto hit = scene.intersect(probe);
            ASSERT_TRUE(hit);
            const float phi = 2.0f * kPi * rng.uniform();
            const glm::vec3 toLight = f.toWorld({std::cos(elevation) * std::cos(phi), std::cos(elevation) * std::sin(phi), std::sin(elevation)});
            ASSERT_FALSE(scene.occluded(*hit, hit->p + 10.0f * toLight)) << "offset " << offset.x;
            ASSERT_FALSE(scene.occludedToInfinity(*hit, toLight)) << "offset " << offset.x;
        }
    }
}

// A closed box seen from inside, a light just outside it: every shadow ray from the inside walls
// must be blocked, also from hits right at the edges and corners where the walls meet.
TEST(RenderSceneOffsets, ClosedBoxLeaksNoLightFromOutside) {
    for (const glm::vec3 offset : {glm::vec3(0.0f), glm::vec3(500.0f, 500.0f, -500.0f)}) {
        const glm::vec3 lo = offset + glm::vec3(-1.0f), hi = offset + glm::vec3(1.0f);
        RenderScene scene(sceneWith(test::boxInside(lo, hi)));
        const glm::vec3 centre = offset;
        // Lights 1e-3 outside a face, beyond an edge and beyond a corner.
        const glm::vec3 lights[] = {centre + glm::vec3(1.001f, 0.2f, -0.3f), centre + glm::vec3(0.3f, -1.001f, 0.9f),
                                    centre + glm::vec3(1.001f, 1.001f, 0.0f), centre + glm::vec3(-1.001f, 1.001f, -1.001f)};
        Rng rng(34);
        int shadowRays = 0;
        for (int i = 0; i < 20000; ++i) {
            Ray ray;
            ray.o = centre + 0.9f * (2.0f * glm::vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 1.0f);
            // Every fourth ray aims at a random edge or corner point, to land within rounding of it.
            if (i % 4 == 0) {
                glm::vec3 target = centre + 2.0f * glm::vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 1.0f;
                const int axis = i / 4 % 3;
                target[axis] = centre[axis] + (rng.uniform() < 0.5f ? -1.0f : 1.0f);
                target[(axis + 1) % 3] = centre[(axis + 1) % 3] + (rng.uniform() < 0.5f ? -1.0f : 1.0f);
                ray.d = glm::normalize(target - ray.o);
            } else {
                ray.d = sampleUniformSphere(rng.uniform2());
            }
            const auto hit = scene.intersect(ray);
            ASSERT_TRUE(hit) << "a ray escaped the closed box";
            ASSERT_GT(glm::dot(hit->ng, centre - hit->p), 0.0f);  // the walls face inwards
            // Only connections on the side the wall is seen from can carry light: a reflecting
            // surface gives nothing to a direction behind it (sameGeometricSide), so a shadow
            // ray that starts a hair behind the wall near an edge there is never traced.
            for (const glm::vec3& light : lights) {
                if (glm::dot(light - hit->p, hit->ng) <= 0.0f) continue;
                ASSERT_TRUE(scene.occluded(*hit, light)) << "offset " << offset.x;
                ++shadowRays;
            }
            const glm::vec3 d = sampleUniformSphere(rng.uniform2());
            ASSERT_TRUE(scene.occludedToInfinity(*hit, glm::dot(d, hit->ng) > 0.0f ? d : -d)) << "offset " << offset.x;
            // A bounce leaving the wall inwards stays inside.
            const glm::vec3 inwards = hit->ng + sampleUniformSphere(rng.uniform2()) * 0.999f;
            ASSERT_TRUE(scene.intersect(scene.spawnRay(*hit, glm::normalize(inwards))));
        }
        EXPECT_GT(shadowRays, 20000);  // most hits see most of the lights
    }
}

}  // namespace
}  // namespace woven
