#include "light.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "math_constants.h"
#include "render_scene.h"
#include "sampling.h"
#include "spherical_rectangle.h"
#include "spherical_triangle.h"
#include "statistics.h"
#include "test_scenes.h"

namespace woven {
namespace {


// Mean and standard error of a Monte Carlo estimate. Tests accept |mean - truth| < 5 standard
// errors (plus a small absolute slack for float rounding): with fixed seeds this never flakes,
// and a wrong factor (2, pi, a missing cosine) moves the mean by hundreds of standard errors.
struct Estimate {
    double sum = 0.0, sumSq = 0.0;
    long n = 0;
    void add(double x) { sum += x; sumSq += x * x; ++n; }
    double mean() const { return sum / n; }
    double stdError() const { return std::sqrt(std::max(0.0, sumSq / n - mean() * mean()) / n); }
};
#define EXPECT_ESTIMATE(est, truth) \
    EXPECT_NEAR((est).mean(), (truth), 5.0 * (est).stdError() + 1e-6 * std::abs(truth)) << "standard error " << (est).stdError()

Bounds unitBounds() {
    Bounds b;
    b.lo = glm::vec3(-1.0f);
    b.hi = glm::vec3(1.0f);
    return b;
}

// ---------------------------------------------------------------------------------------------
// Emissive triangle

const glm::vec3 kA{-0.5f, -0.4f, 2.0f}, kB{0.7f, -0.2f, 2.3f}, kC{0.1f, 0.8f, 1.8f};
const glm::vec3 kRadiance{2.0f, 1.0f, 0.5f};

TEST(TriangleLight, SampledDirectionsHaveThePdfThatPdfLiGives) {
    const Light light = Light::triangle(kA, kB, kC, kRadiance, false);
    const glm::vec3 n = glm::normalize(glm::cross(kB - kA, kC - kA));
    const glm::vec3 front{0.2f, 0.1f, 3.0f}, behind{0.1f, 0.2f, -0.3f};
    ASSERT_GT(glm::dot(front - kA, n), 0.0f);
    ASSERT_LT(glm::dot(behind - kA, n), 0.0f);
    Rng rng(3);
    for (int i = 0; i < 2000; ++i) {
        const auto s = light.sampleLi(front, rng.uniform2());
        ASSERT_TRUE(s);
        ASSERT_NEAR(glm::length(s->wi), 1.0f, 1e-5f);
        ASSERT_NEAR(glm::length(glm::normalize(s->pLight - front) - s->wi), 0.0f, 1e-5f);
        ASSERT_NEAR(glm::length(s->nLight - n), 0.0f, 1e-5f);
        ASSERT_NEAR(s->pdf, light.pdfLi(front, s->wi, s->pLight, s->nLight), 1e-4f * s->pdf);
        ASSERT_EQ(s->L, kRadiance);
        // One-sided: only the front face (counter-clockwise winding) shines, so from behind there
        // is no sample to take.
        ASSERT_FALSE(light.sampleLi(behind, rng.uniform2()));
    }
    EXPECT_FALSE(light.isDelta());
    EXPECT_FALSE(light.isInfinite());
    const float area = 0.5f * glm::length(glm::cross(kB - kA, kC - kA));
    EXPECT_NEAR(light.power().r, kRadiance.r * area * kPi, 1e-5f);
    EXPECT_NEAR(Light::triangle(kA, kB, kC, kRadiance, true).power().r, 2.0f * kRadiance.r * area * kPi, 1e-5f);
}

// The integral of light.pdfLi() over the sphere of directions from ref, by uniform directions;
// real geometry, the light's mesh in an Embree scene, finds which of them reach it.
Estimate pdfLiIntegral(const Light& light, const Mesh& mesh, const glm::vec3& ref, uint64_t seed) {
    RenderScene scene(test::sceneWith({mesh}));
    Estimate integral;
    Rng rng(seed);
    for (int i = 0; i < 200000; ++i) {
        Ray ray;
        ray.o = ref;
        ray.d = sampleUniformSphere(rng.uniform2());
        const auto hit = scene.intersect(ray);
        integral.add(hit ? 4.0 * kPi * light.pdfLi(ref, ray.d, hit->p, hit->ng) : 0.0);
    }
    return integral;
}

TEST(TriangleLight, PdfLiIntegratesToOneOverTheDirectionsThatReachIt) {
    Mesh mesh;
    mesh.name = "emitter";
    mesh.positions = {kA, kB, kC};
    mesh.triangles = {glm::uvec3(0, 1, 2)};
    const Estimate integral = pdfLiIntegral(Light::triangle(kA, kB, kC, kRadiance, false), mesh, {0.1f, 0.2f, -0.3f}, 4);
    EXPECT_ESTIMATE(integral, 1.0);
}

// Irradiance at a point with normal n from a polygon of uniform radiance L: Lambert's formula
// E = L / 2 * sum_i angle(v_i, v_i+1) * n . normalize(v_i x v_i+1), v_i the unit directions to
// the vertices (valid when the polygon lies wholly above the point's tangent plane).
double lambertIrradiance(const glm::dvec3& p, const glm::dvec3& n, const std::vector<glm::dvec3>& polygon, double L) {
    double sum = 0.0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3 a = glm::normalize(polygon[i] - p), b = glm::normalize(polygon[(i + 1) % polygon.size()] - p);
        sum += std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(glm::cross(a, b)));
    }
    return 0.5 * L * std::abs(sum);
}

