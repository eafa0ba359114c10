#pragma once
// Depth maps of the scene as its strongest lights see it, so the preview's direct light is
// occluded as the renderer's is. A light within two bounding radii of the scene's centre gets a
// cube map (storing distance / far); a farther one, and a directional light, gets one flat map
// (perspective or orthographic) fitted to the bounding sphere, so its texels stay fine however
// far the light is. Lights past the budget stay unshadowed. The maps are re-rendered only when
// the shadowed lights move or the meshes change, so orbiting the camera and tuning materials
// cost only the lookups. Needs OpenGL 4.0 (cube map arrays), as the #version 410 shaders do.
// Casters that let light through (TransmittingCasters) get maps of their own: the nearest one's
// depth and the colour it passes, which the lookup multiplies in behind it, as game engines
// colour the shadows of stained glass and foliage; a scene without them has neither the pass nor
// the lookup. Woven cloth with see-through gaps is such a caster, its gaps' mean share passed
// (core's rays pass each gap: the map's texel averages them). Emitters cast none (an area light's
// samples sit on its own surface).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_mesh.h"
#include "preview_lights.h"
#include "scene_camera.h"
#include "shader_program.h"
#include "shadow_lookups.h"

namespace woven {

// The shadow casters that let light through, drawn by the caller (who holds their materials).
struct TransmittingCasters {
    // Changes whenever which meshes they are or what they pass may have; empty: there are none.
    std::string key;
    // Draws them with their transmittance programs (woven_shadow.frag, gltf_shadow.frag) into the
    // bound target for one map view: world to clip, shadow_depth.glsl's shadowLight and far.
    std::function<void(const glm::mat4& viewProjection, const glm::vec4& light, float far)> draw;
};

class ShadowMaps {
public:
    static constexpr int kMaxCubes = 8, kMaxFlats = 8;  // MAX_SHADOW_MAPS in lighting.glsl
    static constexpr int kCubeSize = 512, kFlatSize = 1024;

    ShadowMaps();
    ~ShadowMaps();
    ShadowMaps(const ShadowMaps&) = delete;
    ShadowMaps& operator=(const ShadowMaps&) = delete;

    // Re-renders the maps when the shadowed lights, `meshGeneration` or the transmitting
    // casters' key changed since the last call. `casters` are the meshes that block light;
    // `box` bounds the scene.
    void update(const std::vector<const GpuMesh*>& casters, const TransmittingCasters& transmitting,
                unsigned meshGeneration, const PreviewLights& lights, const SceneBox& box);
    // The lookups the surface programs need: None when no light has a map, Transmitted when the
    // maps hold casters that let light through.
    ShadowLookups lookups() const;
    // Uploads the lookup uniforms and binds the maps to texture units `cubeUnit` and `flatUnit`,
    // and with transmitting casters their four maps to `transmittedUnit` and the three after it.
    void bind(const ShaderProgram& program, int cubeUnit, int flatUnit, int transmittedUnit) const;

private:
    // A light with a map: which light, where it was, and which map.
    struct Shadowed {
        int light;
        PreviewLight::Type type;
        glm::vec3 position;
        bool operator==(const Shadowed& o) const { return light == o.light && type == o.type && position == o.position; }
    };
    // The maps of one kind: the opaque casters' depth; the transmitting casters' depth and colour.
    struct MapSet {
        GLuint depth = 0, transmittedDepth = 0, transmittedColor = 0;
    };
    // Sizes the maps for `cubes` cube and `flats` flat maps, and sets the state they are drawn with.
    void allocateMaps(int cubes, int flats);
    // Renders the six faces of cube map `cube` from a light at `position`.
    void renderCube(int cube, const glm::vec3& position, float far, const std::vector<const GpuMesh*>& casters,
                    const TransmittingCasters& transmitting);
    // Renders one view into `layer` of `maps` (a cube face's layer or a flat map's).
    void renderView(const MapSet& maps, int layer, const glm::mat4& viewProjection, const glm::vec4& light, float far,
                    const std::vector<const GpuMesh*>& casters, const TransmittingCasters& transmitting);

    std::unique_ptr<ShaderProgram> depthProgram_;
    GLuint framebuffer_ = 0, transmittedFramebuffer_ = 0;
    MapSet cubes_, flats_;
    std::vector<Shadowed> shadowed_;
    unsigned meshGeneration_ = ~0u;
    std::string transmittingKey_;
    // Per light (as uploaded): its cube or flat map, -1 none; the cube's far distance.
    std::vector<int> cubeIndex_, flatIndex_;
    std::vector<float> cubeFar_;
    // Per flat map: world to clip, and its texel's size in world units (x: constant, for
    // orthographic maps; y: per unit of distance from the light, for perspective ones).
    std::vector<glm::mat4> flatMatrix_;
    std::vector<glm::vec2> flatTexel_;
};

}  // namespace woven
