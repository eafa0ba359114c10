#pragma once
// Lights, shaped like pbrt-v3's Light interface so that both integrators can use every kind:
// emissive triangles (area), point, spot, directional, and the environment (constant or
// equirectangular image, importance-sampled). Radiance, importance and densities follow pbrt-v3's
// conventions: pdfLi is per unit solid angle at the reference point, pdfPos per unit area (or 1
// for delta positions), pdfDir per unit solid angle (or 1 for delta directions).
#include <array>
#include <glm/glm.hpp>
#include <memory>
#include <optional>

#include "interaction.h"
#include "scene_description.h"
#include "surface_material.h"

namespace woven {

struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::infinity()}, hi{-std::numeric_limits<float>::infinity()};
    glm::vec3 centre() const { return 0.5f * (lo + hi); }
    float radius() const { return 0.5f * glm::length(hi - lo); }
};

struct LightLiSample {
    glm::vec3 L;       // radiance arriving at the reference point along -wi
    glm::vec3 wi;      // unit, from the reference point towards the light
    glm::vec3 pLight;  // point on the light (for infinite lights: far along wi)
    glm::vec3 nLight;  // light's surface normal (area lights), zero otherwise
    float pdf;         // solid angle at the reference point (1 for delta lights)
};

struct LightLeSample {
    Ray ray;           // leaving the light
    glm::vec3 nLight;  // area lights: surface normal; infinite lights: the ray's direction
    glm::vec3 L;       // emitted radiance (or intensity for point/spot)
    float pdfPos, pdfDir;
};

class Light {
public:
    enum class Type { Triangle, Point, Spot, Directional, Environment };

    // An emissive triangle (world-space vertices) with radiance `L` from its front face
    // (and its back when `twoSided`).
    static Light triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& L, bool twoSided);
    // An emissive triangle of a material (which must outlive the light), whose emission (a
    // texture, perhaps) is looked up with the corners' texture coordinates; its power, for
    // choosing lights, is estimated from 16 points of the triangle.
    static Light triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const SurfaceMaterial& emitter,
                          const std::array<TexCoords, 3>& corners);
    static Light punctual(const PunctualLight& light);
    static Light environment(const Environment& env);  // builds the importance distribution

    Type type() const { return type_; }
    bool isDeltaPosition() const { return type_ == Type::Point || type_ == Type::Spot; }
    bool isDeltaDirection() const { return type_ == Type::Directional; }
    bool isDelta() const { return isDeltaPosition() || isDeltaDirection(); }
    bool isInfinite() const { return type_ == Type::Directional || type_ == Type::Environment; }

    // Infinite lights need the scene's extent; call once before sampling.
    void setSceneBounds(const Bounds& b);
    glm::vec3 power() const;  // total emitted power, for choosing lights

    std::optional<LightLiSample> sampleLi(const glm::vec3& ref, const glm::vec2& u) const;
    // For a direction wi from ref that reaches this light (at pLight with normal nLight for
    // triangles; ignored for the environment). Zero for delta lights.
    float pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight) const;

    // Radiance leaving an area light at normal n towards w, at the point with texture coordinates tc.
    glm::vec3 L(const glm::vec3& n, const glm::vec3& w, const TexCoords& tc = {}) const;
    // Environment radiance arriving from direction `dir` (a ray's direction escaping the scene).
    glm::vec3 Le(const glm::vec3& dir) const;

    std::optional<LightLeSample> sampleLe(const glm::vec2& u1, const glm::vec2& u2) const;
    void pdfLe(const Ray& ray, const glm::vec3& nLight, float* pdfPos, float* pdfDir) const;

private:
    struct Data;
    // Environment: a direction towards it with its solid-angle density, and that density.
    glm::vec3 sampleEnvironment(const glm::vec2& u, float* pdf) const;
    float environmentPdf(const glm::vec3& dir) const;
    // A triangle's radiance from its front at barycentrics b.
    glm::vec3 triangleRadiance(const glm::vec2& b) const;


    Type type_ = Type::Point;
    std::shared_ptr<const Data> data_;  // shared: lights are copied freely, never mutated after setup
};

}  // namespace woven
