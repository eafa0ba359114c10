#include "gl_test_context.h"

#include "orbit_camera.h"

namespace woven::test {

void ensureHeadlessGl() {
    static std::unique_ptr<HeadlessGl> context = HeadlessGl::create();
}

Image previewRadiance(const SceneDescription& scene, int width, int height, bool filterWeave, bool ambient,
                      bool shadows, bool refined) {
    ensureHeadlessGl();
    PreviewRenderer renderer;
    renderer.setMeshes(scene);
    PreviewOptions options;
    options.filterWeave = filterWeave;
    options.shadows = shadows;
    PreviewLights lights = PreviewLights::fromScene(scene);
    if (!ambient) lights.ambient = glm::vec3(0.0f);
    if (refined) renderer.renderRefined(scene, lights, scene.camera, {width, height}, options);
    else renderer.render(scene, lights, scene.camera, {width, height}, options);
    return renderer.radiance();
}

}  // namespace woven::test
