#pragma once
// Depth maps of the scene as its strongest lights see it, so the preview's direct light is
// occluded as the renderer's is: a cube map per point, spot or area-light sample (storing
// distance / far) and an orthographic map per directional light. Lights past the budget stay
// unshadowed. The maps are re-rendered only when the lights or the meshes change, so orbiting
// the camera and tuning materials cost only the lookups. Needs OpenGL 4.0 (cube map arrays).
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_mesh.h"
#include "preview_lights.h"
#include "scene_camera.h"
#include "shader_program.h"

namespace woven {

class ShadowMaps {
public:
    static constexpr int kMaxCubes = 8;  // MAX_SHADOW_CUBES in lighting.glsl
    static constexpr int kMaxSuns = 2;   // MAX_SHADOW_SUNS
    static constexpr int kCubeSize = 512, kSunSize = 1024;

    // Whether the current context can draw them.
    static bool supported();

    ShadowMaps();
    ~ShadowMaps();
    ShadowMaps(const ShadowMaps&) = delete;
    ShadowMaps& operator=(const ShadowMaps&) = delete;

    // Re-renders the maps when `lights` or `meshGeneration` differ from the last call. `casters`
    // are the meshes that block light (emitters excluded by the caller); `box` bounds the scene.
    void update(const std::vector<const GpuMesh*>& casters, unsigned meshGeneration, const PreviewLights& lights,
                const SceneBox& box);
    // Whether any light has a map (else the shader variant without shadows is used).
    bool any() const { return cubes_ + suns_ > 0; }
    // Uploads the lookup uniforms and binds the maps to texture units `cubeUnit` and `sunUnit`.
    void bind(const ShaderProgram& program, int cubeUnit, int sunUnit) const;

private:
    void renderCube(int layer, const glm::vec3& position, float far, const std::vector<const GpuMesh*>& casters);
    void renderSun(int layer, const glm::mat4& viewProjection, const std::vector<const GpuMesh*>& casters);

    std::unique_ptr<ShaderProgram> depthProgram_;
    GLuint framebuffer_ = 0, cubeTexture_ = 0, sunTexture_ = 0;
    int cubes_ = 0, suns_ = 0;
    std::vector<int> shadowIndex_;  // per light: its cube or sun layer, -1 none
    std::vector<float> shadowFar_;  // per light: the cube map's far distance
    std::vector<glm::mat4> sunMatrix_;
    float sunTexelWorld_[kMaxSuns] = {};
    // What the maps were rendered for.
    std::vector<PreviewLight> lights_;
    unsigned meshGeneration_ = ~0u;
};

}  // namespace woven