TEST(TriangleLight, IrradianceMatchesLambertsFormula) {
    const Light light = Light::triangle(kA, kB, kC, kRadiance, true);
    const glm::vec3 ref{0.3f, -0.2f, 0.4f};
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f));
    const double expected = lambertIrradiance(ref, n, {kA, kB, kC}, kRadiance.r);
    Estimate E;
    Rng rng(5);
    for (int i = 0; i < 100000; ++i) {
        const auto s = light.sampleLi(ref, rng.uniform2());
        ASSERT_TRUE(s);
        E.add(s->L.r * std::max(0.0f, glm::dot(n, s->wi)) / s->pdf);
    }
    EXPECT_ESTIMATE(E, expected);
    EXPECT_GT(expected, 0.1);  // the configuration is not trivially dark
}

// A point just off the triangle's plane and beside it, as a ceiling beside a lamp hung just
// below it: there sampleLi() samples by solid angle.
const glm::vec3 kNearPlane = 0.6f * kA + 0.5f * kB - 0.1f * kC + 0.01f * glm::normalize(glm::cross(kB - kA, kC - kA));

TEST(SphericalTriangle, DirectionsAreUniformOverTheSolidAngle) {
    // The triangle cut into the n^2 = 64 sub-triangles of a barycentric grid, each of which
    // should receive samples in proportion to its solid angle: from near its plane, from afar
    // and from where it fills most of the view.
    const int n = 8;
    std::vector<double> expected(size_t(n * n), 0.0), observed(size_t(n * n), 0.0);
    const auto corner = [&](int i, int j) { return kA + (float(i) / n) * (kB - kA) + (float(j) / n) * (kC - kA); };
    for (const glm::vec3& ref : {kNearPlane, glm::vec3(0.1f, 0.2f, -0.3f), glm::vec3(0.1f, 0.15f, 2.05f)}) {
        const float solidAngle = triangleSolidAngle(kA, kB, kC, ref);
        ASSERT_GT(solidAngle, kMinSphericalSampleArea);
        ASSERT_LT(solidAngle, kMaxSphericalSampleArea);
        const int count = 200000;
        std::fill(expected.begin(), expected.end(), 0.0);
        std::fill(observed.begin(), observed.end(), 0.0);
        for (int i = 0, k = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j) {
                expected[size_t(k++)] = count * triangleSolidAngle(corner(i, j), corner(i + 1, j), corner(i, j + 1), ref) / solidAngle;
                if (i + j + 1 < n)
                    expected[size_t(k++)] =
                        count * triangleSolidAngle(corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1), ref) / solidAngle;
            }
        Rng rng(12);
        for (int s = 0; s < count; ++s) {
            const auto b = sampleSphericalTriangle(kA, kB, kC, ref, solidAngle, rng.uniform2());
            ASSERT_TRUE(b);
            ASSERT_GE(b->x, 0.0f);
            ASSERT_GE(b->y, 0.0f);
            ASSERT_LE(b->x + b->y, 1.0f + 1e-6f);
            // The same cell numbering as above: row i, then the lower and upper triangle of each j.
            const int i = std::min(n - 1, int(b->x * n)), j = std::min(n - 1 - i, int(b->y * n));
            const bool upper = b->x * n - i + (b->y * n - j) > 1.0f && i + j + 1 < n;
            int k = 0;
            for (int r = 0; r < i; ++r) k += 2 * (n - r) - 1;
            observed[size_t(k + 2 * j + (upper ? 1 : 0))] += 1.0;
        }
        EXPECT_LT(test::chiSquareZ(observed, expected), 4.0) << "from " << ref.x << " " << ref.y << " " << ref.z;
    }
}

TEST(TriangleLight, NearItsPlaneSamplesBySolidAngleWithBoundedVariance) {
    const Light light = Light::triangle(kA, kB, kC, kRadiance, true);
    const glm::vec3 far{0.1f, 0.2f, -0.3f};
    const auto nearSample = light.sampleLi(kNearPlane, glm::vec2(0.3f, 0.6f));
    const auto farSample = light.sampleLi(far, glm::vec2(0.3f, 0.6f));
    ASSERT_TRUE(nearSample && farSample);
    EXPECT_FLOAT_EQ(nearSample->pdf, 1.0f / triangleSolidAngle(kA, kB, kC, kNearPlane));
    EXPECT_GT(std::abs(farSample->pdf * triangleSolidAngle(kA, kB, kC, far) - 1.0f), 1e-3f);  // by area
    // The irradiance of a surface through kNearPlane, parallel to the triangle and facing it,
    // whose estimate by area sampling has a relative deviation per sample of about 10 here; by
    // solid angle it is the cosine's alone, under 1.
    const glm::vec3 n = -glm::normalize(glm::cross(kB - kA, kC - kA));
    const double expected = lambertIrradiance(kNearPlane, n, {kA, kB, kC}, kRadiance.r);
    Estimate E;
    Rng rng(13);
    for (int i = 0; i < 100000; ++i) {
        const auto s = light.sampleLi(kNearPlane, rng.uniform2());
        ASSERT_TRUE(s);
        ASSERT_NEAR(s->pdf, light.pdfLi(kNearPlane, s->wi, s->pLight, s->nLight), 1e-4f * s->pdf);
        ASSERT_NEAR(glm::length(glm::normalize(s->pLight - kNearPlane) - s->wi), 0.0f, 1e-5f);
        E.add(s->L.r * std::max(0.0f, glm::dot(n, s->wi)) / s->pdf);
    }
    EXPECT_ESTIMATE(E, expected);
    EXPECT_LT(E.stdError() * std::sqrt(double(E.n)) / E.mean(), 1.0);
}

