// The glTF writer read back by woven's own loader: a scene with every material extension woven
// renders, textures with their samplers and transforms, vertex attributes, a node hierarchy,
// punctual lights and a camera comes back as it was written, from a .glb and from a .gltf.
#include <gtest/gtest.h>

#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "gltf_loader.h"
#include "gltf_writer.h"
#include "scene_camera.h"
#include "scene_loader.h"
#include "temp_dir.h"

namespace woven {
namespace {

using test::TempDir;

TextureImage texture(const std::string& name, int seed) {
    TextureImage t;
    t.name = name;
    t.width = 4;
    t.height = 3;
    for (int i = 0; i < 12; ++i) t.bytes.emplace_back(17 * i + seed, 255 - 9 * i, 40 + seed, 255 - 20 * (i % 2));
    return t;
}

SceneDescription richScene() {
    SceneDescription s;
    s.source = "rich";
    Mesh a;
    a.name = "Child/Box/0";
    a.meshName = "Box";
    a.nodePath = {"Root", "Child"};
    a.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    a.normals.assign(4, glm::vec3(0, 0, 1));
    a.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    a.uvs1 = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
    a.colors = {{1, 0, 0, 1}, {0, 1, 0, 0.5f}, {0, 0, 1, 1}, {1, 1, 1, 1}};
    a.tangents.assign(4, glm::vec4(1, 0, 0, -1));
    a.triangles = {{0, 1, 2}, {0, 2, 3}};
    a.material = 0;
    Mesh b = a;
    b.name = "Other/Plane/0";
    b.meshName = "Plane";
    b.nodePath = {"Other"};
    b.uvs1.clear();
    b.colors.clear();
    b.material = -1;  // woven's default material
    for (glm::vec3& p : b.positions) p += glm::vec3(0, 0, -2);
    Mesh c = a;
    c.name = "Root/Lamp/0";
    c.meshName = "Lamp";
    c.nodePath = {"Root"};
    c.material = 1;
    // Copies placed by EXT_mesh_gpu_instancing: moved, turned and scaled, and one mirrored.
    Mesh d = b;
    d.name = "Shelf/Crate/0";
    d.meshName = "Crate";
    d.nodePath = {"Shelf"};
    d.instances = std::make_shared<const std::vector<glm::mat4>>(std::vector<glm::mat4>{
        glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)),
        glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 0.5f))) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 2, 1)),
        glm::translate(glm::mat4(1.0f), glm::vec3(-3, 0, 1)) * glm::scale(glm::mat4(1.0f), glm::vec3(1, -1, 1))});
    s.meshes = {a, b, c, d};

    Material m;
    m.name = "Rich";
    m.baseColor = {0.9f, 0.8f, 0.7f, 0.6f};
    m.baseColorTexture.image = 0;
    m.baseColorTexture.srgb = true;
    m.baseColorTexture.uvTransform = glm::mat3(0.5f, -0.2f, 0, 0.2f, 0.5f, 0, 0.1f, 0.3f, 1);  // scale, rotation, offset
    m.baseColorTexture.wrapS = TextureWrap::MirroredRepeat;
    m.baseColorTexture.wrapT = TextureWrap::ClampToEdge;
    m.metallic = 0.3f;
    m.roughness = 0.6f;
    m.metallicRoughnessTexture.image = 1;
    m.metallicRoughnessTexture.texCoord = 1;
    m.metallicRoughnessTexture.nearest = true;
    m.metallicRoughnessTexture.mipmaps = false;
    m.normalTexture.image = 1;
    m.normalTexture.scale = 0.7f;
    m.occlusionTexture.image = 2;
    m.occlusionTexture.scale = 0.4f;
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.3f;
    m.doubleSided = true;
    m.ior = 1.7f;
    m.specular = 0.8f;
    m.specularColor = {1.0f, 0.9f, 0.8f};
    m.sheen.color = {0.3f, 0.2f, 0.1f};
    m.sheen.roughness = 0.4f;
    m.anisotropy.strength = 0.6f;
    m.anisotropy.rotation = 0.5f;
    m.anisotropy.texture.image = 2;
    m.clearcoat.factor = 0.5f;
    m.clearcoat.roughness = 0.2f;
    m.transmission.factor = 0.25f;
    m.transmission.thickness = 0.1f;
    m.transmission.attenuationDistance = 2.0f;
    m.transmission.attenuationColor = {0.9f, 0.8f, 0.7f};
    m.iridescence.factor = 0.8f;
    m.iridescence.ior = 1.4f;
    m.iridescence.thicknessMin = 150.0f;
    m.iridescence.thicknessMax = 350.0f;
    m.iridescence.thicknessTexture.image = 1;
    Material lamp;
    lamp.name = "Lamp";
    lamp.emission = {6.0f, 3.0f, 1.5f};  // above 1: the strength extension
    lamp.emissiveTexture.image = 0;
    lamp.emissiveTexture.srgb = true;
    lamp.doubleSided = false;
    s.materials = {m, lamp};
    s.textures = {texture("a", 1), texture("b", 2), texture("c", 3)};

    PunctualLight point;
    point.position = {1, 2, 3};
    point.intensity = {2.0f, 1.0f, 0.5f};
    PunctualLight spot;
    spot.type = PunctualLight::Type::Spot;
    spot.position = {-1, 3, 0};
    spot.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    spot.intensity = glm::vec3(5.0f);
    spot.innerConeAngle = 0.2f;
    spot.outerConeAngle = 0.6f;
    PunctualLight sun;
    sun.type = PunctualLight::Type::Directional;
    sun.direction = glm::vec3(0.0f, 0.0f, 1.0f);  // along +z: the opposite of the node's -z
    sun.intensity = glm::vec3(0.7f);
    s.lights = {point, spot, sun};
    return s;
}

