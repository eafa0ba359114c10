// EXT_mesh_gpu_instancing as Embree instances: each copy is hit as itself, shades as the same mesh
// expanded into the world would, a million copies hold one mesh's triangles, and a file renders
// as its twin whose copies are separate nodes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <filesystem>

#include "../scene/gltf_builder.h"
#include "../scene/temp_dir.h"
#include "render_scene.h"
#include "scene_loader.h"
#include "uv_scale.h"
#include "test_scenes.h"

namespace woven {
namespace {

using test::quad;
using test::render;
using test::sceneWith;
using test::TempDir;

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance, const std::string& what) {
    EXPECT_LT(glm::length(a - b), tolerance) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ") against ("
                                             << b.x << ", " << b.y << ", " << b.z << ")";
}

// A unit quad in the xy plane facing +z, with normals and tangents as a file gives them.
Mesh unitQuad(int material = -1) {
    Mesh m = quad("quad", {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, material);
    m.normals.assign(4, glm::vec3(0, 0, 1));
    m.tangents.assign(4, glm::vec4(1, 0, 0, 1));
    return m;
}

// Nine placements on a 3 x 3 grid 2 m apart: plain, turned about z, scaled unevenly, and three
// mirrored ones (in x, which keeps the front; in z, which turns it to -z; in x and y, a turn).
std::vector<glm::mat4> ninePlacements() {
    std::vector<glm::mat4> m;
    for (int i = 0; i < 9; ++i) {
        const glm::vec3 at(2.0f * float(i % 3), 2.0f * float(i / 3), 0.0f);
        glm::mat4 own(1.0f);
        if (i == 1) own = glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0, 0, 1));
        if (i == 2) own = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 1.5f, 1.0f));
        if (i == 3) own = glm::translate(glm::mat4(1.0f), glm::vec3(1, 0, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1));
        if (i == 4) own = glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, -1));
        if (i == 5) own = glm::scale(glm::mat4(1.0f), glm::vec3(-1, -1, 1)) * glm::translate(glm::mat4(1.0f), glm::vec3(-1, -1, 0));
        m.push_back(glm::translate(glm::mat4(1.0f), at) * own);
    }
    return m;
}

// The copy as the loader expanded it before instancing (gltf_loader.cpp's addPrimitive): world
// positions, normals by the inverse transpose, the winding swapped under a mirroring matrix.
Mesh expanded(const Mesh& mesh, const glm::mat4& m) {
    Mesh out = mesh;
    out.instances = nullptr;
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
    const bool mirrored = glm::determinant(glm::mat3(m)) < 0.0f;
    for (size_t v = 0; v < out.positions.size(); ++v) {
        out.positions[v] = glm::vec3(m * glm::vec4(mesh.positions[v], 1.0f));
        const glm::vec3 n = normalMatrix * mesh.normals[v];
        out.normals[v] = n / glm::length(n);
        out.tangents[v] = glm::vec4(glm::normalize(glm::mat3(m) * glm::vec3(mesh.tangents[v])), mirrored ? -1.0f : 1.0f);
    }
    if (mirrored)
        for (glm::uvec3& t : out.triangles) std::swap(t.y, t.z);
    return out;
}

// Each of the nine copies is hit as itself (its instance, the one mesh), with the point, normals,
// tangents and uv the expanded copy gives, to float rounding: Embree meets the copy in the mesh's
// own space and the hit is placed by the same matrix the expansion applied.
TEST(Instancing, NineCopiesAreHitAsThemselvesAndShadeAsTheirExpansion) {
    Mesh mesh = unitQuad();
    mesh.instances = std::make_shared<const std::vector<glm::mat4>>(ninePlacements());
    RenderScene instanced(sceneWith({mesh}));
    EXPECT_EQ(instanced.geometryCounts().triangles, 2u);
    EXPECT_EQ(instanced.geometryCounts().instances, 9u);
    for (int i = 0; i < 9; ++i) {
        const glm::mat4& m = (*mesh.instances)[size_t(i)];
        RenderScene single(sceneWith({expanded(mesh, m)}));
        const glm::vec3 target(m * glm::vec4(0.3f, 0.6f, 0.0f, 1.0f));
        Ray ray;
        ray.o = target + glm::vec3(0.01f, 0.02f, 5.0f);
        ray.d = target - ray.o;
        const auto a = instanced.intersect(ray), b = single.intersect(ray);
        ASSERT_TRUE(a && b) << "copy " << i;
        EXPECT_EQ(a->mesh, 0);
        EXPECT_EQ(a->instance, i);
        EXPECT_EQ(b->instance, -1);
        const std::string copy = "copy " + std::to_string(i);
        EXPECT_NEAR(a->t, b->t, 1e-5f) << copy;
        expectNear(a->p, target, 1e-5f, copy + " p");
        expectNear(a->ng, b->ng, 1e-5f, copy + " ng");
        expectNear(a->ns, b->ns, 1e-5f, copy + " ns");
        EXPECT_EQ(a->nsFlipped, b->nsFlipped) << copy;
        expectNear(a->dpdu, b->dpdu, 1e-5f, copy + " dpdu");
        expectNear(a->dpdv, b->dpdv, 1e-5f, copy + " dpdv");
        EXPECT_NEAR(glm::length(a->tex.uv[0] - glm::vec2(0.3f, 0.6f)), 0.0f, 1e-5f) << copy;
        EXPECT_NEAR(a->pError, b->pError, 1e-6f) << copy;
        // Copy 4 is mirrored in z: its front, by the glTF rule for mirroring transforms, faces -z.
        EXPECT_NEAR(a->ng.z, i == 4 ? -1.0f : 1.0f, 1e-6f) << copy;
        const Ray bounce = instanced.spawnRay(*a, glm::vec3(0, 0, 1));
        EXPECT_FALSE(instanced.intersect(bounce)) << copy << ": the bounce met its own copy";
    }
    // Between the copies there is nothing.
    Ray gap;
    gap.o = glm::vec3(1.5f, 1.5f, 5.0f);
    gap.d = glm::vec3(0, 0, -1);
    EXPECT_FALSE(instanced.intersect(gap));
}

