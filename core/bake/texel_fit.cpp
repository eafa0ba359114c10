#include "texel_fit.h"

#include <algorithm>
#include <cmath>

#include "lobe_fit.h"

namespace woven {

namespace {

// The unit eigenvector of the larger eigenvalue of the symmetric [[a, b], [b, c]], and both
// eigenvalues (larger first).
struct Eigen {
    double large, small;
    glm::dvec2 axis;
};
Eigen eigen(const glm::dmat2& m) {
    const double a = m[0][0], b = m[0][1], c = m[1][1];
    const double mean = 0.5 * (a + c), d = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
    Eigen e{mean + d, mean - d, {1.0, 0.0}};
    // The better conditioned of the two forms of the eigenvector.
    const glm::dvec2 v = a >= c ? glm::dvec2(e.large - c, b) : glm::dvec2(b, e.large - a);
    const double length = glm::length(v);
    if (length > 1e-300) e.axis = v / length;
    return e;
}

}  // namespace

void TexelSums::add(const std::optional<WovenShading>& shading) {
    points += 1.0;
    if (!shading) return;
    const AshikhminShirley& lobe = shading->bsdf.lobe();
    const Frame& frame = shading->bsdf.frame();
    covered += 1.0;
    color += glm::dvec3(diffuseScale() * lobe.rd());
    rs += lobe.shape().rs;
    const glm::dvec3 n(frame.z);
    normal += n;
    // The lobe's microfacet normals about n: a GGX (Beckmann) lobe of width alpha spreads them
    // by alpha^2 / 2 per axis; x along the yarn (e_x), y across it (e_y).
    glm::dvec2 along(frame.x.x, frame.x.y);
    const double length = glm::length(along);
    along = length > 1e-12 ? along / length : glm::dvec2(1.0, 0.0);
    const glm::dvec2 across(-along.y, along.x);
    const double ax = ggxAlphaForExponent(lobe.shape().ex), ay = ggxAlphaForExponent(lobe.shape().ey);
    spread += glm::outerProduct(glm::dvec2(n), glm::dvec2(n)) + 0.5 * ax * ax * glm::outerProduct(along, along) +
              0.5 * ay * ay * glm::outerProduct(across, across);
    if (shading->transmission) transmitted += glm::dvec3(shading->transmission->lobe().transmittance());
}

TexelSums& TexelSums::operator+=(const TexelSums& o) {
    points += o.points;
    covered += o.covered;
    color += o.color;
    rs += o.rs;
    normal += o.normal;
    spread += o.spread;
    transmitted += o.transmitted;
    return *this;
}

TexelFit fitTexel(const TexelSums& s) {
    TexelFit t;
    if (!(s.points > 0.0) || !(s.covered > 0.0)) return t;
    t.coverage = float(s.covered / s.points);
    t.baseColor = glm::vec3(glm::clamp(s.color / s.covered, 0.0, 1.0));
    t.rs = float(s.rs / s.covered);
    t.transmitted = glm::vec3(s.transmitted / s.covered);
    const glm::dvec3 mean = s.normal / s.covered;
    const double length = glm::length(mean);
    t.normal = length > 1e-12 ? glm::vec3(mean / length) : glm::vec3(0.0f, 0.0f, 1.0f);
    // The spread of the microfacet normals about the mean normal.
    const glm::dmat2 covariance = s.spread / s.covered - glm::outerProduct(glm::dvec2(mean), glm::dvec2(mean));
    const Eigen e = eigen(covariance);
    const double rough = std::min(1.0, std::sqrt(2.0 * std::max(e.large, 0.0)));
    const double smooth = std::min(rough, std::sqrt(2.0 * std::max(e.small, 0.0)));
    t.roughness = float(std::sqrt(smooth));
    t.anisotropy = smooth < 1.0 ? float(std::sqrt((rough - smooth) / (1.0 - smooth))) : 0.0f;
    glm::vec2 d(e.axis);
    if (d.x + d.y < 0.0f) d = -d;
    t.direction = d;
    return t;
}

TexelFit isotropic(TexelFit t) {
    const double smooth = double(t.roughness) * t.roughness;
    const double rough = smooth + (1.0 - smooth) * double(t.anisotropy) * t.anisotropy;
    t.roughness = float(std::sqrt(std::sqrt(smooth * rough)));
    t.anisotropy = 0.0f;
    return t;
}

}  // namespace woven
