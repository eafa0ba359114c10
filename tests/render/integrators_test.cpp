// The integrators against closed-form answers, against each other, and the render job's
// reproducibility. Scenes are built in code; expected values come from geometry and from the
// independent double-precision BRDF of tests/model/reference_brdf.h, never from core/render.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <set>

#include "adaptive_sampling.h"
#include "reference_brdf.h"
#include "render_job.h"
#include "scene_loader.h"
#include "test_scenes.h"

namespace woven {
namespace {

using test::quad;
using test::render;
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

// A 100 x 100 plane at z = 0 facing +z in that cloth, seen from (0, 0, 2) looking straight down;
// optionally with vertex normals `shadingNormal` instead of its geometric normal.
std::shared_ptr<SceneDescription> clothPlaneScene(const glm::vec3& shadingNormal = glm::vec3(0.0f)) {
    Material cloth;
    cloth.name = "cloth";
    cloth.woven = flatCloth();
    Mesh plane = quad("plane", {-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}, 0, 20.0f);
    if (shadingNormal != glm::vec3(0.0f)) plane.normals.assign(4, shadingNormal);
    auto scene = sceneWith({plane}, {cloth});
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

// Each closed-form case with each integrator, sampling uniformly and adaptively. Adaptive BDPT
// scales its light paths' splats by pixels / pixels sampled (PassImage::splatScale): without
// that, the light-tracing strategy fades as pixels stop, and the point light cases come out 1-4 %
// dark, five to ten standard errors.
struct FurnaceCase {
    const char* integrator;
    bool adaptive;
};

class Furnace : public ::testing::TestWithParam<FurnaceCase> {
protected:
    // `noiseThreshold`: one at which some pixels stop before settings.spp, in the adaptive case.
    FilmImage renderCase(std::shared_ptr<const SceneDescription> scene, RenderSettings settings,
                         double noiseThreshold) const {
        settings.integrator = GetParam().integrator;
        if (GetParam().adaptive) settings.noiseThreshold = noiseThreshold;
        const FilmImage film = render(std::move(scene), settings);
        if (settings.noiseThreshold > 0.0) {
            const auto [fewest, most] = std::minmax_element(film.sampleCount.begin(), film.sampleCount.end());
            EXPECT_LT(*fewest, float(settings.spp)) << "no pixel stopped: the adaptive case tests nothing";
            EXPECT_GE(*fewest, float(AdaptiveSampling::kMinSamples));
            EXPECT_LE(*most, float(settings.spp));
        }
        return film;
    }
};

// A constant environment over a flat plane: every point sees the whole upper hemisphere of sky
// and nothing else, so L(wo) = Le * albedo(wo) exactly.
TEST_P(Furnace, ConstantEnvironmentOverClothPlaneGivesAlbedoTimesLe) {
    auto scene = clothPlaneScene();
    const glm::dvec3 Le(1.0, 0.5, 0.25);
    scene->environment.color = glm::vec3(Le);
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.spp = 64;
    settings.seed = 7;
    const FilmImage film = renderCase(scene, settings, 0.1);

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
    settings.seed = 3;
    const FilmImage film = renderCase(scene, settings, 0.02);

    const auto lobe = referenceLobe(flatCloth());
    const auto expected = expectedPlaneImage(32, 32, [&](const glm::dvec3& p, const glm::dvec3& wo) {
        const glm::dvec3 toLight = glm::dvec3(light.position) - p;
        const double dist2 = glm::dot(toLight, toLight);
        const glm::dvec3 wi = toLight / std::sqrt(dist2);
        return lobe.eval(wo, wi) * glm::dvec3(light.intensity) * (wi.z / dist2);
    });
    expectMatches(film, expected, 4);
}

// The same with every shading normal tilted 30 degrees off the geometric one: the lobe turns with
// it, L(wo) = f_ns(wo, wi) I |wi . ns| / d^2. Light subpaths need the adjoint BSDF's correction
// |wo.ns||wi.ng| / (|wo.ng||wi.ns|) to give the same (Veach 1997, 5.3); without it BDPT's
// light-tracing strategy is off by up to tens of per cent here.
TEST_P(Furnace, PointLightOverPlaneWithTiltedShadingNormals) {
    const glm::dvec3 ns = glm::normalize(glm::dvec3(0.5, 0.0, std::sqrt(3.0) / 2.0));
    auto scene = clothPlaneScene(glm::vec3(ns));
    PunctualLight light;
    light.type = PunctualLight::Type::Point;
    light.position = {-0.4f, 0.1f, 0.8f};
    light.intensity = glm::vec3(1.0f);
    scene->lights.push_back(light);
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.spp = 32;
    settings.seed = 5;
    const FilmImage film = renderCase(scene, settings, 0.02);

    const auto lobe = referenceLobe(flatCloth());
    // Any frame around ns will do: the lobe is isotropic.
    const glm::dvec3 x = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), ns)), y = glm::cross(ns, x);
    auto local = [&](const glm::dvec3& w) { return glm::dvec3(glm::dot(w, x), glm::dot(w, y), glm::dot(w, ns)); };
    const auto expected = expectedPlaneImage(32, 32, [&](const glm::dvec3& p, const glm::dvec3& wo) {
        const glm::dvec3 toLight = glm::dvec3(light.position) - p;
        const double dist2 = glm::dot(toLight, toLight);
        const glm::dvec3 wi = toLight / std::sqrt(dist2);
        return lobe.eval(local(wo), local(wi)) * glm::dvec3(light.intensity) * (std::abs(glm::dot(wi, ns)) / dist2);
    });
    expectMatches(film, expected, 4);
}

