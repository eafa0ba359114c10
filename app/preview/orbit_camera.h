#pragma once
// The previewer's interactive camera: it orbits a pivot point at some distance, pans the pivot
// and zooms the distance, keeping +y up and the field of view and aspect ratio. Until it is
// first moved it is exactly the camera it started from (roll included), so the Render button's
// first frame is `woven render`'s.
#include <optional>

#include <glm/glm.hpp>

#include "scene_camera.h"

namespace woven {

class OrbitCamera {
public:
    // `camera`, pivoting about the point in front of it at the depth of the box's centre.
    static OrbitCamera around(const Camera& camera, const SceneBox& box);
    // around(sceneCamera(scene), sceneBounds(scene)).
    static OrbitCamera forScene(const SceneDescription& scene);

    void orbit(float dYaw, float dPitch);  // radians
    void pan(float dx, float dy);          // fractions of the view height at the pivot
    void zoom(float factor);               // distance *= factor

    Camera camera() const;
    // Whether it was orbited, panned or zoomed since it started (else camera() is the scene's own).
    bool moved() const { return !initial_; }
    const glm::vec3& pivot() const { return pivot_; }
    float distance() const { return distance_; }

private:
    std::optional<Camera> initial_;  // until moved
    glm::vec3 pivot_{0.0f};
    float distance_ = 1.0f, yaw_ = 0.0f, pitch_ = 0.0f, yfov_ = 0.6911f, aspect_ = 0.0f;
};

}  // namespace woven
