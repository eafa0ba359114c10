#pragma once
// The pinhole camera as an importance emitter (pbrt-v3's PerspectiveCamera with no lens), so
// BDPT can connect light subpaths to it (t = 1) and splat onto the film.
#include <optional>

#include "interaction.h"
#include "scene_description.h"

namespace woven {

class CameraModel {
public:
    CameraModel(const Camera& camera, int width, int height);

    // pRaster in pixels: (0, 0) top-left corner of the image, (width, height) bottom-right.
    Ray generateRay(const glm::vec2& pRaster) const;

    // Importance of a ray leaving the camera; pRaster receives where it lands. Zero outside
    // the image.
    glm::vec3 We(const Ray& ray, glm::vec2* pRaster) const;
    void pdfWe(const Ray& ray, float* pdfPos, float* pdfDir) const;

    struct WiSample {
        glm::vec3 We;       // importance arriving at ref from the camera
        glm::vec3 wi;       // unit, from ref towards the camera
        float pdf;          // solid angle at ref
        glm::vec2 pRaster;  // where ref projects on the image
        glm::vec3 pCamera;
    };
    std::optional<WiSample> sampleWi(const glm::vec3& ref, const glm::vec2& u) const;

    // How a surface point p (normal n) moves from one pixel to the next along x and y: the ray
    // differentials of the camera ray through p, met by the tangent plane at p. For a point the
    // camera sees this is exact; for one a path reaches after bounces it is pbrt-v4's
    // approximation (Camera::Approximate_dp_dxy): the footprint it would have if the camera saw
    // it. A function of the point alone, so every path and BDPT strategy that reaches a point
    // shades it alike, and a frame stays a pure function of (scene, seed, sample range). Zero
    // where the plane is edge-on to the ray or p is at the camera.
    struct Footprint {
        glm::vec3 dpdx{0.0f}, dpdy{0.0f};
    };
    Footprint footprint(const glm::vec3& p, const glm::vec3& n) const;

    glm::vec3 position() const;
    glm::vec3 forward() const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    glm::mat4 cameraToWorld_;
    glm::vec3 position_, forward_;
    float tanHalfY_, aspect_, imagePlaneArea_;  // image plane at distance 1
    int width_, height_;
};

}  // namespace woven
