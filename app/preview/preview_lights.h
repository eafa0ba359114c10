#pragma once
// The scene's lights reduced to what the preview shader evaluates per pixel (see
// shaders/lighting.glsl): punctual lights as they are, each emissive mesh as a few point-like
// samples of its triangles, the environment as one ambient radiance. Plain data, no GL.
#include <glm/glm.hpp>
#include <vector>

#include "scene_description.h"

namespace woven {

struct PreviewLight {
    enum Type { Point = 0, Spot = 1, Directional = 2, Area = 3, AreaTwoSided = 4 };
    Type type = Point;
    glm::vec3 position{0.0f};   // or, for directional lights, the direction travelled
    glm::vec3 axis{0.0f};       // spot direction travelled, or area normal
    glm::vec3 intensity{0.0f};  // W/sr, W/m^2, or radiance x area
    float cosOuter = 0.0f, cosInner = 1.0f;
};

struct PreviewLights {
    static constexpr int kMaxLights = 32;  // MAX_LIGHTS in lighting.glsl
    std::vector<PreviewLight> lights;
    glm::vec3 ambient{0.0f};     // constant environment radiance lighting the surfaces
    glm::vec3 background{0.0f};  // what rays that miss everything see (the same mean)

    // The scene's punctual lights, its emissive triangles (split into up to 4 samples each
    // while the budget of kMaxLights allows, merged into clusters when there are too many) and
    // its environment's mean radiance.
    static PreviewLights fromScene(const SceneDescription& scene);
};

// Mean radiance of an environment over the sphere (the equirectangular image weighted by solid
// angle, times the colour).
glm::vec3 meanEnvironmentRadiance(const Environment& env);

}  // namespace woven
