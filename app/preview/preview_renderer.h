#pragma once
// Draws the preview frame: every mesh with the GLSL twin of its material (woven or standard),
// lit by PreviewLights, into a linear-radiance target; then shows it through the same display
// transform as core's PNG output. The window and the headless path both draw through this.
// Needs a current OpenGL 4.1 core context.
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "bounced_light.h"
#include "gltf_gl_material.h"
#include "gpu_mesh.h"
#include "display_transform.h"
#include "image_io.h"
#include "preview_lights.h"
#include "shadow_maps.h"
#include "shader_program.h"
#include "view_refinement.h"
#include "woven_gl_material.h"

namespace woven {

struct PreviewOptions {
    bool filterWeave = true;   // fade to the element-averaged reflectance where the weave is finer than a pixel
    bool shadows = true;       // occlude the strongest lights (ShadowMaps)
    // Progressive refinement (view_refinement.h): this frame is the running mean's frame number
    // `refinement`, sampling each pixel `pixelOffset` pixels from its centre. 0: a frame of its own.
    int refinement = 0;
    glm::vec2 pixelOffset{0.0f};
    // false: the bounced light traced before is kept though the lights changed (a light being
    // dragged: it is traced again once the window rests).
    bool traceBounce = true;
};

class PreviewRenderer {
public:
    PreviewRenderer();
    ~PreviewRenderer();
    PreviewRenderer(const PreviewRenderer&) = delete;
    PreviewRenderer& operator=(const PreviewRenderer&) = delete;

    // Uploads the scene's meshes, textures and environment image (materials, lights and the
    // environment's colour and rotation are read at every render(); the first render() after
    // this, or after a change of the lights, traces the light they bounce, bounced_light.h).
    void setMeshes(const SceneDescription& scene);

    // Renders the radiance image of `camera` at `size` into the internal target (into the running
    // mean of the frames before it, for options.refinement > 0).
    void render(const SceneDescription& scene, const PreviewLights& lights, const Camera& camera, glm::ivec2 size,
                const PreviewOptions& options);
    // render() of every frame of the progressive refinement (view_refinement.h): the view a
    // resting window settles to.
    void renderRefined(const SceneDescription& scene, const PreviewLights& lights, const Camera& camera,
                       glm::ivec2 size, PreviewOptions options);
    // Draws the last radiance image into `framebuffer`, filling the `size` pixels from `origin`,
    // through `transform` (as core's displayColor()). At the size it was rendered, pixel for
    // pixel; at another (a frame rendered smaller while interacting), scaled bilinearly.
    void display(GLuint framebuffer, glm::ivec2 origin, glm::ivec2 size, const DisplayTransform& transform);
    // The last radiance image (the running mean), row 0 at the top.
    Image radiance() const;

    // The program a material is drawn with (compiled on first use, then cached).
    const ShaderProgram& surfaceProgram(const Material& material, bool filterWeave, ShadowLookups shadows);
    // The program of the shadow maps' transmittance pass for a material that lets light through.
    const ShaderProgram& shadowProgram(const Material& material);

private:
    void ensureTarget(glm::ivec2 size);
    void drawEnvironment(const Environment& environment, const Camera& camera, glm::ivec2 size);
    void drawMesh(const GpuMesh& mesh, const Material& material, int materialIndex, const PreviewLights& lights,
                  const FaceAlbedos& bouncedCloth, const Camera& camera, const glm::mat4& viewProjection,
                  const PreviewOptions& options, ShadowLookups shadows);
    // Uploads the material's parameters and binds its textures, for its surface or shadow program.
    void uploadMaterial(const ShaderProgram& program, const Material& material, int materialIndex);
    // Re-renders the shadow maps where needed: the casters that let light through apart.
    void updateShadows(const SceneDescription& scene, const PreviewLights& lights);
    // Traces the bounced light again where the meshes changed since it was traced, or the lights
    // did and `retrace`.
    void updateBouncedLight(const SceneDescription& scene, const PreviewLights& lights, bool retrace);
    // The albedos the light off woven cloth's faces is multiplied by: the woven materials'
    // wovenAlbedos(), weighted by their shares of the bounced rays (recomputed where a woven
    // material changed).
    FaceAlbedos bouncedClothAlbedos(const SceneDescription& scene);

    std::vector<std::unique_ptr<GpuMesh>> meshes_;
    std::vector<size_t> sceneMeshes_;  // the scene's index of each of meshes_
    std::map<std::string, std::unique_ptr<ShaderProgram>> programs_;
    std::map<int, std::unique_ptr<WeaveTextures>> weaves_;    // by material index
    GpuTextures textures_;                                    // SceneDescription::textures
    GLuint sheenAlbedoTable_ = 0;
    std::unique_ptr<ShaderProgram> displayProgram_, environmentProgram_, accumulateProgram_;
    GLuint environmentTexture_ = 0;  // 0: a constant environment, drawn by the clear colour
    std::unique_ptr<ShadowMaps> shadows_;
    std::vector<const GpuMesh*> shadowCasters_;  // every mesh but the emitters
    unsigned meshGeneration_ = 0;
    // skyVisibility() of the meshes last uploaded, and their skyVisibilityKey().
    std::vector<std::vector<glm::vec2>> sky_;
    size_t skyKey_ = 0;
    // The lights bouncedLight() was last traced with (none: not since setMeshes()), and the
    // shares of its rays off woven cloth per material.
    std::optional<PreviewLights> bouncedLights_;
    std::vector<float> clothShares_;
    // wovenAlbedos() per material index, with its parameters' JSON, for bouncedClothAlbedos().
    std::map<int, std::pair<std::string, FaceAlbedos>> clothAlbedos_;
    SceneBox bounds_;  // of the meshes, for the depth range and the shadow maps
    void accumulate(int refinement);

    GLuint framebuffer_ = 0, colour_ = 0, depth_ = 0, emptyVao_ = 0;
    GLuint meanFramebuffer_ = 0, mean_ = 0;  // the running mean of the refinement's frames
    glm::ivec2 size_{0, 0};
};

}  // namespace woven