// A single-sided copy culls its back for camera rays in the mesh's own space, where Embree's
// filter sees the ray: mirrored or not, the face the glTF rule calls front is the one seen.
TEST(Instancing, SingleSidedCopiesShowTheirFrontOnly) {
    Material m;
    m.doubleSided = false;
    Mesh mesh = unitQuad(0);
    mesh.instances = std::make_shared<const std::vector<glm::mat4>>(ninePlacements());
    RenderScene scene(sceneWith({mesh}, {m}));
    for (int i = 0; i < 9; ++i) {
        const glm::vec3 target((*mesh.instances)[size_t(i)] * glm::vec4(0.5f, 0.5f, 0.0f, 1.0f));
        for (float side : {1.0f, -1.0f}) {
            Ray ray;
            ray.o = target + glm::vec3(0, 0, 5.0f * side);
            ray.d = glm::vec3(0, 0, -side);
            const bool front = side * (i == 4 ? -1.0f : 1.0f) > 0.0f;
            EXPECT_EQ(bool(scene.intersect(ray, RayKind::Camera)), front) << "copy " << i << " from " << side;
            EXPECT_TRUE(scene.intersect(ray, RayKind::Scattered)) << "copy " << i << " from " << side;
        }
    }
}

// An instanced emitter is a light per copy and triangle, each found again from its hit.
TEST(Instancing, EachCopyOfAnEmitterIsItsOwnLight) {
    Material glow;
    glow.emission = glm::vec3(2.0f);
    glow.doubleSided = false;  // so that each copy's light must face as its triangles do
    Mesh mesh = unitQuad(0);
    mesh.instances = std::make_shared<const std::vector<glm::mat4>>(ninePlacements());
    RenderScene scene(sceneWith({mesh}, {glow}));
    // Each copy of the square stays a rectangle (turned, scaled, mirrored), one light each.
    ASSERT_EQ(scene.lights().size(), 9u);
    std::vector<bool> found(9, false);
    for (int i = 0; i < 9; ++i) {
        int copysLight = -1;  // both halves of a copy are the one light
        for (const glm::vec2 at : {glm::vec2(0.7f, 0.2f), glm::vec2(0.2f, 0.7f)}) {
            const glm::vec3 target((*mesh.instances)[size_t(i)] * glm::vec4(at, 0.0f, 1.0f));
            Ray ray;
            ray.o = target + glm::vec3(0, 0, i == 4 ? -5.0f : 5.0f);
            ray.d = target - ray.o;
            const auto hit = scene.intersect(ray);
            ASSERT_TRUE(hit);
            const int light = scene.lightIndex(*hit);
            ASSERT_GE(light, 0);
            EXPECT_TRUE(scene.lights()[size_t(light)].is<RectangleLight>());
            if (copysLight >= 0) {
                EXPECT_EQ(light, copysLight) << "copy " << i;
            }
            copysLight = light;
            found[size_t(light)] = true;
            EXPECT_NEAR(glm::length(scene.emitted(*hit, -ray.d) - glm::vec3(2.0f)), 0.0f, 1e-6f);
            // Its sampling shines on the side the copy's triangles face (the ray's) only.
            const Light& lamp = scene.lights()[size_t(light)];
            const auto lit = lamp.sampleLi(ray.o, {0.3f, 0.6f});
            ASSERT_TRUE(lit) << "copy " << i;
            EXPECT_EQ(lit->L, glm::vec3(2.0f)) << "copy " << i;
            EXPECT_FALSE(lamp.sampleLi(2.0f * target - ray.o, {0.3f, 0.6f})) << "copy " << i << ", from behind";
        }
    }
    for (size_t l = 0; l < found.size(); ++l) EXPECT_TRUE(found[l]) << "light " << l << " is no copy's";
}

