#pragma once
// What a scene file says, after loading: flat world-space triangle meshes, materials, lights,
// an environment and a camera. Loaders (glTF, scene files) produce it; the Embree scene, the
// integrators and the previewer consume it. Plain data, no behaviour.
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "woven_params.h"

namespace woven {

// Luminance of linear Rec. 709 RGB.
inline float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// Linear RGB float image, row 0 at the top.
struct Image {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;
    glm::vec3& at(int x, int y) { return pixels[size_t(y) * width + x]; }
    const glm::vec3& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

struct Material {
    std::string name;
    // Woven when set; otherwise the standard fallback: diffuse base colour (factor x texture)
    // plus a glossy lobe derived from roughness.
    std::optional<WovenParams> woven;
    glm::vec3 baseColor{0.8f};
    int baseColorTexture = -1;  // index into SceneDescription::textures (sRGB decoded to linear)
    float roughness = 1.0f;
    float metallic = 0.0f;
    glm::vec3 emission{0.0f};  // emissiveFactor x emissive_strength, radiance of the front side
    bool doubleSided = true;
};

// One primitive in world space. normals, uvs and tangents are per vertex and either empty
// (missing in the file and not derivable) or the size of positions.
struct Mesh {
    std::string name;  // "node/mesh/primitive" for messages
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<glm::vec4> tangents;  // xyz along dp/du, w = handedness of dp/dv
    std::vector<glm::uvec3> triangles;
    int material = -1;  // index into SceneDescription::materials; -1 = default material
};

struct PunctualLight {
    enum class Type { Point, Spot, Directional } type = Type::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // the way the light travels
    glm::vec3 intensity{1.0f};  // W/sr (point, spot) or W/m^2 (directional), colour x intensity
    float innerConeAngle = 0.0f, outerConeAngle = 0.7853982f;
};

struct Environment {
    glm::vec3 color{0.0f};  // constant radiance, multiplies `image` when there is one
    std::shared_ptr<Image> image;  // equirectangular, +y up, u = 0 at -z, increasing towards +x
    float rotation = 0.0f;  // radians about +y
};

struct Camera {
    glm::mat4 cameraToWorld{1.0f};  // glTF convention: looks down -z, +y up
    float yfov = 0.6911f;           // radians, vertical
    float aspect = 0.0f;            // 0: take it from the image size
};

// The integrators a frame can be rendered with; "auto" lets the render job choose.
inline constexpr const char* kIntegratorNames[] = {"auto", "bdpt", "path"};

// Render settings a scene file asks for; 0 or empty = not given (the command line decides).
struct RenderHints {
    int width = 0, height = 0;
    int spp = 0;
    std::string integrator;  // "bdpt", "path", "auto", ...
};

struct SceneDescription {
    std::string source;  // the file it came from, for messages
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Image> textures;
    std::vector<PunctualLight> lights;
    Environment environment;
    Camera camera;
    bool hasCamera = false;
    RenderHints render;
    // What the loader skipped or approximated (also printed on stderr), e.g. line primitives,
    // dropped degenerate triangles.
    std::vector<std::string> warnings;
};

}  // namespace woven
