#pragma once
// Depth maps of the scene as its strongest lights see it, so the preview's direct light is
// occluded as the renderer's is. A light within two bounding radii of the scene's centre gets a
// cube map (storing distance / far); a farther one, and a directional light, gets one flat map
// (perspective or orthographic) fitted to the bounding sphere, so its texels stay fine however
// far the light is. Lights past the budget stay unshadowed. The maps are re-rendered only when
// the shadowed lights move or the meshes change, so orbiting the camera and tuning materials
// cost only the lookups. Needs OpenGL 4.0 (cube map arrays), as the #version 410 shaders do.
// Unlike core, woven cloth with see-through gaps casts a solid shadow here, and emitters cast
// none (an area light's samples sit on its own surface).
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
    static constexpr int kMaxCubes = 8, kMaxFlats = 8;  // MAX_SHADOW_MAPS in lighting.glsl
    static constexpr int kCubeSize = 512, kFlatSize = 1024;

    ShadowMaps();
    ~ShadowMaps();
    ShadowMaps(const ShadowMaps&) = delete;
    ShadowMaps& operator=(const ShadowMaps&) = delete;

    // Re-renders the maps when the shadowed lights or `meshGeneration` changed since the last
    // call. `casters` are the meshes that block light; `box` bounds the scene.
    void update(const std::vector<const GpuMesh*>& casters, unsigned meshGeneration, const PreviewLights& lights,
                const SceneBox& box);
    // Whether any light has a map (else the shader variant without shadows is used).
    bool any() const { return !shadowed_.empty(); }
    // Uploads the lookup uniforms and binds the maps to texture units `cubeUnit` and `flatUnit`.
    void bind(const ShaderProgram& program, int cubeUnit, int flatUnit) const;

private:
    // A light with a map: which light, where it was, and which map.
    struct Shadowed {
        int light;
        PreviewLight::Type type;
        glm::vec3 position;
        bool operator==(const Shadowed& o) const { return light == o.light && type == o.type && position == o.position; }
    };
    void renderCube(int layer, const glm::vec3& position, float far, const std::vector<const GpuMesh*>& casters);
    void renderFlat(int layer, const glm::mat4& viewProjection, const std::vector<const GpuMesh*>& casters);

    std::unique_ptr<ShaderProgram> depthProgram_;
    GLuint framebuffer_ = 0, cubeTexture_ = 0, flatTexture_ = 0;
    std::vector<Shadowed> shadowed_;
    unsigned meshGeneration_ = ~0u;
    // Per light (as uploaded): its cube or flat map, -1 none; the cube's far distance.
    std::vector<int> cubeIndex_, flatIndex_;
    std::vector<float> cubeFar_;
    // Per flat map: world to clip, and its texel's size in world units (x: constant, for
    // orthographic maps; y: per unit of distance from the light, for perspective ones).
    std::vector<glm::mat4> flatMatrix_;
    std::vector<glm::vec2> flatTexel_;
};

}  // namespace woven
