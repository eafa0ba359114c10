#include "camera_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "math_constants.h"
#include "sampling.h"

namespace woven {
namespace {


// A camera at (1, 2, 3) turned 30 degrees about +y (so it looks down -z rotated towards -x).
Camera turnedCamera() {
    Camera c;
    c.cameraToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)) *
                      glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 1, 0));
    c.yfov = 0.8f;
    return c;
}

TEST(CameraModel, RaysFollowTheGltfConventionAndFieldOfView) {
    const Camera c = turnedCamera();
    const CameraModel cam(c, 64, 32);
    const glm::vec3 forward{-std::sin(glm::radians(30.0f)), 0.0f, -std::cos(glm::radians(30.0f))};
    EXPECT_NEAR(glm::length(cam.forward() - forward), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(cam.position() - glm::vec3(1, 2, 3)), 0.0f, 1e-6f);
    const Ray centre = cam.generateRay({32.0f, 16.0f});
    EXPECT_EQ(centre.o, cam.position());
    EXPECT_NEAR(glm::length(centre.d - forward), 0.0f, 1e-6f);
    // Top edge: yfov / 2 above the axis, towards +y (row 0 is the top).
    const Ray top = cam.generateRay({32.0f, 0.0f});
    EXPECT_NEAR(std::acos(glm::dot(top.d, forward)), 0.4f, 1e-5f);
    EXPECT_GT(top.d.y, 0.0f);
    // Right edge: aspect 2 from the image size, to the camera's right (world -z turned).
    const Ray right = cam.generateRay({64.0f, 16.0f});
    EXPECT_NEAR(std::tan(std::acos(glm::dot(right.d, forward))), 2.0f * std::tan(0.4f), 1e-5f);
    const glm::vec3 rightAxis{std::cos(glm::radians(30.0f)), 0.0f, -std::sin(glm::radians(30.0f))};
    EXPECT_GT(glm::dot(right.d, rightAxis), 0.0f);
    // An explicit aspect overrides the image's.
    Camera wide = c;
    wide.aspect = 3.0f;
    const Ray wideRight = CameraModel(wide, 64, 32).generateRay({64.0f, 16.0f});
    EXPECT_NEAR(std::tan(std::acos(glm::dot(wideRight.d, forward))), 3.0f * std::tan(0.4f), 1e-5f);
}

TEST(CameraModel, ScaleInTheTransformDoesNotDistortRays) {
    Camera c = turnedCamera();
    c.cameraToWorld = c.cameraToWorld * glm::scale(glm::mat4(1.0f), glm::vec3(3.0f, 0.5f, 2.0f));
    const CameraModel scaled(c, 64, 32), plain(turnedCamera(), 64, 32);
    for (const glm::vec2 p : {glm::vec2(0, 0), glm::vec2(10, 30), glm::vec2(64, 32)})
        EXPECT_NEAR(glm::length(scaled.generateRay(p).d - plain.generateRay(p).d), 0.0f, 1e-5f);
}

TEST(CameraModel, ImportanceOfAGeneratedRayReturnsItsRasterPosition) {
    const CameraModel cam(turnedCamera(), 64, 32);
    const float tanHalf = std::tan(0.4f);
    const float area = (2.0f * 2.0f * tanHalf) * (2.0f * tanHalf);  // image plane at distance 1
    Rng rng(20);
    for (int i = 0; i < 1000; ++i) {
        const glm::vec2 p = rng.uniform2() * glm::vec2(64.0f, 32.0f);
        const Ray ray = cam.generateRay(p);
        glm::vec2 back;
        const glm::vec3 We = cam.We(ray, &back);
        ASSERT_NEAR(glm::distance(back, p), 0.0f, 1e-3f);
        const float cosTheta = glm::dot(ray.d, cam.forward());
        // pbrt-v3's pinhole: We = 1 / (A cos^4), pdfPos = 1 (lens area 1), pdfDir = 1 / (A cos^3).
        ASSERT_NEAR(We.r, 1.0f / (area * std::pow(cosTheta, 4.0f)), 1e-4f * We.r);
        float pdfPos, pdfDir;
        cam.pdfWe(ray, &pdfPos, &pdfDir);
        ASSERT_EQ(pdfPos, 1.0f);
        ASSERT_NEAR(pdfDir, 1.0f / (area * std::pow(cosTheta, 3.0f)), 1e-4f * pdfDir);
    }
    Ray behind;
    behind.o = cam.position();
    behind.d = -cam.forward();
    EXPECT_EQ(cam.We(behind, nullptr), glm::vec3(0.0f));
    Ray outside = cam.generateRay({70.0f, 16.0f});
    EXPECT_EQ(cam.We(outside, nullptr), glm::vec3(0.0f));
    float pdfPos, pdfDir;
    cam.pdfWe(outside, &pdfPos, &pdfDir);
    EXPECT_EQ(pdfDir, 0.0f);
}

