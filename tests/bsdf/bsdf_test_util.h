#pragma once
// Shared by the tests of core/bsdf: materials (as the glTF file describes them) turned into the
// BSDF's inputs, random materials and directions, and small numerical tools.
#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "direction_domain.h"
#include "gltf_bxdf.h"
#include "reference_gltf_brdf.h"
#include "sheen_lobe.h"

namespace woven::test {

using gltfref::Material;

// Rounds to float for real, out of line: GCC 12.2 at -O2 drops the rounding of a
// double -> float -> double round trip when its SLP vectoriser packs the components (reduced:
// `F3 f{float(d.x), float(d.y), float(d.z)}; D3 back{f.x, f.y, f.z};` leaves back.x == d.x), and
// the reference would then be handed other directions than the code under test.
[[gnu::noinline]] inline glm::vec3 roundToFloat(const glm::dvec3& v) { return glm::vec3(v); }

// What GltfMaterial::inputs() hands to GltfBxdf, for a material without textures (the specular
// and IOR extensions folded into F0 and F90 as their specifications say).
inline GltfBxdfInputs toInputs(const Material& m) {
    GltfBxdfInputs in;
    in.baseColor = glm::vec3(m.baseColor);
    in.metallic = float(m.metallic);
    in.roughness = float(m.roughness);
    in.anisotropy = float(m.anisotropy);
    in.specularF0 = glm::vec3(gltfref::dielectricF0(m));
    in.specularF90 = float(gltfref::dielectricF90(m));
    in.transmission = float(m.transmission);
    in.transmittance = glm::vec3(m.transmittance);
    in.diffuseTransmission = float(m.diffuseTransmission);
    in.diffuseTransmissionColor = glm::vec3(m.diffuseTransmissionColor);
    in.sheenColor = glm::vec3(m.sheenColor);
    in.sheenRoughness = float(m.sheenRoughness);
    in.clearcoat = float(m.clearcoat);
    in.clearcoatRoughness = float(m.clearcoatRoughness);
    in.clearcoatNormal = roundToFloat(glm::normalize(m.clearcoatNormal));
    return in;
}

// The code's tabulated sheen albedo, for the reference (tested on its own by SheenAlbedoTable).
inline double codeSheenAlbedo(double cosTheta, double sheenRoughness) {
    return SheenLobe(glm::vec3(1.0f), float(sheenRoughness)).albedo(float(cosTheta));
}

inline std::string describe(const Material& m) {
    std::ostringstream s;
    s.precision(9);
    s << "base (" << m.baseColor.r << " " << m.baseColor.g << " " << m.baseColor.b << ") metallic " << m.metallic
      << " roughness " << m.roughness << " anisotropy " << m.anisotropy << " ior " << m.ior << " specular " << m.specular << " specColor ("
      << m.specularColor.r << " " << m.specularColor.g << " " << m.specularColor.b << ") T " << m.transmission
      << " transmittance (" << m.transmittance.r << " " << m.transmittance.g << " " << m.transmittance.b
      << ") DT " << m.diffuseTransmission << " (" << m.diffuseTransmissionColor.r << " " << m.diffuseTransmissionColor.g
      << " " << m.diffuseTransmissionColor.b << ") sheen (" << m.sheenColor.r << " " << m.sheenColor.g << " " << m.sheenColor.b << ") r "
      << m.sheenRoughness << " coat " << m.clearcoat << " r " << m.clearcoatRoughness << " n ("
      << m.clearcoatNormal.x << " " << m.clearcoatNormal.y << " " << m.clearcoatNormal.z << ")";
    return s.str();
}

inline std::string describe(const glm::vec3& v) {
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

class TestRng {
public:
    explicit TestRng(uint64_t seed) : gen_(seed) {}
    // [0, 1) with 24 bits, as the renderer's sampler gives them.
    float u() { return float(gen_() >> 40) * 0x1p-24f; }
    glm::vec2 u2() { const float a = u(); return {a, u()}; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * double(gen_() >> 11) * 0x1p-53; }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }
    glm::dvec3 color(double lo = 0.0, double hi = 1.0) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    // Uniform on the sphere, or on the upper hemisphere.
    glm::dvec3 sphere() {
        const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * gltfref::kPi);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return {r * std::cos(phi), r * std::sin(phi), z};
    }
    glm::dvec3 hemisphere() {
        glm::dvec3 w = sphere();
        w.z = std::abs(w.z);
        return w;
    }

private:
    std::mt19937_64 gen_;
};

// A random material over every feature: each extension on or off, parameters anywhere in
// their valid ranges, roughness down to 0 (alpha clamped to 1e-3) some of the time.
inline Material randomMaterial(TestRng& rng) {
    Material m;
    m.baseColor = rng.color();
    m.metallic = rng.chance(0.3) ? (rng.chance(0.5) ? 0.0 : 1.0) : rng.uniform(0.0, 1.0);
    m.roughness = rng.chance(0.1) ? 0.0 : rng.uniform(0.0, 1.0);
    if (rng.chance(0.3)) m.anisotropy = rng.chance(0.2) ? 1.0 : rng.uniform(0.0, 1.0);
    if (rng.chance(0.5)) {
        m.ior = rng.chance(0.2) ? 1.0 : rng.uniform(1.0, 3.0);
        m.specular = rng.uniform(0.0, 1.0);
        m.specularColor = rng.color(0.0, 3.0);  // the extension lets it exceed 1; F0 is clamped
    }
    if (rng.chance(0.4)) {
        m.transmission = rng.uniform(0.0, 1.0);
        m.transmittance = rng.color(0.2, 1.0);
    }
    if (rng.chance(0.4)) {
        m.sheenColor = rng.color();
        m.sheenRoughness = rng.uniform(0.0, 1.0);
    }
    if (rng.chance(0.4)) {
        m.clearcoat = rng.uniform(0.0, 1.0);
        m.clearcoatRoughness = rng.chance(0.1) ? 0.0 : rng.uniform(0.0, 1.0);
        if (rng.chance(0.5)) {
            glm::dvec3 n = rng.hemisphere();
            n.z += 1.0;  // tilted by up to 45 degrees, as a clearcoat normal map would
            m.clearcoatNormal = glm::normalize(n);
        }
    }
    if (rng.chance(0.3)) {
        m.diffuseTransmission = rng.chance(0.2) ? 1.0 : rng.uniform(0.0, 1.0);
        m.diffuseTransmissionColor = rng.color();
    }
    return m;
}

