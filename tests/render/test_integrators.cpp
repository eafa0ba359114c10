// The integrators against closed-form answers, against each other, and the render job's
// reproducibility. Scenes are built in code; expected values come from geometry and from the
// independent double-precision BRDF of tests/model/reference_brdf.h, never from core/render.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <atomic>
#include <cmath>
#include <functional>

#include "reference_brdf.h"
#include "render_job.h"
#include "scene_loader.h"
#include "test_scenes.h"

namespace woven {
namespace {

using test::quad;
using test::sceneWith;

constexpr float kYfov = 0.8f;
constexpr float kCameraHeight = 2.0f;

// An isotropic woven cloth that reduces to one Ashikhmin-Shirley lobe everywhere: flat yarns
// (c_y = 0, no bump), full width (no gaps), equal warp and weft, no noise.
WovenParams flatCloth() {
    WovenParams p;
    p.ex = p.ey = p.warp_ex = p.warp_ey = 10.0f;
    p.rs = 0.04f;
    p.weft_color = p.warp_color = glm::vec3(0.7f, 0.45f, 0.2f);
    p.cy = 0.0f;
    p.noise = 0.0f;
    return p;
}

test::ReferenceAS referenceLobe(const WovenParams& p) {
    return test::ReferenceAS{p.ex, p.ey, p.rs, glm::dvec3(p.weft_color)};
}

// A 100 x 100 plane at z = 0 facing +z in that cloth, seen from (0, 0, 2) looking straight down.
std::shared_ptr<SceneDescription> clothPlaneScene() {
    Material cloth;
    cloth.name = "cloth";
    cloth.woven = flatCloth();
    auto scene = sceneWith({quad("plane", {-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}, 0, 20.0f)}, {cloth});
    scene->camera.cameraToWorld = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, kCameraHeight));
    scene->camera.yfov = kYfov;
    scene->hasCamera = true;
    return scene;
}

// The pinhole camera's ray direction through raster point p (pbrt's convention, camera looking
// down -z with no rotation), written here independently of CameraModel.
glm::dvec3 cameraDirection(const glm::dvec2& p, int width, int height) {
    const double tanHalf = std::tan(0.5 * kYfov), aspect = double(width) / height;
    return glm::normalize(glm::dvec3((2.0 * p.x / width - 1.0) * aspect * tanHalf, (1.0 - 2.0 * p.y / height) * tanHalf, -1.0));
}

// Per pixel, the mean over a 4 x 4 grid inside it of `radiance(point on the plane, wo)`.
std::vector<glm::dvec3> expectedPlaneImage(int width, int height,
                                           const std::function<glm::dvec3(const glm::dvec3&, const glm::dvec3&)>& radiance) {
    std::vector<glm::dvec3> image(size_t(width) * height, glm::dvec3(0.0));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            glm::dvec3 sum(0.0);
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) {
                    const glm::dvec3 d = cameraDirection({x + (i + 0.5) / 4, y + (j + 0.5) / 4}, width, height);
                    const glm::dvec3 p = glm::dvec3(0, 0, kCameraHeight) + d * (kCameraHeight / -d.z);
                    sum += radiance(p, -d);
                }
            image[size_t(y) * width + x] = sum / 16.0;
        }
    return image;
}

// Directional albedo split into the part scaled by R_d and the grey specular part:
// albedo = R_d * diffuse + specular, by midpoint quadrature in (cos theta_i, phi_i).
struct Albedo {
    double diffuse, specular;
};
Albedo referenceAlbedo(const test::ReferenceAS& lobe, double cosThetaO) {
    const glm::dvec3 wo(std::sqrt(std::max(0.0, 1.0 - cosThetaO * cosThetaO)), 0.0, cosThetaO);
    test::ReferenceAS diffuseOnly = lobe, specularOnly = lobe;
    diffuseOnly.rd = glm::dvec3(1.0);
    specularOnly.rd = glm::dvec3(0.0);
    constexpr int kMu = 200, kPhi = 400;
    Albedo a{0.0, 0.0};
    for (int i = 0; i < kMu; ++i)
        for (int j = 0; j < kPhi; ++j) {
            const double mu = (i + 0.5) / kMu, phi = (j + 0.5) / kPhi * 2.0 * test::kPi;
            const double s = std::sqrt(1.0 - mu * mu);
            const glm::dvec3 wi(s * std::cos(phi), s * std::sin(phi), mu);
            const double spec = specularOnly.eval(wo, wi).x;
            a.specular += spec * mu;
            a.diffuse += (diffuseOnly.eval(wo, wi).x - spec) * mu;
        }
    const double dOmega = (1.0 / kMu) * (2.0 * test::kPi / kPhi);
    a.diffuse *= dOmega;
    a.specular *= dOmega;
    return a;
}

FilmImage render(std::shared_ptr<const SceneDescription> scene, RenderSettings settings) {
    RenderJob job(std::move(scene), settings);
    std::atomic<bool> cancel{false};
    job.run(cancel);
    return job.snapshot();
}

