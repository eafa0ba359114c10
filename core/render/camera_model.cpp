#include "camera_model.h"

#include <cmath>

namespace woven {

// Camera space as in glTF: the camera looks down -z with +y up and +x to the right. The image
// plane sits at distance 1 in front of it, spanning [-aspect tanHalfY, aspect tanHalfY] x
// [-tanHalfY, tanHalfY].

CameraModel::CameraModel(const Camera& camera, int width, int height) : width_(width), height_(height) {
    // Keep only rotation and position: a scaled or sheared node transform must not distort rays.
    const glm::vec3 back = glm::normalize(glm::vec3(camera.cameraToWorld[2]));
    const glm::vec3 up = glm::normalize(glm::vec3(camera.cameraToWorld[1]) - glm::dot(glm::vec3(camera.cameraToWorld[1]), back) * back);
    const glm::vec3 right = glm::cross(up, back);
    position_ = glm::vec3(camera.cameraToWorld[3]);
    forward_ = -back;
    cameraToWorld_ = glm::mat4(glm::vec4(right, 0.0f), glm::vec4(up, 0.0f), glm::vec4(back, 0.0f), glm::vec4(position_, 1.0f));
    tanHalfY_ = std::tan(0.5f * camera.yfov);
    aspect_ = camera.aspect > 0.0f ? camera.aspect : float(width) / float(height);
    imagePlaneArea_ = (2.0f * tanHalfY_ * aspect_) * (2.0f * tanHalfY_);
}

glm::vec3 CameraModel::position() const { return position_; }
glm::vec3 CameraModel::forward() const { return forward_; }

Ray CameraModel::generateRay(const glm::vec2& pRaster) const {
    const float x = (2.0f * pRaster.x / float(width_) - 1.0f) * aspect_ * tanHalfY_;
    const float y = (1.0f - 2.0f * pRaster.y / float(height_)) * tanHalfY_;
    Ray ray;
    ray.o = position_;
    ray.d = glm::normalize(glm::mat3(cameraToWorld_) * glm::vec3(x, y, -1.0f));
    return ray;
}

namespace {
// Where a camera-space direction crosses the image plane, in raster coordinates.
glm::vec2 toRaster(const glm::vec3& dCamera, float tanHalfY, float aspect, int width, int height) {
    const float x = dCamera.x / -dCamera.z, y = dCamera.y / -dCamera.z;
    return {(x / (aspect * tanHalfY) + 1.0f) * 0.5f * float(width), (1.0f - y / tanHalfY) * 0.5f * float(height)};
}

bool insideImage(const glm::vec2& p, int width, int height) {
    return p.x >= 0.0f && p.x < float(width) && p.y >= 0.0f && p.y < float(height);
}
}  // namespace

glm::vec3 CameraModel::We(const Ray& ray, glm::vec2* pRaster) const {
    const glm::vec3 d = glm::normalize(ray.d);
    const float cosTheta = glm::dot(d, forward_);
    if (!(cosTheta > 0.0f)) return glm::vec3(0.0f);
    const glm::vec2 p = toRaster(glm::transpose(glm::mat3(cameraToWorld_)) * d, tanHalfY_, aspect_, width_, height_);
    if (pRaster) *pRaster = p;
    if (!insideImage(p, width_, height_)) return glm::vec3(0.0f);
    // pbrt-v3: We = 1 / (A cos^4 theta) for a pinhole (lens area 1), so that splatting light
    // paths with it and dividing by the samples per pixel matches the camera's estimate.
    const float cos2 = cosTheta * cosTheta;
    return glm::vec3(1.0f / (imagePlaneArea_ * cos2 * cos2));
}

void CameraModel::pdfWe(const Ray& ray, float* pdfPos, float* pdfDir) const {
    const glm::vec3 d = glm::normalize(ray.d);
    const float cosTheta = glm::dot(d, forward_);
    *pdfPos = 0.0f;
    *pdfDir = 0.0f;
    if (!(cosTheta > 0.0f)) return;
    const glm::vec2 p = toRaster(glm::transpose(glm::mat3(cameraToWorld_)) * d, tanHalfY_, aspect_, width_, height_);
    if (!insideImage(p, width_, height_)) return;
    *pdfPos = 1.0f;
    *pdfDir = 1.0f / (imagePlaneArea_ * cosTheta * cosTheta * cosTheta);
}

std::optional<CameraModel::WiSample> CameraModel::sampleWi(const glm::vec3& ref, const glm::vec2& u) const {
    WiSample s;
    s.pCamera = position_;
    const glm::vec3 toCamera = position_ - ref;
    const float dist2 = glm::dot(toCamera, toCamera);
    if (!(dist2 > 0.0f)) return std::nullopt;
    s.wi = toCamera / std::sqrt(dist2);
    const float cosTheta = glm::dot(-s.wi, forward_);
    if (!(cosTheta > 0.0f)) return std::nullopt;
    // The pinhole is a point: its density in area measure (1, pbrt-v3's lens area for radius 0)
    // becomes dist^2 / cos per unit solid angle at ref.
    s.pdf = dist2 / cosTheta;
    Ray ray;
    ray.o = position_;
    ray.d = -s.wi;
    s.We = We(ray, &s.pRaster);
    if (s.We == glm::vec3(0.0f)) return std::nullopt;
    return s;
}

}  // namespace woven