// A point light under a gap-free sheet whose yarns transmit, seen from above: all the light the
// camera gets has crossed the yarns, L(wo) = f_T(wo, wi) I |cos theta_i| / d^2, f_T as
// docs/MODEL_TRANSMISSION.md section 2 writes it (flat yarns: the yarn frame is the plane's, and
// the lobe is isotropic). The path tracer finds it by next-event estimation from the sheet's
// front, BDPT also by light tracing from its back. With transmission 0 the image is black.
TEST_P(Furnace, PointLightBehindGapFreeSheetGivesClosedFormTransmission) {
    auto scene = clothPlaneScene();
    WovenParams cloth = flatCloth();
    cloth.transmission = 1.0f;
    cloth.transmission_gloss = 0.5f;
    scene->materials[0].woven = cloth;
    PunctualLight light;
    light.type = PunctualLight::Type::Point;
    light.position = {0.3f, 0.2f, -1.0f};
    light.intensity = glm::vec3(2.0f);
    scene->lights.push_back(light);
    RenderSettings settings;
    settings.width = settings.height = 32;
    settings.spp = 32;
    settings.seed = 9;
    const FilmImage film = renderCase(scene, settings, 0.02);

    const glm::dvec3 rd(cloth.warp_color), hue = rd / std::max(rd.r, std::max(rd.g, rd.b));
    const glm::dvec3 T = double(cloth.transmission) * (1.0 - rd) * hue * hue;
    const double g = cloth.transmission_gloss, e = cloth.ex, rs = cloth.rs;
    const auto coat = [](double mu) { return 1.0 - std::pow(1.0 - mu / 2.0, 5.0); };
    const auto expected = expectedPlaneImage(32, 32, [&](const glm::dvec3& p, const glm::dvec3& wo) {
        const glm::dvec3 toLight = glm::dvec3(light.position) - p;
        const double dist2 = glm::dot(toLight, toLight);
        const glm::dvec3 wi = toLight / std::sqrt(dist2);
        const double mo = wo.z, mi = -wi.z;
        const glm::dvec3 H(wo.x + wi.x, wo.y + wi.y, mo + mi);  // wi mirrored through the sheet
        const double hk = 0.5 * glm::length(H), nh = H.z / glm::length(H);
        const double glossy = (e + 1.0) / (8.0 * test::kPi) * std::pow(nh, e) / (hk * std::max(mo, mi));
        const double lobe = (1.0 - g) * 28.0 / (23.0 * test::kPi) + g * glossy;
        return T * ((1.0 - rs) * coat(mo) * coat(mi) * lobe) * glm::dvec3(light.intensity) * (mi / dist2);
    });
    expectMatches(film, expected, 4);

    cloth.transmission = 0.0f;
    scene->materials[0].woven = cloth;
    settings.noiseThreshold = 0.0;
    settings.spp = 4;
    const FilmImage opaque = render(scene, settings);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_EQ(opaque.radiance.at(x, y), glm::vec3(0.0f)) << x << "," << y;
}

INSTANTIATE_TEST_SUITE_P(Integrators, Furnace,
                         ::testing::Values(FurnaceCase{"path", false}, FurnaceCase{"bdpt", false}, FurnaceCase{"path", true},
                                           FurnaceCase{"bdpt", true}),
                         [](const auto& info) {
                             return std::string(info.param.integrator) + (info.param.adaptive ? "Adaptive" : "");
                         });