TEST(TriangleLight, EmissionSamplesMatchPdfLeAndCarryThePower) {
    for (bool twoSided : {false, true}) {
        const Light light = Light::triangle(kA, kB, kC, kRadiance, twoSided);
        const glm::vec3 n = glm::normalize(glm::cross(kB - kA, kC - kA));
        Estimate flux;
        int backward = 0;
        Rng rng(6);
        const int count = 50000;
        for (int i = 0; i < count; ++i) {
            const auto s = light.sampleLe(rng.uniform2(), rng.uniform2());
            ASSERT_TRUE(s);
            // The origin lies on the triangle's plane, the ray leaves on nLight's side.
            ASSERT_NEAR(glm::dot(s->ray.o - kA, n), 0.0f, 1e-5f);
            ASSERT_GT(glm::dot(s->ray.d, s->nLight), 0.0f);
            if (glm::dot(s->ray.d, n) < 0.0f) ++backward;
            float pdfPos, pdfDir;
            light.pdfLe(s->ray, s->nLight, &pdfPos, &pdfDir);
            ASSERT_NEAR(pdfPos, s->pdfPos, 1e-5f * pdfPos);
            ASSERT_NEAR(pdfDir, s->pdfDir, 1e-4f * pdfDir + 1e-7f);
            flux.add(s->L.r * glm::dot(s->ray.d, s->nLight) / (s->pdfPos * s->pdfDir));
        }
        if (twoSided) EXPECT_NEAR(backward, count / 2, 5 * std::sqrt(count / 4.0));  // binomial, 5 sigma
        else EXPECT_EQ(backward, 0);
        EXPECT_ESTIMATE(flux, light.power().r);
    }
}

// ---------------------------------------------------------------------------------------------
// Emissive rectangle

// A tilted 1.2 x 0.8 rectangle: kEx and kEy orthogonal, its front (kEx x kEy) facing up (+z).
const glm::vec3 kCorner{-0.5f, -0.4f, 2.0f}, kEx{1.2f, 0.0f, 0.3f}, kEy{0.0f, 0.8f, 0.0f};
std::vector<glm::dvec3> rectangleCorners() { return {kCorner, kCorner + kEx, kCorner + kEx + kEy, kCorner + kEy}; }
// Beside the rectangle, 1 cm off its plane on its front side: sampled by solid angle there.
const glm::vec3 kBesideRectangle = kCorner + 1.3f * kEx + 0.5f * kEy + 0.01f * glm::normalize(glm::cross(kEx, kEy));

TEST(SphericalRectangle, SolidAngleIsItsTwoTrianglesAndDirectionsAreUniformOverIt) {
    // The rectangle cut into an 8 x 8 grid, each cell of which should receive samples in
    // proportion to its solid angle: from beside it near its plane, from afar, from behind it and
    // from where it fills most of the view.
    const int n = 8;
    const auto at = [&](int i, int j) { return kCorner + (float(i) / n) * kEx + (float(j) / n) * kEy; };
    const glm::vec3 front = glm::normalize(glm::cross(kEx, kEy));
    for (const glm::vec3& ref : {kBesideRectangle, glm::vec3(0.1f, 0.2f, -0.3f), glm::vec3(0.2f, 0.1f, 3.0f),
                                 kCorner + 0.5f * (kEx + kEy) + 0.05f * front}) {
        const SphericalRectangle rectangle(kCorner, kEx, kEy, ref);
        const float solidAngle = rectangle.solidAngle();
        EXPECT_NEAR(solidAngle, triangleSolidAngle(at(0, 0), at(n, 0), at(n, n), ref) +
                                    triangleSolidAngle(at(0, 0), at(n, n), at(0, n), ref), 1e-4f * solidAngle);
        const int count = 200000;
        std::vector<double> expected, observed(size_t(n * n), 0.0);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                expected.push_back(count * double(SphericalRectangle(at(i, j), kEx / float(n), kEy / float(n), ref).solidAngle()) /
                                   solidAngle);
        Rng rng(14);
        for (int s = 0; s < count; ++s) {
            const glm::vec3 p = rectangle.sample(rng.uniform2());
            const glm::vec3 local = p - kCorner;
            ASSERT_NEAR(glm::dot(local, front), 0.0f, 1e-5f);
            const float x = glm::dot(local, kEx) / glm::dot(kEx, kEx), y = glm::dot(local, kEy) / glm::dot(kEy, kEy);
            ASSERT_GE(x, -1e-6f);
            ASSERT_LE(x, 1.0f + 1e-6f);
            ASSERT_GE(y, -1e-6f);
            ASSERT_LE(y, 1.0f + 1e-6f);
            observed[size_t(std::clamp(int(x * n), 0, n - 1) * n + std::clamp(int(y * n), 0, n - 1))] += 1.0;
        }
        EXPECT_LT(test::chiSquareZ(observed, expected), 4.0) << "from " << ref.x << " " << ref.y << " " << ref.z;
    }
    // From a point in its plane it subtends nothing.
    EXPECT_EQ(SphericalRectangle(kCorner, kEx, kEy, kCorner + 2.0f * kEx).solidAngle(), 0.0f);
}