void expectTextureRef(const TextureRef& got, const TextureRef& want, const char* what) {
    SCOPED_TRACE(what);
    EXPECT_EQ(bool(got), bool(want));
    EXPECT_EQ(got.texCoord, want.texCoord);
    EXPECT_EQ(got.srgb, want.srgb);
    EXPECT_EQ(got.wrapS, want.wrapS);
    EXPECT_EQ(got.wrapT, want.wrapT);
    EXPECT_EQ(got.nearest, want.nearest);
    EXPECT_EQ(got.mipmaps, want.mipmaps);
    EXPECT_NEAR(got.scale, want.scale, 1e-6f);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(got.uvTransform[i][j], want.uvTransform[i][j], 1e-6f) << i << "," << j;
}

void expectSameScene(const SceneDescription& got, const SceneDescription& want, const Camera& camera) {
    // The loader walks the nodes depth first: the meshes come back in that order.
    ASSERT_EQ(got.meshes.size(), want.meshes.size());
    const auto mesh = [&](const std::string& name) -> const Mesh& {
        for (const Mesh& m : got.meshes)
            if (m.meshName == name) return m;
        throw std::runtime_error("no mesh " + name);
    };
    for (const Mesh& w : want.meshes) {
        const Mesh& g = mesh(w.meshName);
        SCOPED_TRACE(w.name);
        EXPECT_EQ(g.meshName, w.meshName);
        EXPECT_EQ(g.nodePath, w.nodePath);
        EXPECT_EQ(g.positions, w.positions);
        EXPECT_EQ(g.normals, w.normals);
        EXPECT_EQ(g.uvs, w.uvs);
        EXPECT_EQ(g.uvs1, w.uvs1);
        EXPECT_EQ(g.colors, w.colors);
        EXPECT_EQ(g.triangles, w.triangles);
        ASSERT_EQ(bool(g.instances), bool(w.instances));
        if (w.instances) {
            ASSERT_EQ(g.instances->size(), w.instances->size());
            for (size_t i = 0; i < w.instances->size(); ++i)
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r)
                        EXPECT_NEAR((*g.instances)[i][c][r], (*w.instances)[i][c][r], 1e-5f) << "instance " << i;
        }
        if (w.material >= 0) {
            EXPECT_EQ(got.materials[size_t(g.material)].name, want.materials[size_t(w.material)].name);
        }
    }
    // The default material is written as what woven renders it as.
    const Material& fallback = got.materials[size_t(mesh("Plane").material)];
    EXPECT_EQ(fallback.baseColor, Material{}.baseColor);
    EXPECT_EQ(fallback.roughness, Material{}.roughness);
    EXPECT_EQ(fallback.metallic, Material{}.metallic);

    const auto find = [&](const std::string& name) -> const Material& {
        for (const Material& m : got.materials)
            if (m.name == name) return m;
        throw std::runtime_error("no material " + name);
    };
    const Material &g = find("Rich"), &w = want.materials[0];
    EXPECT_EQ(g.baseColor, w.baseColor);
    EXPECT_FLOAT_EQ(g.metallic, w.metallic);
    EXPECT_FLOAT_EQ(g.roughness, w.roughness);
    EXPECT_EQ(g.alphaMode, w.alphaMode);
    EXPECT_FLOAT_EQ(g.alphaCutoff, w.alphaCutoff);
    EXPECT_EQ(g.doubleSided, w.doubleSided);
    EXPECT_FLOAT_EQ(g.ior, w.ior);
    EXPECT_FLOAT_EQ(g.specular, w.specular);
    EXPECT_EQ(g.specularColor, w.specularColor);
    EXPECT_EQ(g.sheen.color, w.sheen.color);
    EXPECT_FLOAT_EQ(g.sheen.roughness, w.sheen.roughness);
    EXPECT_FLOAT_EQ(g.anisotropy.strength, w.anisotropy.strength);
    EXPECT_FLOAT_EQ(g.anisotropy.rotation, w.anisotropy.rotation);
    EXPECT_FLOAT_EQ(g.clearcoat.factor, w.clearcoat.factor);
    EXPECT_FLOAT_EQ(g.clearcoat.roughness, w.clearcoat.roughness);
    EXPECT_FLOAT_EQ(g.transmission.factor, w.transmission.factor);
    EXPECT_FLOAT_EQ(g.transmission.thickness, w.transmission.thickness);
    EXPECT_FLOAT_EQ(g.transmission.attenuationDistance, w.transmission.attenuationDistance);
    EXPECT_EQ(g.transmission.attenuationColor, w.transmission.attenuationColor);
    EXPECT_FLOAT_EQ(g.iridescence.factor, w.iridescence.factor);
    EXPECT_FLOAT_EQ(g.iridescence.ior, w.iridescence.ior);
    EXPECT_FLOAT_EQ(g.iridescence.thicknessMin, w.iridescence.thicknessMin);
    EXPECT_FLOAT_EQ(g.iridescence.thicknessMax, w.iridescence.thicknessMax);
    expectTextureRef(g.iridescence.thicknessTexture, w.iridescence.thicknessTexture, "iridescence thickness");
    expectTextureRef(g.baseColorTexture, w.baseColorTexture, "base colour");
    expectTextureRef(g.metallicRoughnessTexture, w.metallicRoughnessTexture, "metallic-roughness");
    expectTextureRef(g.normalTexture, w.normalTexture, "normal");
    expectTextureRef(g.occlusionTexture, w.occlusionTexture, "occlusion");
    expectTextureRef(g.anisotropy.texture, w.anisotropy.texture, "anisotropy");
    // Images come back byte for byte (PNG is lossless), each once however often it is used.
    EXPECT_EQ(got.textures.at(size_t(g.baseColorTexture.image)).bytes, want.textures[0].bytes);
    EXPECT_EQ(got.textures.at(size_t(g.normalTexture.image)).bytes, want.textures[1].bytes);
    EXPECT_EQ(got.textures.at(size_t(g.anisotropy.texture.image)).bytes, want.textures[2].bytes);
    EXPECT_EQ(got.textures.size(), 3u);
    const Material& lamp = find("Lamp");
    EXPECT_NEAR(lamp.emission.r, 6.0f, 1e-5f);
    EXPECT_NEAR(lamp.emission.b, 1.5f, 1e-5f);
    EXPECT_FALSE(lamp.doubleSided);

    ASSERT_EQ(got.lights.size(), want.lights.size());
    for (size_t i = 0; i < want.lights.size(); ++i) {
        const PunctualLight &gl = got.lights[i], &wl = want.lights[i];
        EXPECT_EQ(gl.type, wl.type);
        if (wl.type != PunctualLight::Type::Directional) {
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(gl.position[c], wl.position[c], 1e-6f);
        }
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(gl.direction[c], wl.direction[c], 1e-6f) << "light " << i;
            EXPECT_NEAR(gl.intensity[c], wl.intensity[c], 1e-6f * wl.intensity[c]) << "light " << i;
        }
        if (wl.type == PunctualLight::Type::Spot) {
            EXPECT_FLOAT_EQ(gl.innerConeAngle, wl.innerConeAngle);
            EXPECT_FLOAT_EQ(gl.outerConeAngle, wl.outerConeAngle);
        }
    }
    ASSERT_TRUE(got.hasCamera);
    EXPECT_FLOAT_EQ(got.camera.yfov, camera.yfov);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(got.camera.cameraToWorld[i][j], camera.cameraToWorld[i][j], 1e-6f);
}