// A coarse sphere with smooth vertex normals: its shading normals stray far from the facets'
// geometric normals, which is where the adjoint BSDF of light subpaths needs its correction.
Mesh coarseSphere(const glm::vec3& centre, float radius, int material) {
    constexpr int kSegments = 10, kRings = 6;
    Mesh m;
    m.name = "sphere";
    m.material = material;
    for (int r = 0; r <= kRings; ++r)
        for (int s = 0; s <= kSegments; ++s) {
            const float theta = 3.14159265f * r / kRings, phi = 2.0f * 3.14159265f * s / kSegments;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
            m.positions.push_back(centre + radius * n);
            m.normals.push_back(n);
            m.uvs.push_back(glm::vec2(4.0f * s / kSegments, 2.0f * r / kRings));
        }
    for (int r = 0; r < kRings; ++r)
        for (int s = 0; s < kSegments; ++s) {
            const unsigned a = unsigned(r * (kSegments + 1) + s), b = a + 1, c = a + kSegments + 2, d = a + kSegments + 1;
            if (r > 0) m.triangles.push_back({a, d, b});
            if (r < kRings - 1) m.triangles.push_back({b, d, c});
        }
    return m;
}

// A closed box lit by a small area light under its ceiling and a point light, a woven cloth with
// gaps on its floor and on a coarse smooth-shaded sphere, grey walls: most of the light arrives
// after one or more bounces.
std::shared_ptr<SceneDescription> clothInBoxScene() {
    Material walls;
    walls.name = "walls";
    walls.baseColor = glm::vec4(glm::vec3(0.6f, 0.6f, 0.55f), 1.0f);
    Material lamp;
    lamp.name = "lamp";
    lamp.baseColor = glm::vec4(glm::vec3(0.0f), 1.0f);
    lamp.emission = glm::vec3(12.0f, 10.0f, 8.0f);
    lamp.doubleSided = false;
    Material cloth;
    cloth.name = "cloth";
    WovenParams p;  // the paper's look: e_x = 100, e_y = 2, twill, round yarns with gaps
    p.pattern = {1, 2, 1};
    p.cy = 0.75f;
    p.yarn_width = p.warp_width = 0.8f;
    p.noise = 0.3f;
    cloth.woven = p;
    std::vector<Mesh> meshes = test::boxInside({-1, 0, -1}, {1, 2, 1}, 0);
    // The lamp faces down: counter-clockwise seen from below.
    meshes.push_back(quad("lamp", {-0.25f, 1.98f, -0.25f}, {0.25f, 1.98f, -0.25f}, {0.25f, 1.98f, 0.25f},
                          {-0.25f, 1.98f, 0.25f}, 1));
    meshes.push_back(quad("cloth", {-0.8f, 0.05f, 0.8f}, {0.8f, 0.05f, 0.8f}, {0.8f, 0.05f, -0.8f},
                          {-0.8f, 0.05f, -0.8f}, 2, 12.0f));
    meshes.push_back(coarseSphere({0.35f, 0.45f, -0.3f}, 0.3f, 2));
    auto scene = sceneWith(std::move(meshes), {walls, lamp, cloth});
    PunctualLight bulb;
    bulb.position = {0.6f, 1.5f, -0.6f};
    bulb.intensity = glm::vec3(0.5f);
    scene->lights.push_back(bulb);
    scene->camera.cameraToWorld =
        glm::inverse(glm::lookAt(glm::vec3(0.0f, 1.2f, 0.95f), glm::vec3(0.0f, 0.4f, -0.5f), glm::vec3(0, 1, 0)));
    scene->camera.yfov = 1.2f;
    scene->hasCamera = true;
    return scene;
}