// The solid angle of triangle (a, b, c) from p in double precision (Van Oosterom and Strackee).
double solidAngleInDouble(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& p) {
    const glm::dvec3 da = glm::normalize(a - p), db = glm::normalize(b - p), dc = glm::normalize(c - p);
    return std::abs(2.0 * std::atan2(glm::dot(da, glm::cross(db, dc)), 1.0 + glm::dot(da, db) + glm::dot(da, dc) + glm::dot(db, dc)));
}

TEST(SphericalRectangle, SolidAngleIsAccurateJustOffThePlane) {
    // Beside the lamp and 1 cm, 1 mm and 0.3 mm off its plane, the spherical rectangle is a
    // sliver whose angles are near 0 and pi, where acos(dot) loses most of a float's digits (26 %
    // of the solid angle at 1 mm). The rectangle is 1.2 x 0.8.
    const glm::dvec3 front = glm::normalize(glm::cross(glm::dvec3(kEx), glm::dvec3(kEy)));
    for (double height : {1e-2, 1e-3, 3e-4}) {
        const glm::dvec3 ref = glm::dvec3(kCorner) + 1.3 * glm::dvec3(kEx) + 0.5 * glm::dvec3(kEy) + height * front;
        const glm::dvec3 c0 = kCorner, c1 = kCorner + kEx, c2 = kCorner + kEx + kEy, c3 = kCorner + kEy;
        const double truth = solidAngleInDouble(c0, c1, c2, ref) + solidAngleInDouble(c0, c2, c3, ref);
        const float solidAngle = SphericalRectangle(kCorner, kEx, kEy, glm::vec3(ref)).solidAngle();
        EXPECT_NEAR(solidAngle / truth, 1.0, 2e-3) << "at " << height << " m, truth " << truth;
    }
}

TEST(RectangleLight, SampledPointsHaveThePdfThatPdfLiGivesAndLieOnIt) {
    const Light light = Light::rectangle(kCorner, kEx, kEy, kRadiance, false);
    const glm::vec3 n = glm::normalize(glm::cross(kEx, kEy));
    for (const glm::vec3& ref : {kBesideRectangle, glm::vec3(0.1f, 0.2f, -0.3f), glm::vec3(0.2f, 0.1f, 3.0f)}) {
        const bool refInFront = glm::dot(ref - kCorner, n) > 0.0f;
        Rng rng(15);
        for (int i = 0; i < 2000; ++i) {
            const auto s = light.sampleLi(ref, rng.uniform2());
            ASSERT_EQ(bool(s), refInFront);  // one-sided: no sample from behind
            if (!s) continue;
            ASSERT_NEAR(glm::length(glm::normalize(s->pLight - ref) - s->wi), 0.0f, 1e-5f);
            ASSERT_NEAR(glm::dot(s->pLight - kCorner, n), 0.0f, 1e-5f);
            ASSERT_NEAR(glm::length(s->nLight - n), 0.0f, 1e-5f);
            ASSERT_NEAR(s->pdf, light.pdfLi(ref, s->wi, s->pLight, s->nLight), 1e-4f * s->pdf);
            ASSERT_EQ(s->L, kRadiance);
        }
    }
    const float area = glm::length(glm::cross(kEx, kEy));
    EXPECT_NEAR(light.power().r, kRadiance.r * area * kPi, 1e-5f);
    EXPECT_NEAR(Light::rectangle(kCorner, kEx, kEy, kRadiance, true).power().r, 2.0f * kRadiance.r * area * kPi, 1e-5f);
    EXPECT_FALSE(light.isDelta());
    ASSERT_NE(light.planar(), nullptr);
}

TEST(RectangleLight, PdfLiIntegratesToOneOverTheDirectionsThatReachIt) {
    Mesh mesh;
    mesh.name = "emitter";
    mesh.positions = {kCorner, kCorner + kEx, kCorner + kEx + kEy, kCorner + kEy};
    mesh.triangles = {glm::uvec3(0, 1, 2), glm::uvec3(0, 2, 3)};
    const Light light = Light::rectangle(kCorner, kEx, kEy, kRadiance, true);
    for (const glm::vec3& ref : {kBesideRectangle, glm::vec3(0.1f, 0.2f, -0.3f)}) {
        const Estimate integral = pdfLiIntegral(light, mesh, ref, 16);
        EXPECT_ESTIMATE(integral, 1.0);
    }
}