// Unit direction from spherical angles (theta from +z, phi from +x).
inline glm::dvec3 spherical(double theta, double phi) {
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}
inline glm::vec3 toFloatUnit(const glm::dvec3& w) { return roundToFloat(glm::normalize(w)); }
inline glm::dvec3 mirror(const glm::dvec3& w) { return {w.x, w.y, -w.z}; }
inline glm::vec3 mirror(const glm::vec3& w) { return {w.x, w.y, -w.z}; }
// Whether a material lets light through to the other side (thin or diffuse transmission).
inline bool transmits(const Material& m) {
    return m.metallic < 1.0 && (m.transmission > 0.0 || (m.diffuseTransmission > 0.0 && m.transmission < 1.0));
}
// The thin-walled transmission's L mirrored to the upper side; reflection directions unchanged.
inline glm::vec3 mirrorBelow(const glm::vec3& w) { return w.z < 0.0f ? mirror(w) : w; }

// The size of f's terms at (wo, wi): the sum of the lobes' magnitudes with every colour, Fresnel
// weight and layer scale replaced by 1. Tolerances on f are relative to it, so that a term
// like 1 - F near 0 does not make them vanish.
// The clearcoat's D V at (wo, wi) (zero for transmission).
inline double coatTermSize(const Material& m, const glm::dvec3& wo, const glm::dvec3& wi) {
    const glm::dvec3 v = glm::normalize(wo), l = glm::normalize(wi);
    const glm::dvec3 nc = glm::normalize(m.clearcoatNormal);
    if (m.clearcoat <= 0.0 || l.z <= 0.0 || glm::dot(nc, v) <= 0.0 || glm::dot(nc, l) <= 0.0) return 0.0;
    const glm::dvec3 h = glm::normalize(v + l);
    const double ac = gltfref::alphaOf(m.clearcoatRoughness);
    return gltfref::ggxD(ac, glm::dot(nc, h)) * gltfref::ggxV(ac, glm::dot(nc, l), glm::dot(nc, v), 1, 1);
}
inline double termSize(const Material& m, const glm::dvec3& wo, const glm::dvec3& wi) {
    const glm::dvec3 v = glm::normalize(wo), l = glm::normalize(wi);
    const glm::dvec3 lm = l.z > 0.0 ? l : mirror(l);
    const glm::dvec3 h = glm::normalize(v + lm);
    const double a = gltfref::alphaOf(m.roughness), at = gltfref::anisotropicAlphaOf(m.roughness, m.anisotropy);
    return 1.0 / gltfref::kPi + gltfref::ggxDAnisotropic(at, a, h) * gltfref::ggxVAnisotropic(at, a, v, lm) +
           gltfref::sheenBrdf(m.sheenRoughness, v, lm) + coatTermSize(m, v, lm);
}

inline bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Gauss-Legendre nodes and weights on [0, 1].
struct GaussRule {
    std::vector<double> nodes, weights;
};
inline const GaussRule& gaussRule8() {
    static const GaussRule rule = [] {
        GaussRule r;
        gaussLegendre(8, r.nodes, r.weights);
        return r;
    }();
    return rule;
}

// Composite 8-point Gauss-Legendre of g over [a, b] in `panels` equal panels: exact for
// polynomials of degree 15 on each panel, so smooth integrands converge very fast.
template <class G>
double compositeGauss(const G& g, double a, double b, int panels) {
    const GaussRule& rule = gaussRule8();
    const double width = (b - a) / panels;
    double sum = 0.0;
    for (int p = 0; p < panels; ++p)
        for (size_t i = 0; i < rule.nodes.size(); ++i) sum += rule.weights[i] * g(a + (p + rule.nodes[i]) * width);
    return sum * width;
}

// Gauss-Legendre of g over [a, b], halving panels until the halves agree with the whole to
// `tolerance` (absolute): for integrands smooth but for a narrow feature, such as the GGX
// visibility sqrt(alpha^2 + cos^2) near the horizon at small alpha.
template <class G>
double adaptiveGauss(const G& g, double a, double b, double tolerance, int depth = 40) {
    const auto panel = [&](double lo, double hi) {
        const GaussRule& rule = gaussRule8();
        double sum = 0.0;
        for (size_t i = 0; i < rule.nodes.size(); ++i) sum += rule.weights[i] * g(lo + rule.nodes[i] * (hi - lo));
        return sum * (hi - lo);
    };
    struct Recurse {
        const decltype(panel)& p;
        double operator()(double lo, double hi, double whole, double tol, int d) const {
            const double mid = 0.5 * (lo + hi), left = p(lo, mid), right = p(mid, hi);
            if (d == 0 || std::abs(left + right - whole) <= tol) return left + right;
            return (*this)(lo, mid, left, 0.5 * tol, d - 1) + (*this)(mid, hi, right, 0.5 * tol, d - 1);
        }
    };
    return Recurse{panel}(a, b, panel(a, b), tolerance, depth);
}

}  // namespace woven::test