// Outdoors: a sun (directional), a spot light and a sky over a satin cloth lifted above grey
// ground, with a wall casting shadows and reflecting light onto both.
std::shared_ptr<SceneDescription> clothUnderSkyScene() {
    Material ground;
    ground.name = "ground";
    ground.baseColor = glm::vec4(glm::vec3(0.5f, 0.5f, 0.45f), 1.0f);
    Material cloth;
    cloth.name = "cloth";
    WovenParams p;  // satin (9,1,3) with long glossy floats, see-through gaps
    p.pattern = {9, 1, 3};
    p.yarn_width = p.warp_width = 0.85f;
    p.weft_color = {0.2f, 0.3f, 0.6f};
    p.warp_color = {0.6f, 0.5f, 0.2f};
    cloth.woven = p;
    std::vector<Mesh> meshes{quad("ground", {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}, 0),
                             quad("cloth", {-1, 0.2f, 1}, {1, 0.2f, 1}, {1, 0.2f, -1}, {-1, 0.2f, -1}, 1, 15.0f),
                             quad("wall", {-1.5f, 0, -1.2f}, {1.5f, 0, -1.2f}, {1.5f, 1.5f, -1.2f}, {-1.5f, 1.5f, -1.2f}, 0)};
    auto scene = sceneWith(std::move(meshes), {ground, cloth});
    PunctualLight sun;
    sun.type = PunctualLight::Type::Directional;
    sun.direction = glm::normalize(glm::vec3(0.5f, -1.0f, -0.6f));
    sun.intensity = glm::vec3(2.0f, 1.9f, 1.7f);
    PunctualLight spot;
    spot.type = PunctualLight::Type::Spot;
    spot.position = {0.8f, 1.2f, 0.8f};
    spot.direction = glm::normalize(glm::vec3(-1.0f, -1.5f, -1.0f));
    spot.intensity = glm::vec3(3.0f);
    spot.outerConeAngle = 0.5f;
    spot.innerConeAngle = 0.3f;
    scene->lights = {sun, spot};
    scene->environment.color = glm::vec3(0.3f, 0.4f, 0.6f);
    scene->camera.cameraToWorld =
        glm::inverse(glm::lookAt(glm::vec3(0.0f, 2.0f, 2.2f), glm::vec3(0.0f, 0.3f, -0.3f), glm::vec3(0, 1, 0)));
    scene->camera.yfov = 0.9f;
    scene->hasCamera = true;
    return scene;
}

// A curtain against a window: a gap-free two-faced satin (warp-faced front, weft-faced back in
// other colours, round yarns) that transmits, an area lamp behind it facing it, a grey floor on
// both sides and a weak point light in front. Nearly all the image is light through the yarns;
// BDPT's light subpaths meet the curtain's back first, so the two integrators agree only if a
// point's transmission is the same from either face.
std::shared_ptr<SceneDescription> backlitCurtainScene() {
    Material floor;
    floor.name = "floor";
    floor.baseColor = glm::vec4(glm::vec3(0.5f), 1.0f);
    Material window;
    window.name = "window";
    window.baseColor = glm::vec4(glm::vec3(0.0f), 1.0f);
    window.emission = glm::vec3(5.0f, 5.0f, 4.5f);
    window.doubleSided = false;
    Material curtain;
    curtain.name = "curtain";
    WovenParams p;
    p.pattern = {5, 1, 2};
    p.warp_color = {0.6f, 0.45f, 0.3f};
    p.weft_color = {0.35f, 0.4f, 0.55f};
    p.cy = 0.75f;
    p.transmission = 0.8f;
    p.transmission_gloss = 0.5f;
    curtain.woven = p;
    std::vector<Mesh> meshes{quad("floor", {-3, -0.5f, 3}, {3, -0.5f, 3}, {3, -0.5f, -3}, {-3, -0.5f, -3}, 0),
                             // The window faces the curtain (+z): counter-clockwise seen from +z.
                             quad("window", {-0.6f, 0.5f, -0.5f}, {0.6f, 0.5f, -0.5f}, {0.6f, 1.5f, -0.5f}, {-0.6f, 1.5f, -0.5f}, 1),
                             quad("curtain", {-1.5f, -0.5f, 0}, {1.5f, -0.5f, 0}, {1.5f, 2.5f, 0}, {-1.5f, 2.5f, 0}, 2, 12.0f)};
    auto scene = sceneWith(std::move(meshes), {floor, window, curtain});
    PunctualLight front;
    front.position = {0.8f, 1.8f, 1.5f};
    front.intensity = glm::vec3(0.3f);
    scene->lights.push_back(front);
    scene->camera.cameraToWorld = glm::inverse(glm::lookAt(glm::vec3(0.0f, 1.0f, 2.5f), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0, 1, 0)));
    scene->camera.yfov = 0.7f;
    scene->hasCamera = true;
    return scene;
}

FilmImage renderRange(std::shared_ptr<const SceneDescription> scene, const char* integrator, int64_t firstSample, int spp,
                      int width, int height, int threads = 0, SamplerKind sampler = RenderSettings().sampler) {
    RenderSettings settings;
    settings.sampler = sampler;
    settings.width = width;
    settings.height = height;
    settings.spp = spp;
    settings.firstSample = firstSample;
    settings.integrator = integrator;
    settings.seed = 11;
    settings.threads = threads;
    return render(std::move(scene), settings);
}