TEST(RectangleLight, IrradianceMatchesLambertsFormulaWithLowVarianceNearItsPlane) {
    const Light light = Light::rectangle(kCorner, kEx, kEy, kRadiance, true);
    // A surface beside the lamp, facing it and tilted towards it, as a ceiling beside a lamp hung
    // just below it; and one far below.
    const glm::vec3 front = glm::normalize(glm::cross(kEx, kEy));
    const struct {
        glm::vec3 p, n;
        bool nearPlane;
    } cases[] = {{kBesideRectangle, glm::normalize(-front - 0.3f * glm::normalize(kEx)), true},
                 {glm::vec3(0.3f, -0.2f, 0.4f), glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f)), false}};
    for (const auto& c : cases) {
        const double expected = lambertIrradiance(c.p, c.n, rectangleCorners(), kRadiance.r);
        Estimate E;
        Rng rng(17);
        for (int i = 0; i < 100000; ++i) {
            const auto s = light.sampleLi(c.p, rng.uniform2());
            ASSERT_TRUE(s);
            E.add(s->L.r * std::max(0.0f, glm::dot(c.n, s->wi)) / s->pdf);
        }
        EXPECT_ESTIMATE(E, expected);
        EXPECT_GT(expected, 0.01);
        // By solid angle, the relative deviation of a sample is the cosine's alone, under 1; by
        // area from beside the lamp it would be several.
        if (c.nearPlane) {
            EXPECT_LT(E.stdError() * std::sqrt(double(E.n)) / E.mean(), 1.0);
        }
    }
}

TEST(RectangleLight, EmissionSamplesMatchPdfLeAndCarryThePower) {
    for (bool twoSided : {false, true}) {
        const Light light = Light::rectangle(kCorner, kEx, kEy, kRadiance, twoSided);
        const glm::vec3 n = glm::normalize(glm::cross(kEx, kEy));
        Estimate flux;
        Rng rng(18);
        for (int i = 0; i < 50000; ++i) {
            const auto s = light.sampleLe(rng.uniform2(), rng.uniform2());
            ASSERT_TRUE(s);
            ASSERT_NEAR(glm::dot(s->ray.o - kCorner, n), 0.0f, 1e-5f);
            ASSERT_GT(glm::dot(s->ray.d, s->nLight), 0.0f);
            if (!twoSided) {
                ASSERT_GT(glm::dot(s->ray.d, n), 0.0f);
            }
            float pdfPos, pdfDir;
            light.pdfLe(s->ray, s->nLight, &pdfPos, &pdfDir);
            ASSERT_NEAR(pdfPos, s->pdfPos, 1e-5f * pdfPos);
            ASSERT_NEAR(pdfDir, s->pdfDir, 1e-4f * pdfDir + 1e-7f);
            flux.add(s->L.r * glm::dot(s->ray.d, s->nLight) / (s->pdfPos * s->pdfDir));
        }
        EXPECT_ESTIMATE(flux, light.power().r);
    }
}

// ---------------------------------------------------------------------------------------------
// Point and spot

TEST(PointLight, InverseSquareRadianceAndUniformEmission) {
    PunctualLight p;
    p.type = PunctualLight::Type::Point;
    p.position = {1.0f, 2.0f, 3.0f};
    p.intensity = {4.0f, 2.0f, 1.0f};
    const Light light = Light::punctual(p);
    EXPECT_TRUE(light.isDeltaPosition());
    const auto s = light.sampleLi({1.0f, 2.0f, 1.0f}, {0.3f, 0.7f});
    ASSERT_TRUE(s);
    EXPECT_EQ(s->wi, glm::vec3(0, 0, 1));
    EXPECT_EQ(s->pLight, p.position);
    EXPECT_FLOAT_EQ(s->pdf, 1.0f);
    EXPECT_NEAR(s->L.r, 4.0f / 4.0f, 1e-6f);  // distance 2
    EXPECT_EQ(light.pdfLi({1.0f, 2.0f, 1.0f}, s->wi, s->pLight, s->nLight), 0.0f);
    EXPECT_NEAR(light.power().r, 4.0f * kPi * 4.0f, 1e-4f);
    Estimate flux;
    Rng rng(7);
    for (int i = 0; i < 20000; ++i) {
        const auto e = light.sampleLe(rng.uniform2(), rng.uniform2());
        ASSERT_TRUE(e);
        ASSERT_EQ(e->ray.o, p.position);
        float pdfPos, pdfDir;
        light.pdfLe(e->ray, e->nLight, &pdfPos, &pdfDir);
        ASSERT_NEAR(pdfDir, e->pdfDir, 1e-6f);
        flux.add(e->L.r / e->pdfDir);
    }
    EXPECT_ESTIMATE(flux, light.power().r);
}

