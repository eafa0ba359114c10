#include "scene_picker.h"

#include "camera_model.h"

namespace woven {

int ScenePicker::pick(const SceneDescription& scene, const Camera& camera, glm::ivec2 size, glm::vec2 cursor) {
    if (size.x < 1 || size.y < 1) return -1;
    if (!scene_) scene_ = std::make_unique<RenderScene>(std::make_shared<const SceneDescription>(scene));
    const CameraModel model(camera, size.x, size.y);
    const auto hit = scene_->intersect(model.generateRay(cursor));
    return hit ? hit->mesh : -1;
}

}  // namespace woven
