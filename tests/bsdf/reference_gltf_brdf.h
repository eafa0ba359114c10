#pragma once
// An independent double-precision glTF 2.0 BRDF written from the specifications, the yardstick
// core/bsdf's GltfBxdf is checked against. It calls nothing in core/bsdf (the sheen's tabulated
// albedo E comes in as a function, which the tests fill with the code's table after checking
// that table against their own integral).
//
// Sources, formula by formula:
//  - glTF 2.0 specification, appendix B: D (Trowbridge-Reitz), the height-correlated Smith
//    visibility V = G / (4 |N.L| |N.V|), Schlick's Fresnel, diffuse = baseColor / pi,
//    dielectric = fresnel_mix(diffuse, specular), metal = conductor_fresnel(baseColor, specular),
//    material = mix(dielectric, metal, metallic).
//  - KHR_materials_ior and KHR_materials_specular: F0 = min(((ior - 1) / (ior + 1))^2
//    specularColor, 1) specular, F90 = specular, F = F0 + (F90 - F0) (1 - |V.H|)^5 per channel.
//  - KHR_materials_transmission (thin-walled, no refraction): the diffuse base becomes
//    mix(diffuse, specular_btdf, transmission), the BTDF being the specular BRDF evaluated with
//    L mirrored through the surface and tinted by the base colour; KHR_materials_volume's
//    attenuation of one crossing multiplies it.
//  - KHR_materials_diffuse_transmission: that diffuse base's Lambert BRDF becomes
//    mix(diffuse_brdf(baseColor), diffuse_btdf(diffuseTransmissionColor), diffuseTransmission),
//    the BTDF being colour / pi towards L on the other side; fresnel_mix's weight for it taken at
//    the half vector of V and L mirrored, as for the thin-walled transmission.
//  - KHR_materials_sheen: the Charlie distribution and Conty-Kulla's visibility, layered over
//    the base by albedo scaling, min(1 - max(sheenColor) E(N.V), 1 - max(sheenColor) E(N.L)).
//  - KHR_materials_clearcoat: a GGX coat with F0 = 0.04 (IOR 1.5) on its own normal, over the
//    rest; the rest is scaled by 1 - clearcoat F_c.
//  - KHR_materials_anisotropy: the base's GGX lobe with a_t = mix(alpha, 1, strength^2) along the
//    anisotropy direction (here the frame's x axis) and a_b = alpha across it, the extension's
//    D_GGX_anisotropic and V_GGX_anisotropic.
//
// The implementation's documented choices, followed here on purpose:
//  - alpha = roughness^2 clamped below at 1e-3 (no delta lobes); sheen roughness clamped below
//    at 0.07 and its alpha = sheenRoughness^2.
//  - the coat scales the layer below by 1 - clearcoat max(F_c(|N_c.V|), F_c(|N_c.L|)) (the
//    extension uses N_c.V alone, which is not reciprocal).
//  - clearcoat goes over sheen, which goes over the base (as KHR_materials_sheen says).
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace woven::gltfref {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMinAlpha = 1e-3;           // gltf_bxdf.h, ggx.h: no BSDF in woven is a delta
constexpr double kMinSheenRoughness = 0.07;  // sheen_lobe.h

// A material as the glTF file (with its extensions) describes it, every texture looked up.
struct Material {
    glm::dvec3 baseColor{1.0};
    double metallic = 1.0, roughness = 1.0;
    double anisotropy = 0.0;  // KHR_materials_anisotropy's strength, along x
    double ior = 1.5, specular = 1.0;
    glm::dvec3 specularColor{1.0};
    double transmission = 0.0;
    glm::dvec3 transmittance{1.0};
    double diffuseTransmission = 0.0;
    glm::dvec3 diffuseTransmissionColor{1.0};
    glm::dvec3 sheenColor{0.0};
    double sheenRoughness = 0.0;
    double clearcoat = 0.0, clearcoatRoughness = 0.0;
    glm::dvec3 clearcoatNormal{0.0, 0.0, 1.0};
};

// KHR_materials_ior + KHR_materials_specular.
inline glm::dvec3 dielectricF0(const Material& m) {
    const double r = (m.ior - 1.0) / (m.ior + 1.0);
    return glm::min(r * r * m.specularColor, glm::dvec3(1.0)) * m.specular;
}
inline double dielectricF90(const Material& m) { return m.specular; }

inline double alphaOf(double roughness) { return std::max(roughness * roughness, kMinAlpha); }

inline double heaviside(double x) { return x > 0.0 ? 1.0 : 0.0; }

// Appendix B, D: alpha^2 chi+(N.H) / (pi ((N.H)^2 (alpha^2 - 1) + 1)^2).
inline double ggxD(double alpha, double nh) {
    const double a2 = alpha * alpha;
    const double d = nh * nh * (a2 - 1.0) + 1.0;
    return a2 * heaviside(nh) / (kPi * d * d);
}

// Appendix B, the visibility nu = G / (4 |N.L| |N.V|) of the height-correlated Smith G.
inline double ggxV(double alpha, double nl, double nv, double hl, double hv) {
    const double a2 = alpha * alpha;
    nl = std::abs(nl);
    nv = std::abs(nv);
    const double denom = nv * std::sqrt(a2 + (1.0 - a2) * nl * nl) + nl * std::sqrt(a2 + (1.0 - a2) * nv * nv);
    if (!(denom > 0.0)) return 0.0;
    return heaviside(hl) * heaviside(hv) / (2.0 * denom);
}

// KHR_materials_anisotropy: the alpha along the anisotropy direction (the extension's mix, on
// the alpha before woven's clamp, which then applies to both).
inline double anisotropicAlphaOf(double roughness, double strength) {
    const double a = roughness * roughness;
    return std::max(a + (1.0 - a) * strength * strength, kMinAlpha);
}
// The extension's D_GGX_anisotropic, at = alpha along x (T), ab = alpha along y (B).
inline double ggxDAnisotropic(double at, double ab, const glm::dvec3& h) {
    const double a2 = at * ab;
    const glm::dvec3 f(ab * h.x, at * h.y, a2 * h.z);
    const double w2 = a2 / glm::dot(f, f);
    return heaviside(h.z) * a2 * w2 * w2 / kPi;
}
// The extension's V_GGX_anisotropic (without its clamp to 1, which only large alphas at grazing
// angles reach, where G / (4 |N.L| |N.V|) is what the BRDF needs).
inline double ggxVAnisotropic(double at, double ab, const glm::dvec3& v, const glm::dvec3& l) {
    const double gv = std::abs(l.z) * glm::length(glm::dvec3(at * v.x, ab * v.y, v.z));
    const double gl = std::abs(v.z) * glm::length(glm::dvec3(at * l.x, ab * l.y, l.z));
    return 0.5 / (gv + gl);
}

inline double schlickWeight(double vh) { return std::pow(1.0 - std::abs(vh), 5.0); }

// KHR_materials_sheen: "Charlie" distribution and visibility, alphaG = sheenRoughness^2.
inline double charlieD(double alphaG, double nh) {
    const double invR = 1.0 / alphaG;
    const double sin2h = std::max(0.0, 1.0 - nh * nh);
    return (2.0 + invR) * std::pow(sin2h, invR * 0.5) / (2.0 * kPi);
}
inline double charlieL(double x, double alphaG) {
    const double t = (1.0 - alphaG) * (1.0 - alphaG);
    const auto mix = [t](double a, double b) { return a + (b - a) * t; };
    const double a = mix(21.5473, 25.3245), b = mix(3.82987, 3.32435), c = mix(0.19823, 0.16801);
    const double d = mix(-1.97760, -1.27393), e = mix(-4.32054, -4.85967);
    return a / (1.0 + b * std::pow(x, c)) + d * x + e;
}
inline double charlieLambda(double cosTheta, double alphaG) {
    const double c = std::abs(cosTheta);
    return c < 0.5 ? std::exp(charlieL(c, alphaG)) : std::exp(2.0 * charlieL(0.5, alphaG) - charlieL(1.0 - c, alphaG));
}
inline double charlieV(double alphaG, double nv, double nl) {
    return 1.0 / ((1.0 + charlieLambda(nv, alphaG) + charlieLambda(nl, alphaG)) * (4.0 * nv * nl));
}
inline double sheenAlphaOf(double sheenRoughness) {
    const double r = std::clamp(sheenRoughness, kMinSheenRoughness, 1.0);
    return r * r;
}
// The sheen BRDF with colour 1 (the extension's F = 1); zero off the upper hemisphere.
inline double sheenBrdf(double sheenRoughness, const glm::dvec3& v, const glm::dvec3& l) {
    if (v.z <= 0.0 || l.z <= 0.0) return 0.0;
    const glm::dvec3 h = glm::normalize(v + l);
    const double a = sheenAlphaOf(sheenRoughness);
    return charlieD(a, h.z) * charlieV(a, v.z, l.z);
}

inline double maxComponent(const glm::dvec3& c) { return std::max({c.r, c.g, c.b}); }

// E(cos theta, sheenRoughness): the directional albedo of the sheen BRDF with colour 1.
using SheenAlbedo = std::function<double(double cosTheta, double sheenRoughness)>;

// f(V = wo, L = wi) in a frame with z = the shading normal, wo on its side; wi below the surface
// is the thin-walled transmission. The directions are taken as they come, unit vectors: float
// directions are unit only to about 1e-7, and renormalising them here would move the half
// vector of a grazing pair near the mirror direction (where V + L is short) by far more than
// any rounding in the code under test.
inline glm::dvec3 eval(const Material& m, const glm::dvec3& v, const glm::dvec3& l, const SheenAlbedo& sheenE) {
    if (v.z <= 0.0 || l.z == 0.0) return glm::dvec3(0.0);
    const bool reflection = l.z > 0.0;
    // Thin-walled: the BTDF is the BRDF towards L mirrored through the surface.
    const glm::dvec3 lm = reflection ? l : glm::dvec3(l.x, l.y, -l.z);
    const glm::dvec3 h = glm::normalize(v + lm);
    const double alpha = alphaOf(m.roughness);
    const double vh = glm::dot(v, h);
    const double microfacet =
        m.anisotropy > 0.0
            ? ggxDAnisotropic(anisotropicAlphaOf(m.roughness, m.anisotropy), alpha, h) *
                  ggxVAnisotropic(anisotropicAlphaOf(m.roughness, m.anisotropy), alpha, v, lm) * heaviside(glm::dot(h, lm)) * heaviside(vh)
            : ggxD(alpha, h.z) * ggxV(alpha, lm.z, v.z, glm::dot(h, lm), vh);
    const double w = schlickWeight(vh);

    const glm::dvec3 f0 = dielectricF0(m);
    const glm::dvec3 dielectricF = f0 + (glm::dvec3(dielectricF90(m)) - f0) * w;
    const glm::dvec3 metalF = m.baseColor + (1.0 - m.baseColor) * w;

    glm::dvec3 f;
    if (reflection) {
        // fresnel_mix(base = mix(diffuse, btdf, T) -> only the diffuse part reflects, layer = specular)
        const glm::dvec3 diffuse = (1.0 - m.diffuseTransmission) * m.baseColor / kPi;
        const glm::dvec3 dielectric = (1.0 - dielectricF) * (1.0 - m.transmission) * diffuse + dielectricF * microfacet;
        const glm::dvec3 metal = metalF * microfacet;
        f = (1.0 - m.metallic) * dielectric + m.metallic * metal;
    } else {
        const glm::dvec3 btdf = m.baseColor * m.transmittance * microfacet;
        const glm::dvec3 diffuseBtdf = m.diffuseTransmission * m.diffuseTransmissionColor / kPi;
        f = (1.0 - m.metallic) * (1.0 - dielectricF) * (m.transmission * btdf + (1.0 - m.transmission) * diffuseBtdf);
    }

    if (maxComponent(m.sheenColor) > 0.0) {
        const double s = maxComponent(m.sheenColor);
        const double scale = std::min(1.0 - s * sheenE(v.z, m.sheenRoughness), 1.0 - s * sheenE(lm.z, m.sheenRoughness));
        f *= std::clamp(scale, 0.0, 1.0);
        if (reflection) f += m.sheenColor * sheenBrdf(m.sheenRoughness, v, l);
    }

    if (m.clearcoat > 0.0) {
        const glm::dvec3 nc = glm::normalize(m.clearcoatNormal);
        const auto coatF = [](double cosTheta) { return 0.04 + 0.96 * schlickWeight(cosTheta); };
        // |N_c.L| with L itself, also for transmission: a thin wall seen from behind has the coat
        // (normal -N_c) on that side, and only this keeps the transmission reciprocal.
        const double scale = 1.0 - m.clearcoat * std::max(coatF(std::abs(glm::dot(nc, v))), coatF(std::abs(glm::dot(nc, l))));
        f *= scale;
        const double nv = glm::dot(nc, v), nl = glm::dot(nc, l);
        if (reflection && nv > 0.0 && nl > 0.0) {
            const double ac = alphaOf(m.clearcoatRoughness);
            const double coat = coatF(vh) * ggxD(ac, glm::dot(nc, h)) * ggxV(ac, nl, nv, glm::dot(h, l), vh);
            f += glm::dvec3(m.clearcoat * coat);
        }
    }
    return f;
}

}  // namespace woven::gltfref