// Compares a render with a known image block by block: the mean residual of each block must lie
// within 4.5 of its standard errors (measured from the residuals' spread over the block's
// independently sampled pixels) plus 0.2 % of the expected value for the quadrature. With 16
// blocks a correct integrator fails with probability ~1e-4 (and the seeds are fixed); a factor
// missing from a strategy or its MIS weight moves a block by tens of per cent, hundreds of
// standard errors.
void expectMatches(const FilmImage& film, const std::vector<glm::dvec3>& expected, int blocks) {
    const int width = film.radiance.width, height = film.radiance.height;
    const int bw = width / blocks, bh = height / blocks;
    for (int by = 0; by < blocks; ++by)
        for (int bx = 0; bx < blocks; ++bx)
            for (int c = 0; c < 3; ++c) {
                double sum = 0.0, sumSq = 0.0, expectedSum = 0.0;
                const int n = bw * bh;
                for (int y = by * bh; y < (by + 1) * bh; ++y)
                    for (int x = bx * bw; x < (bx + 1) * bw; ++x) {
                        const double r = double(film.radiance.at(x, y)[c]) - expected[size_t(y) * width + x][c];
                        sum += r;
                        sumSq += r * r;
                        expectedSum += expected[size_t(y) * width + x][c];
                    }
                const double mean = sum / n, expectedMean = expectedSum / n;
                const double standardError = std::sqrt(std::max(0.0, sumSq / n - mean * mean) / (n - 1));
                EXPECT_LE(std::abs(mean), 4.5 * standardError + 2e-3 * expectedMean)
                    << "block (" << bx << ", " << by << ") channel " << c << ": render "
                    << expectedMean + mean << ", expected " << expectedMean << ", standard error " << standardError;
            }
}

class Furnace : public ::testing::TestWithParam<const char*> {};

// A constant environment over a flat plane: every point sees the whole upper hemisphere of sky
// and nothing else, so L(wo) = Le * albedo(wo) exactly.
TEST_P(Furnace, ConstantEnvironmentOverClothPlaneGivesAlbedoTimesLe) {
    auto scene = clothPlaneScene();
    const glm::dvec3 Le(1.0, 0.5, 0.25);
    scene->environment.color = glm::vec3(Le);
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.spp = 64;
    settings.integrator = GetParam();
    settings.seed = 7;
    const FilmImage film = render(scene, settings);

    const auto lobe = referenceLobe(flatCloth());
    // Albedo depends on cos(theta_o) only (isotropic lobe): tabulate it once.
    constexpr int kTable = 64;
    const double cosMin = 0.8;  // the widest view angle of this camera is under 37 degrees
    std::vector<Albedo> table;
    for (int i = 0; i <= kTable; ++i) table.push_back(referenceAlbedo(lobe, cosMin + (1.0 - cosMin) * i / kTable));
    const glm::dvec3 rd = lobe.rd;
    const auto expected = expectedPlaneImage(32, 32, [&](const glm::dvec3&, const glm::dvec3& wo) {
        const double f = (wo.z - cosMin) / (1.0 - cosMin) * kTable;
        const int i = std::min(int(f), kTable - 1);
        const double t = f - i;
        const double diffuse = (1 - t) * table[i].diffuse + t * table[i + 1].diffuse;
        const double specular = (1 - t) * table[i].specular + t * table[i + 1].specular;
        return Le * (rd * diffuse + glm::dvec3(specular));
    });
    expectMatches(film, expected, 4);
}

// A point light over the plane: L(wo) = f(wo, wi) I cos(theta_i) / d^2, delta light strategies only.
TEST_P(Furnace, PointLightOverClothPlaneGivesClosedFormDirectLight) {
    auto scene = clothPlaneScene();
    PunctualLight light;
    light.type = PunctualLight::Type::Point;
    light.position = {0.3f, -0.2f, 1.0f};
    light.intensity = {2.0f, 1.5f, 1.0f};
    scene->lights.push_back(light);
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.spp = 32;
    settings.integrator = GetParam();
    settings.seed = 3;
    const FilmImage film = render(scene, settings);

    const auto lobe = referenceLobe(flatCloth());
    const auto expected = expectedPlaneImage(32, 32, [&](const glm::dvec3& p, const glm::dvec3& wo) {
        const glm::dvec3 toLight = glm::dvec3(light.position) - p;
        const double dist2 = glm::dot(toLight, toLight);
        const glm::dvec3 wi = toLight / std::sqrt(dist2);
        return lobe.eval(wo, wi) * glm::dvec3(light.intensity) * (wi.z / dist2);
    });
    expectMatches(film, expected, 4);
}

INSTANTIATE_TEST_SUITE_P(BothIntegrators, Furnace, ::testing::Values("path", "bdpt"));

}  // namespace
}  // namespace woven