// Region means of an integrator with their standard errors, from two renders of disjoint sample
// ranges: per pixel, (a - b)^2 / 4 estimates the variance of the mean of the two.
struct RegionEstimate {
    std::vector<glm::dvec3> mean, standardError;
};
RegionEstimate regionMeans(const FilmImage& a, const FilmImage& b, int regionsX, int regionsY) {
    const int width = a.radiance.width, height = a.radiance.height;
    const int rw = width / regionsX, rh = height / regionsY;
    RegionEstimate e;
    for (int ry = 0; ry < regionsY; ++ry)
        for (int rx = 0; rx < regionsX; ++rx) {
            glm::dvec3 sum(0.0), variance(0.0);
            for (int y = ry * rh; y < (ry + 1) * rh; ++y)
                for (int x = rx * rw; x < (rx + 1) * rw; ++x) {
                    const glm::dvec3 va(a.radiance.at(x, y)), vb(b.radiance.at(x, y));
                    sum += 0.5 * (va + vb);
                    variance += (va - vb) * (va - vb) / 4.0;
                }
            const double n = double(rw) * rh;
            e.mean.push_back(sum / n);
            e.standardError.push_back(glm::sqrt(variance) / n);
        }
    return e;
}

// Both integrators estimate the same image: in a closed box lit by an area light and a point
// light, outdoors under a sun, a spot light and the sky, and a curtain lit through from behind.
// Region means of BDPT and PT must agree within 4.5 combined standard errors (measured, 36
// comparisons per scene: a false alarm for correct integrators has probability ~2e-4, the seeds
// are fixed) plus 1 % for the standard errors' own uncertainty with heavy-tailed glossy paths. A
// wrong MIS weight, a missing strategy or a wrong splat scale shifts regions by far more: indirect
// light is a large part of the first two images, and the curtain's light reaches the camera by a
// strategy from each side (next-event estimation from its front, light tracing from its back).
class BdptAgainstPathTracer : public ::testing::TestWithParam<std::shared_ptr<SceneDescription> (*)()> {};

TEST_P(BdptAgainstPathTracer, AgreeRegionByRegion) {
    const auto scene = GetParam()();
    constexpr int kWidth = 48, kHeight = 36;
    const RegionEstimate path = regionMeans(renderRange(scene, "path", 0, 48, kWidth, kHeight),
                                            renderRange(scene, "path", 48, 48, kWidth, kHeight), 4, 3);
    const RegionEstimate bdpt = regionMeans(renderRange(scene, "bdpt", 0, 24, kWidth, kHeight),
                                            renderRange(scene, "bdpt", 24, 24, kWidth, kHeight), 4, 3);
    for (size_t r = 0; r < path.mean.size(); ++r)
        for (int c = 0; c < 3; ++c) {
            const double se = std::hypot(path.standardError[r][c], bdpt.standardError[r][c]);
            EXPECT_GT(path.mean[r][c], 0.01) << "region " << r << " is dark: the test would prove nothing";
            EXPECT_LE(std::abs(path.mean[r][c] - bdpt.mean[r][c]), 4.5 * se + 0.01 * path.mean[r][c])
                << "region " << r << " channel " << c << ": path " << path.mean[r][c] << " +- " << path.standardError[r][c]
                << ", bdpt " << bdpt.mean[r][c] << " +- " << bdpt.standardError[r][c];
        }
}

INSTANTIATE_TEST_SUITE_P(Scenes, BdptAgainstPathTracer, ::testing::Values(&clothInBoxScene, &clothUnderSkyScene, &backlitCurtainScene),
                         [](const auto& info) {
                             return std::string(info.index == 0 ? "ClothInBox" : info.index == 1 ? "ClothUnderSky" : "BacklitCurtain");
                         });

// Each integrator with each sampler.
struct ReproducibleCase {
    const char* integrator;
    SamplerKind sampler;
};
class Reproducible : public ::testing::TestWithParam<ReproducibleCase> {
protected:
    FilmImage renderSamples(std::shared_ptr<const SceneDescription> scene, int64_t firstSample, int spp, int width,
                            int height, int threads = 0) const {
        return renderRange(std::move(scene), GetParam().integrator, firstSample, spp, width, height, threads,
                                 GetParam().sampler);
    }
};

TEST_P(Reproducible, SameSeedGivesTheSameImageWhateverTheThreadCount) {
    const auto scene = clothInBoxScene();
    const FilmImage a = renderSamples(scene, 0, 3, 24, 18, 1);
    const FilmImage b = renderSamples(scene, 0, 3, 24, 18, 2);
    const FilmImage c = renderSamples(scene, 0, 3, 24, 18, 0);
    EXPECT_EQ(a.radiance.pixels, b.radiance.pixels);
    EXPECT_EQ(a.radiance.pixels, c.radiance.pixels);
    EXPECT_EQ(a.sampleCount, std::vector<float>(24 * 18, 3.0f));
    const FilmImage other = renderSamples(scene, 3, 3, 24, 18);
    EXPECT_NE(a.radiance.pixels, other.radiance.pixels) << "another sample range must give other samples";
}

