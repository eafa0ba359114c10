#include "orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace woven {

namespace {
constexpr float kMaxPitch = 1.55f;  // just short of straight up or down, where yaw degenerates
}

SceneBox sceneBounds(const SceneDescription& scene) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const Mesh& m : scene.meshes)
        for (const glm::vec3& p : m.positions)
            if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
    if (!(lo.x <= hi.x)) return {glm::vec3(-0.5f), glm::vec3(0.5f)};
    return {lo, hi};
}

OrbitCamera OrbitCamera::framing(const SceneBox& box, float yfov) {
    OrbitCamera c;
    c.pivot_ = box.centre();
    c.yfov_ = yfov;
    // The bounding sphere fits the vertical field of view with a little margin.
    c.distance_ = std::max(box.radius(), 1e-3f) / std::sin(0.5f * yfov) * 1.05f;
    c.yaw_ = 0.0f;
    c.pitch_ = -0.5f;
    return c;
}

OrbitCamera OrbitCamera::fromCamera(const Camera& camera, float pivotDistance) {
    const glm::vec3 position(camera.cameraToWorld[3]);
    const glm::vec3 forward = -glm::normalize(glm::vec3(camera.cameraToWorld[2]));
    OrbitCamera c;
    c.distance_ = std::max(pivotDistance, 1e-4f);
    c.pivot_ = position + c.distance_ * forward;
    c.yfov_ = camera.yfov;
    c.pitch_ = std::clamp(std::asin(std::clamp(forward.y, -1.0f, 1.0f)), -kMaxPitch, kMaxPitch);
    c.yaw_ = std::atan2(forward.x, -forward.z);
    return c;
}

OrbitCamera OrbitCamera::forScene(const SceneDescription& scene) {
    const SceneBox box = sceneBounds(scene);
    if (!scene.hasCamera) return framing(box, scene.camera.yfov);
    const glm::vec3 position(scene.camera.cameraToWorld[3]);
    const glm::vec3 forward = -glm::normalize(glm::vec3(scene.camera.cameraToWorld[2]));
    const float depth = glm::dot(box.centre() - position, forward);
    return fromCamera(scene.camera, depth > 0.0f ? depth : box.radius());
}

void OrbitCamera::orbit(float dYaw, float dPitch) {
    yaw_ += dYaw;
    pitch_ = std::clamp(pitch_ + dPitch, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::pan(float dx, float dy) {
    const Camera c = camera();
    const glm::vec3 right(c.cameraToWorld[0]), up(c.cameraToWorld[1]);
    const float viewHeight = 2.0f * distance_ * std::tan(0.5f * yfov_);
    pivot_ += viewHeight * (-dx * right + dy * up);
}

void OrbitCamera::zoom(float factor) { distance_ = std::clamp(distance_ * factor, 1e-4f, 1e6f); }

Camera OrbitCamera::camera() const {
    // forward from yaw (about +y, 0 = looking down -z) and pitch (positive looks up).
    const glm::vec3 forward(std::sin(yaw_) * std::cos(pitch_), std::sin(pitch_), -std::cos(yaw_) * std::cos(pitch_));
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, forward);
    Camera c;
    c.yfov = yfov_;
    c.cameraToWorld = glm::mat4(glm::vec4(right, 0.0f), glm::vec4(up, 0.0f), glm::vec4(-forward, 0.0f),
                                glm::vec4(pivot_ - distance_ * forward, 1.0f));
    return c;
}

}  // namespace woven
