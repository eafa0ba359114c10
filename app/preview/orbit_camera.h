#pragma once
// The previewer's interactive camera: it orbits a pivot point at some distance, pans the pivot
// and zooms the distance; it converts to and from the scene's Camera, which the preview shader
// and core's renderer both take.
#include <glm/glm.hpp>

#include "scene_description.h"

namespace woven {

struct SceneBox {
    glm::vec3 lo{0.0f}, hi{0.0f};
    glm::vec3 centre() const { return 0.5f * (lo + hi); }
    float radius() const { return 0.5f * glm::length(hi - lo); }
};
// Bounds of every finite vertex; a unit box at the origin when there are none.
SceneBox sceneBounds(const SceneDescription& scene);

class OrbitCamera {
public:
    // Looks at the whole box from the front, slightly above.
    static OrbitCamera framing(const SceneBox& box, float yfov);
    // The scene's own camera, pivoting about the point `pivotDistance` in front of it.
    static OrbitCamera fromCamera(const Camera& camera, float pivotDistance);
    // The scene's camera if it has one (pivot at the depth of the bounds' centre), else framing.
    static OrbitCamera forScene(const SceneDescription& scene);

    void orbit(float dYaw, float dPitch);  // radians
    void pan(float dx, float dy);          // fractions of the view height at the pivot
    void zoom(float factor);               // distance *= factor

    Camera camera() const;
    const glm::vec3& pivot() const { return pivot_; }
    float distance() const { return distance_; }

private:
    glm::vec3 pivot_{0.0f};
    float distance_ = 1.0f, yaw_ = 0.0f, pitch_ = 0.0f, yfov_ = 0.6911f;
};

}  // namespace woven
