#pragma once
// What a scene file says, after loading: flat world-space triangle meshes, materials, lights,
// an environment and a camera. Loaders (glTF, scene files) produce it; the Embree scene, the
// integrators and the previewer consume it. Plain data, no behaviour.
#include <glm/glm.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "image.h"
#include "luminance.h"
#include "textile_units.h"
#include "woven_params.h"

namespace woven {

// A texture image as decoded, before any colour decoding: every channel normalised to [0, 1]
// (or, for float formats, as stored), always RGBA (grey and grey-alpha expanded, alpha 1 where
// the file has none). 8-bit files keep their bytes, so a 2048^2 texture takes 16 MiB; wider
// formats keep floats. How the values are decoded (sRGB colour or linear data) is a property of
// each use (TextureRef::srgb), not of the image: glTF lets one image serve both.
struct TextureImage {
    std::string name;  // for messages: the file, or "image N"
    int width = 0, height = 0;
    std::vector<glm::u8vec4> bytes;  // 8-bit sources
    std::vector<glm::vec4> floats;   // 16-bit and float sources
    bool isFloat() const { return bytes.empty(); }
};

enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };

// One use of a texture by a material (glTF's textureInfo with its sampler and
// KHR_texture_transform): which image, which texture coordinates, how they are transformed and
// wrapped, and how the texels are decoded.
struct TextureRef {
    int image = -1;    // index into SceneDescription::textures; -1: no texture
    int texCoord = 0;  // TEXCOORD_0 or TEXCOORD_1
    glm::mat3 uvTransform{1.0f};  // KHR_texture_transform: uv' = (T * (u, v, 1)).xy
    TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
    bool nearest = false;  // magnification filter NEAREST (pixel art); else bilinear
    bool mipmaps = true;   // the preview's minification filter uses mip levels
    bool srgb = false;     // RGB holds sRGB-encoded colour (alpha is always linear)
    float scale = 1.0f;    // normalTexture.scale, occlusionTexture.strength
    explicit operator bool() const { return image >= 0; }
};

enum class AlphaMode { Opaque, Mask, Blend };

// KHR_materials_sheen: the Charlie sheen layer of cloth.
struct SheenParams {
    glm::vec3 color{0.0f};
    TextureRef colorTexture;  // RGB, sRGB
    float roughness = 0.0f;
    TextureRef roughnessTexture;  // A
};

// KHR_materials_anisotropy: the GGX lobe rougher along a direction in the tangent plane.
struct AnisotropyParams {
    float strength = 0.0f;
    float rotation = 0.0f;  // radians, counter-clockwise from the tangent towards the bitangent
    TextureRef texture;     // RG: direction in (tangent, bitangent) space, [0, 1] -> [-1, 1]; B: strength
};

// KHR_materials_clearcoat: a GGX dielectric coat (IOR 1.5) over the material.
struct ClearcoatParams {
    float factor = 0.0f;
    TextureRef texture;  // R
    float roughness = 0.0f;
    TextureRef roughnessTexture;  // G
    TextureRef normalTexture;     // with its scale
};

// KHR_materials_transmission and KHR_materials_volume, rendered thin-walled (no refraction): the
// attenuation of `thickness` is split between the two crossings of a closed surface.
struct TransmissionParams {
    float factor = 0.0f;
    TextureRef texture;  // R
    float thickness = 0.0f;
    TextureRef thicknessTexture;  // G
    glm::vec3 attenuationColor{1.0f};
    float attenuationDistance = std::numeric_limits<float>::infinity();
};

// KHR_materials_diffuse_transmission: of the light the diffuse base does not reflect, the share
// `factor` passes to the other side as a Lambertian BTDF of colour `color` (thin-walled, as a
// leaf, paper or a curtain is).
struct DiffuseTransmissionParams {
    float factor = 0.0f;
    TextureRef texture;  // A
    glm::vec3 color{1.0f};
    TextureRef colorTexture;  // RGB, sRGB
};

// KHR_materials_iridescence: a thin dielectric film over the specular reflection (thin_film.h).
struct IridescenceParams {
    float factor = 0.0f;
    TextureRef texture;  // R
    float ior = 1.3f;
    float thicknessMin = 100.0f, thicknessMax = 400.0f;  // nm
    TextureRef thicknessTexture;  // G: mix(thicknessMin, thicknessMax, G); thicknessMax without it
};

// What a glTF material made woven by a scene file, --woven or the previewer keeps of itself
// (docs/SCENE_FORMAT.md): its normal map and alpha cut-out always, its base colour unless
// "keep_base_color": false (woven_assignment.cpp).
struct KeptGltfSurface {
    bool print = true;  // the base colour texture and vertex colour multiply the yarns' colour
    bool colorsFromFactor = false;  // the yarn colours are the base colour factor's (no layer set one)
};

