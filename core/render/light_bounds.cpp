#include "light_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "math_constants.h"

namespace woven {

namespace {

float safeSqrt(float x) { return std::sqrt(std::max(0.0f, x)); }
float safeAcos(float x) { return std::acos(std::clamp(x, -1.0f, 1.0f)); }

// cos and sin of max(0, a - b) for angles a and b given by their cosines and sines.
float cosSubClamped(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}
float sinSubClamped(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB;
}

// v rotated by `angle` about the unit `axis` (Rodrigues).
glm::vec3 rotate(const glm::vec3& v, const glm::vec3& axis, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0f - c);
}

Bounds unionOf(const Bounds& a, const Bounds& b) { return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)}; }

}  // namespace

DirectionCone unionOf(const DirectionCone& a, const DirectionCone& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    const float thetaA = safeAcos(a.cosTheta), thetaB = safeAcos(b.cosTheta);
    const float thetaD = safeAcos(glm::dot(a.w, b.w));
    if (std::min(thetaD + thetaB, kPi) <= thetaA) return a;
    if (std::min(thetaD + thetaA, kPi) <= thetaB) return b;
    // The cone's half-angle reaches from one's far side to the other's, about the axis of the two.
    const float thetaO = (thetaA + thetaD + thetaB) / 2.0f;
    if (thetaO >= kPi) return DirectionCone::entireSphere();
    const glm::vec3 axis = glm::cross(a.w, b.w);
    const float length = glm::length(axis);
    if (!(length > 1e-7f)) return DirectionCone::entireSphere();
    return {glm::normalize(rotate(a.w, axis / length, thetaO - thetaA)), std::cos(thetaO)};
}

LightBounds unionOf(const LightBounds& a, const LightBounds& b) {
    if (a.phi == 0.0f) return b;
    if (b.phi == 0.0f) return a;
    LightBounds u;
    u.bounds = unionOf(a.bounds, b.bounds);
    u.phi = a.phi + b.phi;
    u.cone = unionOf(a.cone, b.cone);
    u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
    u.twoSided = a.twoSided || b.twoSided;
    return u;
}

LightImportance::LightImportance(const LightBounds& b)
    : centre_(b.bounds.centre()),
      w_(b.cone.w),
      radius2_(glm::dot(b.bounds.hi - b.bounds.lo, b.bounds.hi - b.bounds.lo) / 4.0f),
      // Clamped below by half the box's diagonal (a length, as pbrt-v4 has it), so that points
      // inside or near a group do not give it unbounded weight.
      minDistance2_(glm::length(b.bounds.hi - b.bounds.lo) / 2.0f),
      phi_(b.phi),
      cosThetaO_(b.cone.cosTheta),
      sinThetaO_(safeSqrt(1.0f - b.cone.cosTheta * b.cone.cosTheta)),
      cosThetaE_(b.cosThetaE),
      twoSided_(b.twoSided) {}

float LightImportance::operator()(const glm::vec3& p, const glm::vec3& n) const {
    const glm::vec3 toP = p - centre_;
    const float distance2 = glm::dot(toP, toP);
    const glm::vec3 wi = distance2 > 0.0f ? toP / std::sqrt(distance2) : w_;
    float cosThetaW = glm::dot(w_, wi);
    if (twoSided_) cosThetaW = std::abs(cosThetaW);
    const float sinThetaW = safeSqrt(1.0f - cosThetaW * cosThetaW);
    // The half-angle theta_b that the bounding sphere subtends from p: everything from inside.
    const bool inside = distance2 < radius2_;
    const float sinThetaB = inside ? 0.0f : std::sqrt(radius2_ / distance2);
    const float cosThetaB = inside ? -1.0f : safeSqrt(1.0f - radius2_ / distance2);
    // The smallest angle between an emitting normal and the direction to p: theta_w less theta_o
    // and less theta_b.
    const float cosThetaX = cosSubClamped(sinThetaW, cosThetaW, sinThetaO_, cosThetaO_);
    const float sinThetaX = sinSubClamped(sinThetaW, cosThetaW, sinThetaO_, cosThetaO_);
    const float cosThetaP = cosSubClamped(sinThetaX, cosThetaX, sinThetaB, cosThetaB);
    if (cosThetaP <= cosThetaE_) return 0.0f;
    float importance = phi_ * cosThetaP / std::max(distance2, minDistance2_);
    if (n != glm::vec3(0.0f)) {
        // Both sides of the surface: a cloth's yarns let light through.
        const float cosThetaI = std::abs(glm::dot(wi, n)), sinThetaI = safeSqrt(1.0f - cosThetaI * cosThetaI);
        importance *= cosSubClamped(sinThetaI, cosThetaI, sinThetaB, cosThetaB);
    }
    // A point light at p itself: finite, so that two children's importances still add up.
    return std::clamp(importance, 0.0f, std::numeric_limits<float>::max() / 4.0f);
}

std::optional<LightBounds> boundsOf(const Light& light) {
    if (light.isInfinite()) return std::nullopt;
    LightBounds b;
    b.phi = std::max(luminance(light.power()), 0.0f);
    if (!(b.phi > 0.0f)) return std::nullopt;
    if (const TriangleLight* t = light.get<TriangleLight>()) {
        b.bounds = {glm::min(t->a, glm::min(t->b, t->c)), glm::max(t->a, glm::max(t->b, t->c))};
        b.cone = {t->n, 1.0f};
        b.cosThetaE = 0.0f;  // the cosine lobe: pi / 2 beyond the normal
        b.twoSided = t->twoSided;
    } else if (const RectangleLight* r = light.get<RectangleLight>()) {
        const glm::vec3 far = r->corner + r->ex + r->ey;
        b.bounds = {glm::min(glm::min(r->corner, far), glm::min(r->corner + r->ex, r->corner + r->ey)),
                    glm::max(glm::max(r->corner, far), glm::max(r->corner + r->ex, r->corner + r->ey))};
        b.cone = {r->n, 1.0f};
        b.cosThetaE = 0.0f;
        b.twoSided = r->twoSided;
    } else if (const PointLight* q = light.get<PointLight>()) {
        b.bounds = {q->position, q->position};
        b.cone = DirectionCone::entireSphere();
        b.cosThetaE = 0.0f;
    } else if (const SpotLight* s = light.get<SpotLight>()) {
        // Emission within the outer cone around the spot's direction; theta_e is kept just
        // above 0 so that rounding never culls a point on the cone's edge.
        b.bounds = {s->position, s->position};
        b.cone = {s->direction, s->cone.cosOuter};
        b.cosThetaE = std::cos(1e-3f);
    } else {
        return std::nullopt;
    }
    return b;
}

}  // namespace woven