// Thread counts measure an instanced mesh's UVs where its copies are placed: copies scaled 3 times
// take 3 times the metres per UV unit of the mesh's own space.
TEST(Instancing, ThreadCountsMeasureTheCopiesAsPlaced) {
    Mesh mesh = unitQuad();
    auto scene = sceneWith({mesh});
    EXPECT_NEAR(worldLengthPerUv(*scene, {0}).x, 1.0, 1e-9);
    scene->meshes[0].instances = std::make_shared<const std::vector<glm::mat4>>(std::vector<glm::mat4>{
        glm::scale(glm::mat4(1.0f), glm::vec3(3.0f)),
        glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0)) * glm::rotate(glm::mat4(1.0f), 1.0f, glm::vec3(0, 0, 1)) *
            glm::scale(glm::mat4(1.0f), glm::vec3(3.0f))});
    const glm::dvec2 metres = worldLengthPerUv(*scene, {0});
    EXPECT_NEAR(metres.x, 3.0, 1e-6);
    EXPECT_NEAR(metres.y, 3.0, 1e-6);
}

// A grey ground, a row of boxes and a point light, as one glTF file with the boxes instanced and
// as its twin with a node per box: the two render the same frame.
void writeShelf(const std::string& path, bool instanced) {
    test::GltfBuilder b;
    const std::vector<glm::vec3> cube = {{-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, -0.5f}, {-0.5f, 0.5f, -0.5f},
                                         {-0.5f, -0.5f, 0.5f},  {0.5f, -0.5f, 0.5f},  {0.5f, 0.5f, 0.5f},  {-0.5f, 0.5f, 0.5f}};
    const std::vector<uint32_t> faces = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                         3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5};
    const int red = b.addMaterial({{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.2, 0.1, 1}}, {"roughnessFactor", 0.4}}}});
    const int box = b.addMesh({{"attributes", {{"POSITION", b.addPositions(cube)}}}, {"indices", b.addIndices(faces)}, {"material", red}}, "Box");
    const int ground = b.addMesh({{"attributes", {{"POSITION", b.addPositions({{-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4}})}}},
                                  {"indices", b.addIndices({0, 2, 1, 0, 3, 2})}}, "Ground");
    std::vector<glm::vec3> t, s;
    std::vector<glm::vec4> r;
    for (int i = 0; i < 5; ++i) {
        t.emplace_back(-2.0f + float(i), 0.3f + 0.1f * float(i), 0.2f * float(i % 2));
        const glm::quat q = glm::angleAxis(0.3f * float(i), glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f)));
        r.emplace_back(q.x, q.y, q.z, q.w);
        s.emplace_back(0.6f, 0.4f + 0.1f * float(i), 0.6f);
    }
    std::vector<int> roots = {b.addNode({{"mesh", ground}})};
    if (instanced) {
        b.useExtension("EXT_mesh_gpu_instancing", true);
        roots.push_back(b.addNode({{"mesh", box}, {"translation", {0, 0.1, 0}},
                                   {"extensions", {{"EXT_mesh_gpu_instancing",
                                                    {{"attributes", {{"TRANSLATION", b.addVec3(t)}, {"ROTATION", b.addVec4(r)},
                                                                     {"SCALE", b.addVec3(s)}}}}}}}}));
    } else {
        std::vector<int> copies;
        for (int i = 0; i < 5; ++i)
            copies.push_back(b.addNode({{"mesh", box}, {"translation", {t[i].x, t[i].y, t[i].z}},
                                        {"rotation", {r[i].x, r[i].y, r[i].z, r[i].w}}, {"scale", {s[i].x, s[i].y, s[i].z}}}));
        roots.push_back(b.addNode({{"translation", {0, 0.1, 0}}, {"children", copies}}));
    }
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 4000.0}}};
    b.useExtension("KHR_lights_punctual");
    roots.push_back(b.addNode({{"translation", {1, 3, 2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));
    b.json()["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.01}}}}};
    roots.push_back(b.addNode({{"camera", 0}, {"translation", {0, 2, 5}}, {"rotation", {-0.2588, 0, 0, 0.9659}}}));
    b.setScene(roots);
    b.writeGltf(path);
}

// The copies' vertices land where the twin's do bit for bit (the same matrix product, world x
// TRS, in the same float operations), but Embree meets them in the mesh's own space: t, the
// barycentrics and so the hit points differ in the last bits, and a path whose bounce, shadow
// ray or Russian roulette sits on a threshold may take another turn. So the frames agree to float
// noise, not exactly: each pixel within 1e-3 of the pair's brightest pixel over most of the frame,
// the mean within 0.2 % (a frame's noise at 16 spp is about 5 %: a difference in the geometry
// itself, a copy misplaced or shaded from the wrong normal, moves the mean by far more).
TEST(Instancing, AFileRendersAsItsTwinWithANodePerCopy) {
    TempDir dir;
    writeShelf(dir.file("instanced.gltf"), true);
    writeShelf(dir.file("nodes.gltf"), false);
    auto instanced = std::make_shared<SceneDescription>(loadScene(dir.file("instanced.gltf")));
    auto nodes = std::make_shared<SceneDescription>(loadScene(dir.file("nodes.gltf")));
    ASSERT_EQ(instanced->meshes.size(), 2u);
    ASSERT_EQ(nodes->meshes.size(), 6u);
    RenderSettings s;
    s.width = 48;
    s.height = 32;
    s.spp = 16;
    s.integrator = "path";
    s.seed = 3;
    const FilmImage a = render(instanced, s), b = render(nodes, s);
    double meanA = 0.0, meanB = 0.0, brightest = 0.0;
    for (size_t i = 0; i < a.radiance.pixels.size(); ++i) {
        meanA += luminance(a.radiance.pixels[i]);
        meanB += luminance(b.radiance.pixels[i]);
        brightest = std::max({brightest, double(luminance(a.radiance.pixels[i])), double(luminance(b.radiance.pixels[i]))});
    }
    ASSERT_GT(meanB, 0.0);
    EXPECT_NEAR(meanA / meanB, 1.0, 2e-3);
    size_t close = 0;
    for (size_t i = 0; i < a.radiance.pixels.size(); ++i)
        close += std::abs(luminance(a.radiance.pixels[i]) - luminance(b.radiance.pixels[i])) < 1e-3 * brightest;
    EXPECT_GT(double(close), 0.9 * double(a.radiance.pixels.size()));
}

// A million copies of a box through the loader: the scene holds one box's 12 triangles and a
// million instances (what its memory follows: about 400 bytes an Embree instance, where the 12
// million triangles expanded would take about 1.5 GB with their BVH), and a frame of camera rays
// from above sees the grid: 1 m boxes 2 m apart cover a quarter of the ground.
TEST(Instancing, AMillionCopiesHoldOneMeshAndShowTheirGrid) {
    constexpr size_t kCopies = 1000000;
    test::GltfBuilder b;
    const std::vector<glm::vec3> cube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    const int box = b.addMesh({{"attributes", {{"POSITION", b.addPositions(cube)}}},
                               {"indices", b.addIndices({0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                                         3, 7, 6, 3, 6, 2, 0, 4, 7, 0, 7, 3, 1, 2, 6, 1, 6, 5})}});
    std::vector<glm::vec3> t(kCopies);
    for (size_t i = 0; i < kCopies; ++i) t[i] = glm::vec3(float(i % 1000) * 2.0f, 0.0f, -float(i / 1000) * 2.0f);
    b.useExtension("EXT_mesh_gpu_instancing", true);
    const int forest = b.addNode({{"mesh", box}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", b.addVec3(t)}}}}}}}});
    b.setScene({forest});
    TempDir dir;
    b.writeGlb(dir.file("forest.glb"));
    auto scene = std::make_shared<SceneDescription>(loadScene(dir.file("forest.glb")));
    ASSERT_EQ(scene->meshes.size(), 1u);
    ASSERT_EQ(scene->meshes[0].instances->size(), kCopies);
    const RenderScene rs(scene);
    EXPECT_EQ(rs.geometryCounts().triangles, 12u);
    EXPECT_EQ(rs.geometryCounts().instances, kCopies);
    // The far corner's copy is where its translation puts it.
    Ray ray;
    ray.o = glm::vec3(1998.5f, 10.0f, -1997.5f);
    ray.d = glm::vec3(0, -1, 0);
    const auto hit = rs.intersect(ray);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instance, int(kCopies - 1));
    EXPECT_NEAR(hit->p.y, 1.0f, 1e-4f);
    // Straight down over 20 x 20 m in the middle of the forest, one ray per 10 cm, each through
    // the middle of its cell: 100 boxes' tops of 100 rays each.
    size_t hits = 0, rays = 0;
    for (int x = 0; x < 200; ++x)
        for (int z = 0; z < 200; ++z, ++rays) {
            ray.o = glm::vec3(1000.0f + 0.1f * (float(x) + 0.5f), 10.0f, -1000.0f - 0.1f * (float(z) + 0.5f));
            hits += bool(rs.intersect(ray, RayKind::Camera));
        }
    EXPECT_EQ(hits, rays / 4);
}

}  // namespace
}  // namespace woven
