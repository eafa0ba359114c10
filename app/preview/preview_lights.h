#pragma once
// The scene's lights reduced to what the preview shader evaluates per pixel (see
// shaders/lighting.glsl): punctual lights as they are, each emissive mesh as a few point-like
// samples of its triangles, the environment's bright compact regions (a sun, a softbox) as
// directional lights and the rest of it as one ambient radiance. Plain data, no GL.
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
    float area = 0.0f;  // an area sample's: of the triangles it stands for
};

struct PreviewLights {
    static constexpr int kMaxLights = 32;  // MAX_LIGHTS in lighting.glsl
    std::vector<PreviewLight> lights;
    glm::vec3 ambient{0.0f};  // constant environment radiance lighting the surfaces

    // The scene's punctual lights, its environment (environmentLights()), and its emissive
    // triangles (split into up to 4 samples each while the budget of kMaxLights allows, merged
    // into clusters when there are too many).
    static PreviewLights fromScene(const SceneDescription& scene);
};

// An environment as up to `maxLights` directional lights, one per connected region of the
// image brighter than 8x its mean (the brightest regions first, each carrying its irradiance
// sum L dOmega, from its luminance-weighted mean direction; a region without one direction,
// such as a ring, is left out), plus the constant radiance that keeps the rest of its energy.
// A constant environment is all ambient. Negative pixels count as 0, as in core.
struct EnvironmentLights {
    std::vector<PreviewLight> lights;
    glm::vec3 ambient{0.0f};
};
EnvironmentLights environmentLights(const Environment& env, int maxLights);

}  // namespace woven