// Rendering samples [0, 3) and [3, 8) separately and adding their exact sums is the render of
// [0, 8), bit for bit, as `woven merge` does it.
TEST_P(Reproducible, DisjointSampleRangesAddUpToTheUnionExactly) {
    const auto scene = clothInBoxScene();
    const FilmImage first = renderSamples(scene, 0, 3, 24, 18);
    const FilmImage second = renderSamples(scene, 3, 5, 24, 18);
    const FilmImage all = renderSamples(scene, 0, 8, 24, 18);
    EXPECT_EQ(first.samples.first, 0);
    EXPECT_EQ(first.samples.count, 3);
    EXPECT_EQ(second.samples.first, 3);
    EXPECT_EQ(second.samples.count, 5);
    double maxValue = 0.0;
    for (const glm::vec3& v : all.radiance.pixels) maxValue = std::max<double>(maxValue, glm::max(v.x, glm::max(v.y, v.z)));
    ASSERT_GT(maxValue, 0.0);
    for (size_t i = 0; i < all.radiance.pixels.size(); ++i) {
        const float n = first.sampleCount[i] + second.sampleCount[i];
        ASSERT_EQ(n, all.sampleCount[i]);
        for (int c = 0; c < 3; ++c) {
            ExactSum sum = first.sampleSums[3 * i + size_t(c)];
            sum += second.sampleSums[3 * i + size_t(c)];
            ASSERT_EQ(sum, all.sampleSums[3 * i + size_t(c)]) << "pixel " << i;
            ASSERT_EQ(sum.mean(n), all.radiance.pixels[i][c]) << "pixel " << i;
        }
    }
}

// Sample indices are 64-bit: samples 2^32 on are not samples 0 on again, ranges across 2^32 add
// up exactly, and past 2^62 (the auto pilot's) a range is refused. Every render records its frame.
TEST_P(Reproducible, SampleIndicesPast32BitsAreTheirOwnAndAddUpExactly) {
    const auto scene = clothInBoxScene();
    const int64_t wrap = int64_t(1) << 32;
    EXPECT_NE(renderSamples(scene, wrap, 2, 12, 9).sampleSums, renderSamples(scene, 0, 2, 12, 9).sampleSums);
    const FilmImage below = renderSamples(scene, wrap - 1, 1, 12, 9);
    const FilmImage across = renderSamples(scene, wrap, 2, 12, 9);
    const FilmImage all = renderSamples(scene, wrap - 1, 3, 12, 9);
    EXPECT_EQ(all.samples.first, wrap - 1);
    EXPECT_EQ(all.samples.end(), wrap + 2);
    for (size_t i = 0; i < all.sampleSums.size(); ++i) {
        ExactSum sum = below.sampleSums[i];
        sum += across.sampleSums[i];
        ASSERT_EQ(sum, all.sampleSums[i]) << "channel " << i;
    }
    EXPECT_EQ(all.frame.scene, below.frame.scene);
    EXPECT_EQ(all.frame.scene.size(), 16u);
    EXPECT_EQ(all.frame.seed, 11u);
    EXPECT_EQ(all.frame.integrator, GetParam().integrator);
    EXPECT_EQ(all.frame.maxDepth, RenderSettings().maxDepth);
    EXPECT_FALSE(all.frame.filterWeave);

    RenderSettings settings;
    settings.firstSample = kSampleIndexLimit - 1;
    settings.spp = 2;
    EXPECT_THROW(RenderJob(scene, settings), std::invalid_argument);
}

// Adaptive sampling decides between whole passes from the film alone: the same seed gives the
// same image and the same sample counts whatever the threads, and pixels stop at different counts.
TEST_P(Reproducible, AdaptiveSamplingDecidesTheSameWhateverTheThreadCount) {
    const auto scene = clothInBoxScene();
    RenderSettings settings;
    settings.width = 24;
    settings.height = 18;
    settings.spp = 48;
    settings.integrator = GetParam().integrator;
    settings.sampler = GetParam().sampler;
    settings.noiseThreshold = 0.1;
    settings.threads = 1;
    const FilmImage a = render(scene, settings);
    settings.threads = 2;
    const FilmImage b = render(scene, settings);
    EXPECT_EQ(a.radiance.pixels, b.radiance.pixels);
    EXPECT_EQ(a.sampleCount, b.sampleCount);
    const auto [fewest, most] = std::minmax_element(a.sampleCount.begin(), a.sampleCount.end());
    EXPECT_LT(*fewest, *most) << "every pixel took the same samples: nothing was adaptive";
}