// KHR_lights_punctual's recommended falloff, written out from the specification.
float gltfSpotFalloff(float cosTheta, float inner, float outer) {
    const float scale = 1.0f / std::max(0.001f, std::cos(inner) - std::cos(outer));
    const float offset = -std::cos(outer) * scale;
    const float f = glm::clamp(cosTheta * scale + offset, 0.0f, 1.0f);
    return f * f;
}

PunctualLight spot() {
    PunctualLight p;
    p.type = PunctualLight::Type::Spot;
    p.position = {0.0f, 1.0f, 0.0f};
    p.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
    p.intensity = glm::vec3(3.0f);
    p.innerConeAngle = 0.3f;
    p.outerConeAngle = 0.6f;
    return p;
}

TEST(SpotLight, SmoothFalloffBetweenTheConesAndPowerIsItsIntegral) {
    const PunctualLight p = spot();
    const Light light = Light::punctual(p);
    const Frame frame = Frame::fromNormal(p.direction);
    for (float angle : {0.0f, 0.2f, 0.3f, 0.35f, 0.45f, 0.55f, 0.6f, 0.7f, 1.5f}) {
        const glm::vec3 out = frame.toWorld({std::sin(angle), 0.0f, std::cos(angle)});
        const glm::vec3 ref = p.position + 2.0f * out;
        const auto s = light.sampleLi(ref, {0.5f, 0.5f});
        ASSERT_TRUE(s);
        EXPECT_NEAR(s->L.r, 3.0f / 4.0f * gltfSpotFalloff(std::cos(angle), p.innerConeAngle, p.outerConeAngle), 1e-5f)
            << "angle " << angle;
    }
    // Power = intensity times the falloff's integral over the sphere, estimated from sampleLi
    // around the light at unit distance.
    Estimate power;
    Rng rng(8);
    for (int i = 0; i < 200000; ++i) {
        const auto s = light.sampleLi(p.position + sampleUniformSphere(rng.uniform2()), {0.5f, 0.5f});
        power.add(4.0 * kPi * s->L.r);
    }
    EXPECT_ESTIMATE(power, light.power().r);
}

TEST(SpotLight, EmissionStaysInTheOuterConeAndMatchesPdfLe) {
    const PunctualLight p = spot();
    const Light light = Light::punctual(p);
    Estimate flux;
    Rng rng(9);
    for (int i = 0; i < 100000; ++i) {
        const auto e = light.sampleLe(rng.uniform2(), rng.uniform2());
        ASSERT_TRUE(e);
        ASSERT_GE(glm::dot(e->ray.d, p.direction), std::cos(p.outerConeAngle) - 1e-5f);
        float pdfPos, pdfDir;
        light.pdfLe(e->ray, e->nLight, &pdfPos, &pdfDir);
        ASSERT_NEAR(pdfDir, e->pdfDir, 1e-5f * pdfDir);
        ASSERT_NEAR(e->L.r, 3.0f * gltfSpotFalloff(glm::dot(e->ray.d, p.direction), p.innerConeAngle, p.outerConeAngle), 1e-4f);
        flux.add(e->L.r / e->pdfDir);
    }
    EXPECT_ESTIMATE(flux, light.power().r);
    Ray outside;
    outside.o = p.position;
    outside.d = -p.direction;
    float pdfPos, pdfDir;
    light.pdfLe(outside, glm::vec3(0.0f), &pdfPos, &pdfDir);
    EXPECT_EQ(pdfDir, 0.0f);
}

// ---------------------------------------------------------------------------------------------
// Directional

TEST(DirectionalLight, ArrivesFromOneDirectionAndEmitsFromADiskCoveringTheScene) {
    PunctualLight p;
    p.type = PunctualLight::Type::Directional;
    p.direction = glm::normalize(glm::vec3(1.0f, -2.0f, 0.5f));
    p.intensity = glm::vec3(5.0f);
    Light light = Light::punctual(p);
    Bounds bounds;
    bounds.lo = glm::vec3(-1.0f, 0.0f, -2.0f);
    bounds.hi = glm::vec3(3.0f, 2.0f, 2.0f);
    light.setSceneBounds(bounds);
    const float r = bounds.radius();
    EXPECT_TRUE(light.isDeltaDirection());
    EXPECT_TRUE(light.isInfinite());
    const glm::vec3 ref{0.5f, 0.5f, 0.5f};
    const auto s = light.sampleLi(ref, {0.2f, 0.9f});
    ASSERT_TRUE(s);
    EXPECT_NEAR(glm::length(s->wi + p.direction), 0.0f, 1e-6f);
    EXPECT_EQ(s->L, glm::vec3(5.0f));
    EXPECT_GE(glm::distance(s->pLight, ref), 2.0f * r - 1e-4f);  // beyond anything in the scene
    EXPECT_NEAR(light.power().r, 5.0f * kPi * r * r, 1e-3f);
    Rng rng(10);
    for (int i = 0; i < 2000; ++i) {
        const auto e = light.sampleLe(rng.uniform2(), rng.uniform2());
        ASSERT_TRUE(e);
        ASSERT_NEAR(glm::length(e->ray.d - p.direction), 0.0f, 1e-5f);
        // Starts outside the bounding sphere and passes within its radius of the centre.
        const glm::vec3 toCentre = bounds.centre() - e->ray.o;
        ASSERT_GE(glm::length(toCentre), r * (1.0f - 1e-5f));
        ASSERT_LE(glm::length(toCentre - glm::dot(toCentre, e->ray.d) * e->ray.d), r * (1.0f + 1e-5f));
        ASSERT_NEAR(e->pdfPos, 1.0f / (kPi * r * r), 1e-6f);
        float pdfPos, pdfDir;
        light.pdfLe(e->ray, e->nLight, &pdfPos, &pdfDir);
        ASSERT_NEAR(pdfPos, e->pdfPos, 1e-6f);
    }
}

