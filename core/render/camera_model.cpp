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

CameraModel::Footprint CameraModel::footprint(const glm::vec3& p, const glm::vec3& n) const {
    const glm::vec3 d = p - position_;
    const float depth = glm::dot(d, forward_);
    // The ray to p scaled to reach the image plane's depth 1, whose x and y move by one pixel's
    // width on that plane; beside or behind the camera (a point only bounces reach), p's distance
    // takes the depth's place, as pbrt-v4 treats every point as if straight ahead.
    const float length = glm::length(d);
    if (!(length > 0.0f)) return {};
    const float scale = depth > 0.1f * length ? depth : length;
    const glm::vec3 D = d / scale;
    const glm::vec3 right(cameraToWorld_[0]), up(cameraToWorld_[1]);
    const float pixel = 2.0f * tanHalfY_ / float(height_);  // square pixels: also aspect 2 tanHalfY / width
    const float pixelX = 2.0f * aspect_ * tanHalfY_ / float(width_);
    const float np = glm::dot(n, d);
    auto offset = [&](const glm::vec3& dir) -> glm::vec3 {
        const float nd = glm::dot(n, dir);
        if (!(std::abs(nd) > 1e-6f * glm::length(dir))) return glm::vec3(0.0f);
        const glm::vec3 hit = position_ + (np / nd) * dir;
        const glm::vec3 dp = hit - p;
        return std::isfinite(dp.x + dp.y + dp.z) ? dp : glm::vec3(0.0f);
    };
    Footprint f;
    f.dpdx = offset(D + pixelX * right);
    f.dpdy = offset(D - pixel * up);  // raster y runs down
    if (f.dpdx == glm::vec3(0.0f) || f.dpdy == glm::vec3(0.0f)) return {};
    return f;
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