INSTANTIATE_TEST_SUITE_P(BothIntegratorsBothSamplers, Reproducible,
                         ::testing::Values(ReproducibleCase{"path", SamplerKind::Sobol}, ReproducibleCase{"bdpt", SamplerKind::Sobol},
                                           ReproducibleCase{"path", SamplerKind::Independent},
                                           ReproducibleCase{"bdpt", SamplerKind::Independent}),
                         [](const auto& info) {
                             return std::string(info.param.integrator) + "_" + samplerName(info.param.sampler);
                         });

// A pixel that stops keeps the prefix of its sequence: with adaptive sampling, each pixel's sum
// is, bit for bit, that pixel in a uniform render of as many samples, with either sampler. (The
// path tracer's pixels are their own samples alone; BDPT's also gather other pixels' light paths.)
TEST(RenderJob, AnAdaptivePixelHoldsTheFirstSamplesOfItsSequence) {
    const auto scene = clothInBoxScene();
    for (SamplerKind sampler : {SamplerKind::Sobol, SamplerKind::Independent}) {
        RenderSettings settings;
        settings.width = 24;
        settings.height = 18;
        settings.spp = 40;
        settings.integrator = "path";
        settings.sampler = sampler;
        settings.seed = 11;
        settings.noiseThreshold = 0.1;
        const FilmImage adaptive = render(scene, settings);
        const std::set<float> counts(adaptive.sampleCount.begin(), adaptive.sampleCount.end());
        ASSERT_GT(counts.size(), 1u) << "every pixel took the same samples: nothing was adaptive";
        for (float count : counts) {
            const FilmImage uniform = renderRange(scene, "path", 0, int(count), 24, 18, 0, sampler);
            for (size_t i = 0; i < adaptive.sampleCount.size(); ++i) {
                if (adaptive.sampleCount[i] != count) continue;
                for (size_t c = 0; c < 3; ++c)
                    ASSERT_EQ(adaptive.sampleSums[3 * i + c], uniform.sampleSums[3 * i + c])
                        << samplerName(sampler) << ", pixel " << i << ", " << count << " samples";
            }
        }
    }
}

// A film without the render passes (woven fit's) keeps the same radiance sums to the bit, BDPT's
// splats included.
TEST(RenderJob, WithoutPassesTheSameRadiance) {
    for (const char* integrator : {"path", "bdpt"}) {
        RenderSettings settings;
        settings.width = 24;
        settings.height = 18;
        settings.spp = 6;
        settings.integrator = integrator;
        settings.seed = 11;
        const FilmImage with = render(clothInBoxScene(), settings);
        settings.renderPasses = false;
        const FilmImage without = render(clothInBoxScene(), settings);
        EXPECT_EQ(with.passSums.size(), with.sampleCount.size()) << integrator;
        EXPECT_TRUE(without.passSums.empty()) << integrator;
        EXPECT_EQ(with.sampleCount, without.sampleCount) << integrator;
        EXPECT_TRUE(with.sampleSums == without.sampleSums) << integrator;
    }
}

TEST(RenderJob, CancelKeepsWholePassesOnly) {
    RenderSettings settings;
    settings.width = 24;
    settings.height = 18;
    settings.spp = 100;
    settings.integrator = "bdpt";
    RenderJob job(clothInBoxScene(), settings);
    std::atomic<bool> cancel{false};
    int calls = 0;
    job.run(cancel, [&](const RenderProgress& p) {
        ++calls;
        EXPECT_EQ(p.samplesDone, calls);
        EXPECT_EQ(p.samplesTotal, 100);
        EXPECT_GT(p.rays, 0u);
        if (p.samplesDone == 2) cancel = true;
    });
    EXPECT_EQ(calls, 2);
    EXPECT_EQ(job.snapshot().sampleCount, std::vector<float>(24 * 18, 2.0f));
}

TEST(RenderJob, TimeLimitStopsAfterThePassThatCrossesIt) {
    RenderSettings settings;
    settings.width = 24;
    settings.height = 18;
    settings.spp = 1000;
    settings.timeLimit = 1e-6;  // crossed by the first pass
    settings.integrator = "path";
    RenderJob job(clothInBoxScene(), settings);
    std::atomic<bool> cancel{false};
    job.run(cancel);
    EXPECT_EQ(job.snapshot().sampleCount, std::vector<float>(24 * 18, 1.0f));
}