// The normalisation a light tracer relies on: the integral of We cos over a pixel's directions is
// 1 / (width height), so that W H / N times the splats of N light paths estimate radiance. Monte
// Carlo over the sphere: 4 pi mean(We cos) = 1 and pdfDir integrates to 1; 5 standard errors.
TEST(CameraModel, ImportanceAndDirectionPdfIntegrateToOne) {
    const CameraModel cam(turnedCamera(), 64, 32);
    Rng rng(21);
    double sumWe = 0.0, sumWe2 = 0.0, sumPdf = 0.0;
    double pixelWe = 0.0;
    const int n = 1000000;
    for (int i = 0; i < n; ++i) {
        Ray ray;
        ray.o = cam.position();
        ray.d = sampleUniformSphere(rng.uniform2());
        glm::vec2 p;
        const float we = cam.We(ray, &p).r * std::max(0.0f, glm::dot(ray.d, cam.forward()));
        sumWe += 4.0 * kPi * we;
        sumWe2 += double(4.0 * kPi * we) * (4.0 * kPi * we);
        float pdfPos, pdfDir;
        cam.pdfWe(ray, &pdfPos, &pdfDir);
        sumPdf += 4.0 * kPi * pdfDir;
        if (we > 0.0f && int(p.x) / 8 == 3 && int(p.y) / 8 == 1) pixelWe += 4.0 * kPi * we;  // an 8 x 8 pixel block
    }
    const double mean = sumWe / n, se = std::sqrt((sumWe2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, 1.0, 5.0 * se);
    EXPECT_NEAR(sumPdf / n, 1.0, 5.0 * se);  // We cos and pdfDir are the same function for a pinhole
    // 64 of the 2048 pixels, off-centre: 1/32 of the total. Its standard error is about
    // sqrt(32) times the whole image's relative error; 5 of them.
    EXPECT_NEAR(pixelWe / n, 1.0 / 32.0, 5.0 * se * std::sqrt(32.0) / 32.0);
}

TEST(CameraModel, SampleWiAgreesWithWeAndProjection) {
    const CameraModel cam(turnedCamera(), 64, 32);
    Rng rng(22);
    int inside = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 ref = cam.position() + 5.0f * sampleUniformSphere(rng.uniform2()) * (0.2f + rng.uniform());
        const auto s = cam.sampleWi(ref, rng.uniform2());
        if (!s) continue;
        ++inside;
        ASSERT_EQ(s->pCamera, cam.position());
        const glm::vec3 toCamera = cam.position() - ref;
        ASSERT_NEAR(glm::length(s->wi - glm::normalize(toCamera)), 0.0f, 1e-5f);
        const float cosTheta = glm::dot(-s->wi, cam.forward());
        ASSERT_NEAR(s->pdf, glm::dot(toCamera, toCamera) / cosTheta, 1e-4f * s->pdf);
        Ray ray;
        ray.o = cam.position();
        ray.d = -s->wi;
        glm::vec2 p;
        ASSERT_NEAR(cam.We(ray, &p).r, s->We.r, 1e-5f * s->We.r);
        ASSERT_NEAR(glm::distance(p, s->pRaster), 0.0f, 1e-3f);
        // The camera ray through pRaster goes to ref.
        const Ray back = cam.generateRay(s->pRaster);
        ASSERT_NEAR(glm::length(back.d + s->wi), 0.0f, 1e-4f);
    }
    // About the image's share of directions: a sanity check that the test saw both cases.
    EXPECT_GT(inside, 20);
    EXPECT_LT(inside, 1000);
}

// End to end, as a light tracer would do it: a camera facing a large emitter of radiance L that
// fills its view. Points sampled uniformly on the emitter, connected with sampleWi and splatted
// with weight W H / N, estimate L in every pixel.
TEST(CameraModel, LightTracingSplatsReproduceTheRadianceSeen) {
    Camera c;  // at the origin, looking down -z
    c.yfov = 0.6f;
    const int width = 8, height = 6;
    const CameraModel cam(c, width, height);
    const float L = 2.5f, z = -2.0f, half = 1.0f;  // the emitter: [-1, 1]^2 at z = -2, facing +z
    const float area = (2.0f * half) * (2.0f * half);
    std::vector<double> image(width * height, 0.0);
    const int n = 400000;
    Rng rng(23);
    for (int i = 0; i < n; ++i) {
        const glm::vec2 u = rng.uniform2();
        const glm::vec3 y{(2.0f * u.x - 1.0f) * half, (2.0f * u.y - 1.0f) * half, z};
        const auto s = cam.sampleWi(y, rng.uniform2());
        if (!s) continue;
        const float cosLight = std::abs(s->wi.z);
        const double contribution = L * s->We.r * cosLight / s->pdf * area;  // / pdfPos
        image[int(s->pRaster.y) * width + int(s->pRaster.x)] += contribution * width * height / n;
    }
    // The view covers half the emitter, so each pixel gets ~ 400000 / 2 / 48 ~ 4000 splats of
    // nearly equal weight (cos^4 varies by < 20 %): a relative error near 1.6 %. 8 % is five of
    // those, while a missing cosine or area factor is off by 10 % (the corner cosines) to 300 %.
    // (Measured: the worst of the 48 pixels is 3.2 % off.)
    for (int p = 0; p < width * height; ++p) EXPECT_NEAR(image[p], L, 0.08 * L) << "pixel " << p;
}

}  // namespace
}  // namespace woven