// ---------------------------------------------------------------------------------------------
// Environment

// The image convention of scene_description.h, written out independently: theta = pi v from +y,
// phi = 2 pi u from -z towards +x.
glm::vec3 conventionDirection(float u, float v) {
    const float theta = kPi * v, phi = 2.0f * kPi * u;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// 32 x 16, every pixel distinct, a bright "sun", a dark band and a black pixel.
std::shared_ptr<Image> testEnvironmentImage() {
    auto image = std::make_shared<Image>();
    image->width = 32;
    image->height = 16;
    image->pixels.resize(32 * 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x) image->at(x, y) = glm::vec3(0.1f + 0.01f * x, 0.05f + 0.02f * y, 0.2f + 0.001f * (x * y));
    image->at(9, 5) = glm::vec3(80.0f, 60.0f, 40.0f);
    for (int x = 0; x < 32; ++x) image->at(x, 12) *= 0.01f;
    image->at(3, 3) = glm::vec3(0.0f);
    return image;
}

// The integral of radiance over the sphere, in closed form: each pixel spans 2 pi / W in phi and
// [pi y / H, pi (y + 1) / H] in theta.
glm::dvec3 imageRadianceIntegral(const Image& image, const glm::vec3& color) {
    glm::dvec3 sum(0.0);
    for (int y = 0; y < image.height; ++y) {
        const double solidAngle = 2.0 * M_PI / image.width *
                                  (std::cos(M_PI * y / image.height) - std::cos(M_PI * (y + 1) / image.height));
        for (int x = 0; x < image.width; ++x) sum += glm::dvec3(image.at(x, y)) * solidAngle;
    }
    return sum * glm::dvec3(color);
}

TEST(EnvironmentLight, ImageConventionAndRotation) {
    // The convention's cardinal points.
    EXPECT_NEAR(glm::length(conventionDirection(0.0f, 0.5f) - glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(conventionDirection(0.25f, 0.5f) - glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(conventionDirection(0.3f, 0.0f) - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    Environment env;
    env.color = glm::vec3(2.0f);
    env.image = testEnvironmentImage();
    const Light light = Light::environment(env);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 32; ++x)
            ASSERT_EQ(light.Le(conventionDirection((x + 0.5f) / 32, (y + 0.5f) / 16)), 2.0f * env.image->at(x, y))
                << x << ", " << y;
    // A quarter turn about +y by the right-hand rule carries the image's -z to world -x.
    env.rotation = 0.5f * kPi;
    const Light turned = Light::environment(env);
    const glm::vec3 seenAtMinusZ = light.Le(glm::normalize(glm::vec3(0.01f, 0.3f, -1.0f)));
    EXPECT_EQ(turned.Le(glm::normalize(glm::vec3(-1.0f, 0.3f, -0.01f))), seenAtMinusZ);
    // A degenerate direction still reads a pixel, never outside the image.
    EXPECT_TRUE(std::isfinite(light.Le(glm::vec3(0.0f)).r));
    EXPECT_TRUE(std::isfinite(light.pdfLi(glm::vec3(0.0f), glm::vec3(0.0f), {}, {})));
}

TEST(EnvironmentLight, ConstantColourIsUniform) {
    Environment env;
    env.color = {0.5f, 1.0f, 2.0f};
    Light light = Light::environment(env);
    light.setSceneBounds(unitBounds());
    EXPECT_TRUE(light.isInfinite());
    EXPECT_FALSE(light.isDelta());
    Rng rng(11);
    for (int i = 0; i < 100; ++i) {
        const auto s = light.sampleLi(glm::vec3(0.0f), rng.uniform2());
        ASSERT_TRUE(s);
        ASSERT_EQ(s->L, env.color);
        ASSERT_NEAR(s->pdf, 1.0f / (4.0f * kPi), 1e-6f);
        ASSERT_NEAR(light.pdfLi(glm::vec3(0.0f), s->wi, s->pLight, s->nLight), s->pdf, 1e-6f);
    }
    // Flux onto the bounding sphere: 4 pi^2 r^2 L.
    EXPECT_NEAR(light.power().g, 4.0f * kPi * kPi * 3.0f * 1.0f, 1e-3f);
}

class ImageEnvironment : public ::testing::Test {
protected:
    void SetUp() override {
        env.color = glm::vec3(1.5f);
        env.image = testEnvironmentImage();
        env.rotation = 0.7f;
        light = Light::environment(env);
        light.setSceneBounds(unitBounds());
    }
    Environment env;
    Light light = Light::environment(Environment{});
};

TEST_F(ImageEnvironment, SampledPdfMatchesPdfLiAndIntegratesToOne) {
    Rng rng(12);
    for (int i = 0; i < 20000; ++i) {
        const auto s = light.sampleLi(glm::vec3(0.3f), rng.uniform2());
        ASSERT_TRUE(s);
        ASSERT_NEAR(light.pdfLi(glm::vec3(0.3f), s->wi, s->pLight, s->nLight), s->pdf, 1e-4f * s->pdf);
        ASSERT_EQ(s->L, light.Le(s->wi));
        ASSERT_GT(glm::dot(s->L, s->L), 0.0f) << "sampled where the image is black";
    }
    Estimate integral;
    for (int i = 0; i < 200000; ++i) integral.add(4.0 * kPi * light.pdfLi(glm::vec3(0.0f), sampleUniformSphere(rng.uniform2()), {}, {}));
    EXPECT_ESTIMATE(integral, 1.0);
}

TEST_F(ImageEnvironment, ImportanceSampledRadianceIntegratesToTheImagesIntegral) {
    const glm::dvec3 expected = imageRadianceIntegral(*env.image, env.color);
    Estimate red, blue;
    Rng rng(13);
    for (int i = 0; i < 100000; ++i) {
        const auto s = light.sampleLi(glm::vec3(0.0f), rng.uniform2());
        ASSERT_TRUE(s);
        red.add(s->L.r / s->pdf);
        blue.add(s->L.b / s->pdf);
    }
    EXPECT_ESTIMATE(red, expected.r);
    EXPECT_ESTIMATE(blue, expected.b);
    // Importance sampling pays: the estimate's relative error per sample is far below uniform
    // sampling's (whose relative standard deviation is about 9 here because of the sun).
    EXPECT_LT(red.stdError() * std::sqrt(double(red.n)) / red.mean(), 1.0);
    // Power: the flux onto the bounding sphere, 4 pi^2 r^2 times the mean radiance = pi r^2 x the integral.
    const float r = unitBounds().radius();
    EXPECT_NEAR(light.power().r, kPi * r * r * expected.r, 1e-3 * kPi * r * r * expected.r);
}

TEST_F(ImageEnvironment, SampledPixelsFollowBrightnessTimesSinTheta) {
    // Unrotated, so the sampled direction maps back to its pixel through the convention.
    env.rotation = 0.0f;
    light = Light::environment(env);
    light.setSceneBounds(unitBounds());
    const Image& image = *env.image;
    std::vector<double> weight(image.pixels.size());
    double total = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3& p = image.at(x, y);
            total += weight[y * image.width + x] = (p.r + p.g + p.b) / 3.0 * std::sin(M_PI * (y + 0.5) / image.height);
        }
    const int n = 400000;
    std::vector<double> observed(weight.size(), 0.0), expected(weight.size());
    for (size_t i = 0; i < weight.size(); ++i) expected[i] = n * weight[i] / total;
    Rng rng(14);
    for (int i = 0; i < n; ++i) {
        const auto s = light.sampleLi(glm::vec3(0.0f), rng.uniform2());
        ASSERT_TRUE(s);
        float phi = std::atan2(s->wi.x, -s->wi.z);
        if (phi < 0.0f) phi += 2.0f * kPi;
        const int x = std::min(int(phi / (2.0f * kPi) * image.width), image.width - 1);
        const int y = std::min(int(std::acos(glm::clamp(s->wi.y, -1.0f, 1.0f)) / kPi * image.height), image.height - 1);
        observed[y * image.width + x] += 1.0;
    }
    EXPECT_LT(test::chiSquareZ(observed, expected), 4.0);
}

TEST_F(ImageEnvironment, EmissionRaysMatchPdfLeAndCarryThePower) {
    const glm::dvec3 expected = imageRadianceIntegral(*env.image, env.color);
    const Bounds b = unitBounds();
    const float r = b.radius();
    Estimate flux;
    Rng rng(15);
    for (int i = 0; i < 100000; ++i) {
        const auto e = light.sampleLe(rng.uniform2(), rng.uniform2());
        ASSERT_TRUE(e);
        const glm::vec3 toCentre = b.centre() - e->ray.o;
        ASSERT_LE(glm::length(toCentre - glm::dot(toCentre, e->ray.d) * e->ray.d), r * (1.0f + 1e-5f));
        ASSERT_EQ(e->L, light.Le(-e->ray.d));
        float pdfPos, pdfDir;
        light.pdfLe(e->ray, e->nLight, &pdfPos, &pdfDir);
        ASSERT_NEAR(pdfPos, e->pdfPos, 1e-6f * pdfPos);
        ASSERT_NEAR(pdfDir, e->pdfDir, 1e-4f * pdfDir);
        flux.add(e->L.g / (e->pdfPos * e->pdfDir));
    }
    // Flux through the disk: pi r^2 times the radiance integral.
    EXPECT_ESTIMATE(flux, kPi * r * r * expected.g);
}

}  // namespace
}  // namespace woven