TEST(RenderJob, AutoResolvesToAnIntegratorAndRecordsIt) {
    RenderSettings settings;
    settings.width = 24;
    settings.height = 18;
    settings.spp = 1;
    RenderJob job(clothInBoxScene(), settings);
    EXPECT_EQ(job.integratorName(), "auto");
    std::atomic<bool> cancel{false};
    job.run(cancel);
    EXPECT_TRUE(job.integratorName() == "path" || job.integratorName() == "bdpt") << job.integratorName();
}

// A tiny lamp facing the ceiling of a closed room behind a shade: everything the camera sees is
// lit only by the small bright spot above the lamp. Path tracing finds that spot by BSDF
// sampling alone (its light samples are shaded), BDPT connects light subpaths that hit it: in
// the pilot BDPT's variance per unit time is over a hundred times lower, a margin no
// scheduling noise on a loaded machine can reverse.
TEST(RenderJob, AutoPicksBdptWhenAllLightArrivesAfterABounce) {
    Material walls;
    walls.baseColor = glm::vec4(glm::vec3(0.6f), 1.0f);
    Material lamp;
    lamp.baseColor = glm::vec4(glm::vec3(0.0f), 1.0f);
    lamp.emission = glm::vec3(50.0f);
    lamp.doubleSided = false;
    std::vector<Mesh> meshes = test::boxInside({-1, 0, -1}, {1, 2, 1}, 0);
    meshes.push_back(quad("lamp", {-0.05f, 1.95f, -0.05f}, {-0.05f, 1.95f, 0.05f}, {0.05f, 1.95f, 0.05f},
                          {0.05f, 1.95f, -0.05f}, 1));  // facing up
    meshes.push_back(quad("shade", {-0.1f, 1.94f, -0.1f}, {-0.1f, 1.94f, 0.1f}, {0.1f, 1.94f, 0.1f},
                          {0.1f, 1.94f, -0.1f}, 0));
    auto scene = sceneWith(std::move(meshes), {walls, lamp});
    scene->camera.cameraToWorld =
        glm::inverse(glm::lookAt(glm::vec3(0.0f, 1.5f, 0.9f), glm::vec3(0.0f, 0.5f, -1.0f), glm::vec3(0, 1, 0)));
    scene->camera.yfov = 1.2f;
    scene->hasCamera = true;
    RenderSettings settings;
    settings.width = 160;
    settings.height = 120;
    settings.spp = 1;
    RenderJob job(scene, settings);
    std::atomic<bool> cancel{false};
    job.run(cancel);
    EXPECT_EQ(job.integratorName(), "bdpt");
}

TEST(RenderJob, SceneWithoutLightsIsAnErrorNamingTheFile) {
    auto scene = clothPlaneScene();
    try {
        RenderJob job(scene, RenderSettings{});
        FAIL() << "a scene without lights was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("test.gltf"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("scene has no lights"), std::string::npos) << e.what();
    }
}

TEST(RenderJob, UnknownIntegratorIsRejected) {
    auto scene = clothPlaneScene();
    scene->environment.color = glm::vec3(1.0f);
    RenderSettings settings;
    settings.integrator = "photon";
    EXPECT_THROW(RenderJob(scene, settings), std::invalid_argument);
}

// A scene file's render.integrator is checked against the integrators' table where a render
// takes it (the scene layer below cannot see the table): the message names the file and the key.
TEST(RenderJob, SceneFileIntegratorOutsideTheTableNamesTheFileAndKey) {
    SceneDescription scene;
    scene.source = "dir/scene.json";
    scene.render.integrator = "fast";
    try {
        defaultRenderSettings(scene);
        FAIL() << "render.integrator \"fast\" was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("dir/scene.json: render.integrator: must be"), std::string::npos) << e.what();
    }
    scene.render.integrator = "bdpt";
    EXPECT_EQ(defaultRenderSettings(scene).integrator, "bdpt");
}

TEST(RenderJob, SceneFileSamplerIsTakenAndAnUnknownOneNamesTheFileAndKey) {
    SceneDescription scene;
    scene.source = "dir/scene.json";
    EXPECT_EQ(defaultRenderSettings(scene).sampler, SamplerKind::Sobol);
    scene.render.sampler = "independent";
    EXPECT_EQ(defaultRenderSettings(scene).sampler, SamplerKind::Independent);
    scene.render.sampler = "halton";
    try {
        defaultRenderSettings(scene);
        FAIL() << "render.sampler \"halton\" was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("dir/scene.json: render.sampler: must be \"sobol\" or \"independent\", not "
                                             "\"halton\""),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace woven
