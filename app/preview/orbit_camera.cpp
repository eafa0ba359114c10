#include "orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace woven {

namespace {
constexpr float kMaxPitch = 1.55f;  // just short of straight up or down, where yaw degenerates
}

OrbitCamera OrbitCamera::around(const Camera& camera, const SceneBox& box) {
    const glm::vec3 position(camera.cameraToWorld[3]);
    const glm::vec3 forward = -glm::normalize(glm::vec3(camera.cameraToWorld[2]));
    const float depth = glm::dot(box.centre() - position, forward);
    OrbitCamera c;
    c.initial_ = camera;
    c.distance_ = std::max(depth > 0.0f ? depth : box.radius(), 1e-4f);
    c.pivot_ = position + c.distance_ * forward;
    c.yfov_ = camera.yfov;
    c.aspect_ = camera.aspect;
    c.pitch_ = std::clamp(std::asin(std::clamp(forward.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
    c.yaw_ = std::atan2(forward.x, -forward.z);
    return c;
}

OrbitCamera OrbitCamera::forScene(const SceneDescription& scene) { return around(sceneCamera(scene), sceneBounds(scene)); }

void OrbitCamera::orbit(float dYaw, float dPitch) {
    initial_.reset();
    yaw_ += dYaw;
    pitch_ = std::clamp(pitch_ + dPitch, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float dx, float dy) {
    const Camera c = camera();
    initial_.reset();
    const glm::vec3 right(c.cameraToWorld[0]), up(c.cameraToWorld[1]);
    const float viewHeight = 2.0f * distance_ * std::tan(0.5f * yfov_);
    pivot_ += viewHeight * (-dx * right + dy * up);
}

void OrbitCamera::zoom(float factor) {
    initial_.reset();
    distance_ = std::clamp(distance_ * factor, 1e-4f, 1e6f);
}

Camera OrbitCamera::camera() const {
    if (initial_) return *initial_;
    // forward from yaw (about +y, 0 = looking down -z) and pitch (positive looks up).
    const glm::vec3 forward(std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_));
    Camera c = lookAt(pivot_ - distance_ * forward, pivot_, glm::vec3(0.0f, 1.0f, 0.0f), yfov_);
    c.aspect = aspect_;
    return c;
}

}  // namespace woven