// A glTF 2.0 material (metallic-roughness, the KHR extensions woven reads), or a woven one.
// Defaults are woven's default material for primitives without one: a grey dielectric, as
// Blender gives them; the glTF loader sets every field from the file, whose defaults differ.
struct Material {
    std::string name;
    // Woven when set: the weave replaces the glTF BSDF; emission and doubleSided still apply.
    std::optional<WovenParams> woven;
    // Set where a glTF material was made woven after loading. A material woven in its file
    // (WOVEN_fabric) has none: its glTF fields are other viewers' fallback, not applied.
    std::optional<KeptGltfSurface> keptSurface;
    std::string draft;  // the WIF file the woven parameters were made from ("wif"), if any
    // The real cloth where the woven layers said it: its thread counts (textile keys or "scale":
    // "draft", always set here), yarn counts and fibre, which U3M export's physics read.
    std::optional<TextileKeys> textile;
    glm::vec4 baseColor{0.8f, 0.8f, 0.8f, 1.0f};  // linear RGB and alpha
    TextureRef baseColorTexture;
    float metallic = 0.0f, roughness = 0.5f;
    TextureRef metallicRoughnessTexture;  // B = metallic, G = roughness
    TextureRef normalTexture;
    TextureRef occlusionTexture;          // R; used by the preview only
    glm::vec3 emission{0.0f};  // emissiveFactor x emissive_strength: radiance of the front side
    TextureRef emissiveTexture;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = true;
    bool unlit = false;        // KHR_materials_unlit: shows its base colour, reflects nothing
    float ior = 1.5f;          // KHR_materials_ior
    float specular = 1.0f;     // KHR_materials_specular: strength of the dielectric reflection
    TextureRef specularTexture;  // A
    glm::vec3 specularColor{1.0f};
    TextureRef specularColorTexture;  // RGB, sRGB
    SheenParams sheen;
    AnisotropyParams anisotropy;
    ClearcoatParams clearcoat;
    TransmissionParams transmission;
    DiffuseTransmissionParams diffuseTransmission;
    IridescenceParams iridescence;

    // An area light: some emission, on a surface that is not unlit (which shows its colour and
    // lights nothing).
    bool emits() const { return glm::max(emission.r, glm::max(emission.g, emission.b)) > 0.0f && !unlit; }
};

// One primitive in world space. Per-vertex arrays are either empty (missing in the file and not
// derivable) or the size of positions.
struct Mesh {
    std::string name;  // "node/mesh/primitive" for messages
    // What users name parts by (woven_assignment.h): the glTF mesh's name and the names of the
    // nodes from the scene's root down to the node that holds it ("mesh3", "node7" when unnamed).
    std::string meshName;
    std::vector<std::string> nodePath;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;   // TEXCOORD_0
    std::vector<glm::vec2> uvs1;  // TEXCOORD_1
    std::vector<glm::vec4> colors;  // COLOR_0, linear RGBA
    // xyz along dp/du of the normal map's texture coordinates, w = handedness of dp/dv
    std::vector<glm::vec4> tangents;
    std::vector<glm::uvec3> triangles;
    int material = -1;  // index into SceneDescription::materials; -1 = default material
    // EXT_mesh_gpu_instancing (mesh_instances.h). Null: the arrays above are in world space.
    // Otherwise they are in the mesh's own space and each matrix places one copy of it in the
    // world, drawn as an Embree instance and by one instanced draw, so that a million copies cost
    // what one mesh does. The primitives of one instanced node share the list.
    std::shared_ptr<const std::vector<glm::mat4>> instances;
};

struct PunctualLight {
    enum class Type { Point, Spot, Directional } type = Type::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // the way the light travels
    glm::vec3 intensity{1.0f};  // W/sr (point, spot) or W/m^2 (directional), colour x intensity
    float innerConeAngle = 0.0f, outerConeAngle = 0.7853982f;
    std::string name;  // the file's, for woven render --list; may be empty
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

// A camera as a glTF file names it: --camera chooses one by either name or its index.
struct NamedCamera {
    std::string name;  // the glTF camera's ("camera2" when unnamed)
    std::string node;  // the node that holds it ("node5" when unnamed)
    Camera camera;
};

// Render settings a scene file asks for; 0 or empty = not given (the command line decides).
struct RenderHints {
    int width = 0, height = 0;
    int spp = 0;
    std::string integrator;  // a name in integrators.h's table, checked where a render takes it
    std::string sampler;     // a name in sampler.h's kSamplerNames, checked where a render takes it
    std::optional<double> noiseThreshold;  // 0 to 1
};

// A shot's photograph (docs/FIT.md): the scene file's "photo" key, which `woven fit` compares
// the scene's render with. Nothing else uses it; it changes no pixel of a render.
struct ShotPhoto {
    std::string image;  // as resolved against the scene file's folder; not opened by the loader
    enum class Encoding { Srgb, Gamma22, Linear } encoding = Encoding::Srgb;
    float vignetteSigmaPx = 0.0f;  // 0: no vignette
    std::optional<float> exposure = 1.0f;  // nullopt: "free", fitted
};

struct SceneDescription {
    std::string source;  // the file it came from, for messages
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<TextureImage> textures;
    std::vector<PunctualLight> lights;
    Environment environment;
    Camera camera;
    bool hasCamera = false;
    RenderHints render;
    // A woven scene file that sets "environment" or "lights" chose its lighting on purpose (a room
    // lit by its lamp alone): no default lighting is added to it (scene_lighting.h).
    bool lightingFromSceneFile = false;
    // Every file the scene was read from (a scene file, its glTF file, buffers and images), as
    // given: what no output of woven's may overwrite (output_path.h).
    std::vector<std::string> inputFiles;
    // What the loader skipped or approximated (also printed on stderr), e.g. line primitives,
    // dropped degenerate triangles.
    std::vector<std::string> warnings;
    // Every perspective camera of a glTF file, in the order the loader meets them (depth first
    // from the scene's roots; `camera` is the first unless a scene file sets its own), for
    // --camera to choose from (scene_camera.h).
    std::vector<NamedCamera> cameras;
    std::optional<ShotPhoto> photo;  // a shot's photograph (woven fit only)
};

}  // namespace woven