TEST(GltfWriter, WhatItWritesWovensLoaderReadsBackFromGlbAndGltf) {
    const SceneDescription scene = richScene();
    const Camera camera = lookAt({2, 3, 4}, {0, 0, 0}, {0, 1, 0}, 0.7f);
    TempDir dir;
    for (const char* name : {"rich.glb", "rich.gltf"}) {
        SCOPED_TRACE(name);
        std::vector<std::string> warnings;
        writeGltf(dir.file(name), scene, camera, warnings);
        EXPECT_TRUE(warnings.empty());
        const SceneDescription back = loadGltf(dir.file(name));
        ASSERT_EQ(back.warnings.size(), 1u);  // the loader's own note on KHR_materials_volume
        EXPECT_NE(back.warnings[0].find("thin-walled"), std::string::npos);
        expectSameScene(back, scene, camera);
    }
    // One file each, nothing beside it (no temporary left).
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), std::filesystem::directory_iterator{}), 2);
}

TEST(GltfWriter, AFloatTextureIsWrittenWithEightBitsAndAWarning) {
    SceneDescription scene = richScene();
    TextureImage wide;
    wide.name = "wide.png";
    wide.width = 2;
    wide.height = 1;
    wide.floats = {{0.0f, 0.5f, 1.0f, 1.0f}, {0.25f, 0.75f, 2.0f, 1.0f}};
    scene.textures[2] = wide;
    TempDir dir;
    std::vector<std::string> warnings;
    writeGltf(dir.file("wide.glb"), scene, sceneCamera(scene), warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("'wide.png' has more than 8 bits a channel"), std::string::npos) << warnings[0];
    const SceneDescription back = loadGltf(dir.file("wide.glb"));
    const TextureImage& t = back.textures.at(size_t(back.materials[0].anisotropy.texture.image));
    EXPECT_EQ(t.bytes.at(0), glm::u8vec4(0, 128, 255, 255));
    EXPECT_EQ(t.bytes.at(1), glm::u8vec4(64, 191, 255, 255));  // 2.0 clamped
}

TEST(GltfWriter, BadPathsAreRefusedAndLeaveNoFile) {
    const SceneDescription scene = richScene();
    TempDir dir;
    std::vector<std::string> warnings;
    try {
        writeGltf(dir.file("scene.obj"), scene, sceneCamera(scene), warnings);
        FAIL() << "no error for .obj";
    } catch (const GltfExportError& e) {
        EXPECT_NE(std::string(e.what()).find("must end in .glb or .gltf"), std::string::npos) << e.what();
    }
    try {
        writeGltf(dir.file("missing/scene.glb"), scene, sceneCamera(scene), warnings);
        FAIL() << "no error for a missing folder";
    } catch (const GltfExportError& e) {
        EXPECT_NE(std::string(e.what()).find(dir.file("missing/scene.glb")), std::string::npos) << e.what();
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace woven
