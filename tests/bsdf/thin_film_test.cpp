// KHR_materials_iridescence's thin-film Fresnel (core/bsdf/thin_film.h) against a reference
// written here in double from the extension's implementation notes (Belcour and Barla 2017's
// two interfaces with Schlick reflectances, phase shifts of 0 or pi, the first two orders of the
// spectral Fourier series with the Gaussian fits of the CIE sensitivities), and GltfBxdf's
// specular lobe with the film mixed in by the iridescence factor.
//
// Tolerance: the code works in float. The phase of the cosines is 2 pi OPD x 1.8e6 / 1e9, about
// 10 radians at 800 nm, so a float's relative 6e-8 error in OPD moves a cosine by 1e-6; the
// sensitivities' sums of terms near 1 lose a few float digits to cancellation; over the ~60
// operations 2e-5 absolute covers the worst case (the largest error observed is printed) and a
// wrong formula (an OPD with cos theta1 instead of cos theta2, a missing phase shift, one
// Fourier order instead of two, Rec. 709 rows for columns) moves the reflectance by 1e-2 or more.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gltf_bxdf.h"
#include "reference_gltf_brdf.h"
#include "thin_film.h"

namespace woven {
namespace {

constexpr double kPi = 3.14159265358979323846;

double schlick(double f0, double c) { return f0 + (1.0 - f0) * std::pow(1.0 - c, 5.0); }
double normalReflectance(double n1, double n2) { return std::pow((n1 - n2) / (n1 + n2), 2.0); }

// The extension's evalSensitivity: the XYZ sensitivities' Fourier transform at OPD (nm) with
// a phase shift, as Rec. 709 (one colour channel at a time, the XYZ-to-RGB matrix's rows).
glm::dvec3 sensitivityRgb(double opd, const glm::dvec3& shift) {
    const double phase = 2.0 * kPi * opd * 1e-9;
    const double val[3] = {5.4856e-13, 4.4201e-13, 5.2481e-13}, pos[3] = {1.6810e+06, 1.7953e+06, 2.2084e+06},
                 var[3] = {4.3278e+09, 9.3046e+09, 6.6121e+09};
    double xyz[3];
    for (int i = 0; i < 3; ++i)
        xyz[i] = val[i] * std::sqrt(2.0 * kPi * var[i]) * std::cos(pos[i] * phase + shift[i]) * std::exp(-phase * phase * var[i]);
    xyz[0] += 9.7470e-14 * std::sqrt(2.0 * kPi * 4.5282e+09) * std::cos(2.2399e+06 * phase + shift[0]) *
              std::exp(-4.5282e+09 * phase * phase);
    for (double& v : xyz) v /= 1.0685e-7;
    return {3.2404542 * xyz[0] - 1.5371385 * xyz[1] - 0.4985314 * xyz[2],
            -0.9692660 * xyz[0] + 1.8760108 * xyz[1] + 0.0415560 * xyz[2],
            0.0556434 * xyz[0] - 0.2040259 * xyz[1] + 1.0572252 * xyz[2]};
}

// F_iridescence for a film of index n2 and thickness d (nm) between n1 and a base of F0 baseF0
// (each channel's base index from its F0), at cos theta1 (nonzero d: no fading to the outside).
glm::dvec3 referenceFilm(double n1, double n2, double cos1, double d, const glm::dvec3& baseF0) {
    const double sin2Sq = (n1 / n2) * (n1 / n2) * (1.0 - cos1 * cos1);
    if (sin2Sq > 1.0) return glm::dvec3(1.0);
    const double cos2 = std::sqrt(1.0 - sin2Sq);
    const double R12 = schlick(normalReflectance(n2, n1), cos1), T121 = 1.0 - R12;
    const double phi12 = n2 < n1 ? kPi : 0.0, phi21 = kPi - phi12;
    const double opd = 2.0 * n2 * d * cos2;
    glm::dvec3 out;
    for (int c = 0; c < 3; ++c) {
        const double n3 = (1.0 + std::sqrt(baseF0[c])) / (1.0 - std::sqrt(baseF0[c]));
        const double R23 = schlick(normalReflectance(n3, n2), cos2);
        const double phi = phi21 + (n3 < n2 ? kPi : 0.0);
        const double R123 = std::clamp(R12 * R23, 1e-5, 0.9999);
        const double Rs = T121 * T121 * R23 / (1.0 - R123);
        double I = R12 + Rs;  // m = 0
        for (int m = 1; m <= 2; ++m) {
            const double Cm = (Rs - T121) * std::pow(std::sqrt(R123), m);
            I += Cm * 2.0 * sensitivityRgb(m * opd, glm::dvec3(m * phi))[c];
        }
        out[c] = std::max(I, 0.0);
    }
    return out;
}

TEST(ThinFilm, MatchesTheExtensionsFormulaAtSeveralAnglesAndThicknesses) {
    struct Case {
        double n1, n2;
        glm::dvec3 baseF0;
    };
    const Case cases[] = {
        {1.0, 1.3, glm::dvec3(0.04)},             // the extension's default film on glass
        {1.0, 1.8, glm::dvec3(0.04)},             // a film denser than the base: phase shift pi at the base
        {1.0, 1.3, {0.95, 0.64, 0.54}},           // over copper's F0
        {1.5, 1.3, glm::dvec3(0.04)},             // under a clearcoat, a film thinner than the outside
    };
    double worst = 0.0;
    for (const Case& c : cases)
        for (double cosTheta : {1.0, 0.8, 0.5, 0.2, 0.05})
            for (double d : {50.0, 150.0, 400.0, 800.0, 1200.0}) {
                const glm::dvec3 ref = referenceFilm(c.n1, c.n2, cosTheta, d, c.baseF0);
                const glm::vec3 got = thinFilmFresnel(float(c.n1), float(c.n2), float(cosTheta), float(d), glm::vec3(c.baseF0));
                for (int i = 0; i < 3; ++i) {
                    worst = std::max(worst, std::abs(got[i] - ref[i]));
                    EXPECT_NEAR(got[i], ref[i], 2e-5) << "n " << c.n1 << " / " << c.n2 << ", cos " << cosTheta << ", " << d << " nm";
                }
            }
    std::printf("largest difference from the reference: %.2g\n", worst);
}

TEST(ThinFilm, ColoursTheReflectionAndReflectsAllPastTheCriticalAngle) {
    // A 300 nm film of index 1.5 on glass reflects coloured light (its channels differ by over a
    // quarter of their mean, a thousand times the tolerance), unlike the grey Schlick it replaces.
    const glm::vec3 film = thinFilmFresnel(1.0f, 1.5f, 1.0f, 300.0f, glm::vec3(0.04f));
    EXPECT_GT(std::max({film.r, film.g, film.b}) - std::min({film.r, film.g, film.b}), 0.25f * (film.r + film.g + film.b) / 3.0f);
    // A film of lower index than the outside reflects everything past its critical angle.
    EXPECT_EQ(thinFilmFresnel(1.5f, 1.2f, 0.3f, 300.0f, glm::vec3(0.04f)), glm::vec3(1.0f));
}

TEST(ThinFilm, GltfBxdfMixesTheFilmIntoTheSpecularLobeByTheFactor) {
    // A black dielectric (no diffuse) and a metal: f = F D V with F = mix(Schlick, film, factor)
    // at the half vector.
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, 0.1f, 0.9f)), wi = glm::normalize(glm::vec3(-0.4f, 0.2f, 0.8f));
    const glm::dvec3 h = glm::normalize(glm::dvec3(wo) + glm::dvec3(wi));
    const double vh = glm::dot(glm::dvec3(wo), h), alpha = 0.3 * 0.3;
    const double dv = gltfref::ggxD(alpha, h.z) * gltfref::ggxV(alpha, wi.z, wo.z, glm::dot(glm::dvec3(wi), h), vh);
    for (float metallic : {0.0f, 1.0f}) {
        GltfBxdfInputs in;
        in.baseColor = metallic > 0.0f ? glm::vec3(0.95f, 0.64f, 0.54f) : glm::vec3(0.0f);
        in.metallic = metallic;
        in.roughness = 0.3f;
        in.iridescence = 0.75f;
        in.iridescenceIor = 1.3f;
        in.iridescenceThickness = 400.0f;
        const glm::dvec3 f0 = metallic > 0.0f ? glm::dvec3(in.baseColor) : glm::dvec3(in.specularF0);
        const glm::dvec3 film = referenceFilm(1.0, 1.3, vh, 400.0, f0);
        const glm::vec3 f = GltfBxdf(in).eval(wo, wi);
        for (int i = 0; i < 3; ++i) {
            const double schlickF = metallic > 0.0f ? schlick(f0[i], vh) : f0[i] + (1.0 - f0[i]) * std::pow(1.0 - vh, 5.0);
            EXPECT_NEAR(f[i], (0.25 * schlickF + 0.75 * film[i]) * dv, 1e-4 * dv) << "metallic " << metallic << " channel " << i;
        }
    }
}

}  // namespace
}  // namespace woven
