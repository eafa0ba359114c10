#pragma once
// Lights, shaped like pbrt-v3's Light interface so that both integrators can use every kind:
// emissive triangles and rectangles (area), point, spot, directional, and the environment
// (constant or equirectangular image, importance-sampled), each a struct of its own in a
// variant, as bsdf.h keeps its lobes. Which light a sample takes is light_sampler.h's choice.
// Radiance, importance and densities follow pbrt-v3's conventions: pdfLi is per unit solid
// angle at the reference point, pdfPos per unit area (or 1 for delta positions), pdfDir per
// unit solid angle (or 1 for delta directions).
#include <array>
#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <variant>

#include "interaction.h"
#include "piecewise_constant.h"
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

// KHR_lights_punctual's spot falloff: squared, linear in cos between the outer and inner cones.
struct SpotCone {
    float cosOuter = 1.0f, scale = 1.0f;
    SpotCone() = default;
    SpotCone(float inner, float outer);
    float falloff(float cosTheta) const;
    float solidAngle() const;  // the falloff's integral over the sphere
};

// The kinds of light, one struct each; Light holds one of them. Each has the members Light's
// interface forwards to (power, sampleLi, pdfLi, sampleLe, pdfLe) and says whether its position
// or direction is a delta and whether it lies at infinity.

// What emissive triangles and rectangles share: a flat face of radiance L from its front (and
// its back when twoSided), a cosine lobe each way. Both are sampled by area from afar and by
// solid angle near their plane, where area sampling's density in solid angle, d^2 / (cos_light
// area), grows without bound towards the edges.
struct PlanarEmitter {
    static constexpr bool kDeltaPosition = false, kDeltaDirection = false, kInfinite = false;
    glm::vec3 n{0.0f};
    float area = 0.0f;
    float longestEdge2 = 0.0f;  // squared
    bool twoSided = false;
    glm::vec3 L{0.0f};  // a triangle's with an emitter: its mean, for choosing lights by power

    glm::vec3 power() const;
    void pdfLe(const Ray& ray, const glm::vec3& nLight, float* pdfPos, float* pdfDir) const;

protected:
    // Whether ref is near enough the plane (closer than the longest edge: Cycles' test) for
    // sampling by solid angle to pay.
    bool nearPlane(const glm::vec3& ref, const glm::vec3& pointOfPlane) const;
    // ref lies behind a one-sided emitter or in its plane, where no point of it shines: a ceiling
    // above a lamp that lights downwards. Its samples would all carry no light.
    bool darkFrom(const glm::vec3& ref, const glm::vec3& pointOfPlane) const {
        return !twoSided && !(glm::dot(n, ref - pointOfPlane) > 0.0f);
    }
    // The sample of pLight from ref, its density by solidAngle (0: by area), L set where the face
    // towards ref emits (to `radiance`).
    std::optional<LightLiSample> towards(const glm::vec3& ref, const glm::vec3& pLight, float solidAngle,
                                         const glm::vec3& radiance) const;
    float pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight,
                float solidAngle) const;
    // A ray leaving `origin` on the face, cosine-distributed on a side chosen by u2 (L unset).
    std::optional<LightLeSample> leaving(const glm::vec3& origin, const glm::vec2& u2) const;
};

// An emissive triangle: the constant L, or the emission of a material (which must outlive the
// light) at the corners' texture coordinates. Near its plane it is sampled by solid angle with
// spherical_triangle.h.
struct TriangleLight : PlanarEmitter {
    glm::vec3 a{0.0f}, b{0.0f}, c{0.0f};
    const SurfaceMaterial* emitter = nullptr;  // else the constant L
    std::array<TexCoords, 3> corners;

    glm::vec3 radiance(const glm::vec2& barycentrics) const;  // from the front
    std::optional<LightLiSample> sampleLi(const glm::vec3& ref, const glm::vec2& u) const;
    // As sampleLi() at the centroid, by area, with the mean radiance L: no spherical triangle.
    std::optional<LightLiSample> centroidLi(const glm::vec3& ref) const;
    float pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight) const;
    std::optional<LightLeSample> sampleLe(const glm::vec2& u1, const glm::vec2& u2) const;
    // The solid angle sampleLi() samples uniformly from ref, 0 where it samples by area.
    float solidAngleSampled(const glm::vec3& ref) const;
};

// An emissive rectangle of constant radiance L: corner + s ex + t ey for s, t in [0, 1], ex and
// ey orthogonal, n along ex x ey. A mesh's rectangular lamp made of two triangles becomes one
// (render_scene.cpp), sampled near its plane by solid angle (spherical_rectangle.h) in one
// sample, with no choice between its halves.
struct RectangleLight : PlanarEmitter {
    glm::vec3 corner{0.0f}, ex{0.0f}, ey{0.0f};

    std::optional<LightLiSample> sampleLi(const glm::vec3& ref, const glm::vec2& u) const;
    std::optional<LightLiSample> centroidLi(const glm::vec3& ref) const;  // at its centre, by area
    float pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight) const;
    std::optional<LightLeSample> sampleLe(const glm::vec2& u1, const glm::vec2& u2) const;
    float solidAngleSampled(const glm::vec3& ref) const;
};

// Intensity I (W/sr) from a point, the same every way.
struct PointLight {
    static constexpr bool kDeltaPosition = true, kDeltaDirection = false, kInfinite = false;
    glm::vec3 position{0.0f}, I{0.0f};

    glm::vec3 power() const;
    std::optional<LightLiSample> sampleLi(const glm::vec3& ref, const glm::vec2& u) const;
    std::optional<LightLeSample> sampleLe(const glm::vec2& u1, const glm::vec2& u2) const;
    void pdfLe(const Ray& ray, const glm::vec3& nLight, float* pdfPos, float* pdfDir) const;
};

// A point's intensity I within a cone around `direction` (of travel), with the spot's falloff.
struct SpotLight {
    static constexpr bool kDeltaPosition = true, kDeltaDirection = false, kInfinite = false;
    glm::vec3 position{0.0f}, direction{0.0f, 0.0f, -1.0f}, I{0.0f};
    glm::vec3 x{0.0f}, y{0.0f};  // completing direction to a frame
    SpotCone cone;

    glm::vec3 power() const;
    std::optional<LightLiSample> sampleLi(const glm::vec3& ref, const glm::vec2& u) const;
    std::optional<LightLeSample> sampleLe(const glm::vec2& u1, const glm::vec2& u2) const;
    void pdfLe(const Ray& ray, const glm::vec3& nLight, float* pdfPos, float* pdfDir) const;
};

// The scene's bounding sphere, which infinite lights need to place and emit their rays.
struct SceneSphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

// Irradiance E (W/m^2) along `direction` (of travel), from infinitely far.
struct DirectionalLight {
    static constexpr bool kDeltaPosition = false, kDeltaDirection = true, kInfinite = true;
    glm::vec3 direction{0.0f, 0.0f, -1.0f}, E{0.0f};
    SceneSphere sphere;

    glm::vec3 power() const;
    std::optional<LightLiSample> sampleLi(const glm::vec3& ref, const glm::vec2& u) const;
    std::optional<LightLeSample> sampleLe(const glm::vec2& u1, const glm::vec2& u2) const;
    void pdfLe(const Ray& ray, const glm::vec3& nLight, float* pdfPos, float* pdfDir) const;
};

// Radiance from every direction: a colour, times an equirectangular image (importance-sampled
// by its piecewise-constant distribution) where there is one.
struct EnvironmentLight {
    static constexpr bool kDeltaPosition = false, kDeltaDirection = false, kInfinite = true;
    glm::vec3 color{0.0f};
    std::shared_ptr<const Image> image;
    float rotation = 0.0f;
    std::shared_ptr<const PiecewiseConstant2D> distribution;  // over the image's (u, v)
    glm::vec3 meanRadiance{0.0f};                             // over the sphere of directions
    SceneSphere sphere;

    glm::vec3 Le(const glm::vec3& dir) const;
    // A direction towards the environment with its solid-angle density, and that density.
    glm::vec3 sampleDirection(const glm::vec2& u, float* pdf) const;
    float pdfDirection(const glm::vec3& dir) const;
    glm::vec3 power() const;
    std::optional<LightLiSample> sampleLi(const glm::vec3& ref, const glm::vec2& u) const;
    float pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight) const;
    std::optional<LightLeSample> sampleLe(const glm::vec2& u1, const glm::vec2& u2) const;
    void pdfLe(const Ray& ray, const glm::vec3& nLight, float* pdfPos, float* pdfDir) const;
};

class Light {
public:
    using Kind = std::variant<TriangleLight, RectangleLight, PointLight, SpotLight, DirectionalLight, EnvironmentLight>;

    // An emissive triangle (world-space vertices) with radiance `L` from its front face
    // (and its back when `twoSided`).
    static Light triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& L, bool twoSided);
    // An emissive triangle of a material (which must outlive the light), whose emission (a
    // texture, perhaps) is looked up with the corners' texture coordinates; its power, for
    // choosing lights, is estimated from 16 points of the triangle.
    static Light triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const SurfaceMaterial& emitter,
                          const std::array<TexCoords, 3>& corners);
    // A rectangle (corner + s ex + t ey, ex orthogonal to ey) of radiance L from the face whose
    // normal is along ex x ey (and its back when `twoSided`).
    static Light rectangle(const glm::vec3& corner, const glm::vec3& ex, const glm::vec3& ey, const glm::vec3& L,
                           bool twoSided);
    static Light punctual(const PunctualLight& light);
    static Light environment(const Environment& env);  // builds the importance distribution

    template <class K>
    bool is() const { return std::holds_alternative<K>(kind_); }
    template <class K>
    const K* get() const { return std::get_if<K>(&kind_); }  // null when the light is another kind
    // The emissive surface, triangle or rectangle; null for the other kinds.
    const PlanarEmitter* planar() const;
    bool isDeltaPosition() const { return std::visit([](const auto& k) { return k.kDeltaPosition; }, kind_); }
    bool isDeltaDirection() const { return std::visit([](const auto& k) { return k.kDeltaDirection; }, kind_); }
    bool isDelta() const { return isDeltaPosition() || isDeltaDirection(); }
    bool isInfinite() const { return std::visit([](const auto& k) { return k.kInfinite; }, kind_); }

    // Infinite lights need the scene's extent; call once before sampling.
    void setSceneBounds(const Bounds& b);
    glm::vec3 power() const { return std::visit([](const auto& k) { return k.power(); }, kind_); }  // total emitted power

    std::optional<LightLiSample> sampleLi(const glm::vec3& ref, const glm::vec2& u) const {
        return std::visit([&](const auto& k) { return k.sampleLi(ref, u); }, kind_);
    }
    // The light from one fixed point of it, no random numbers: a triangle's centroid, a delta
    // light's one point or direction (the direct-light pass's, sample_contributions.h's FirstHit).
    std::optional<LightLiSample> fixedPointLi(const glm::vec3& ref) const;
    // For a direction wi from ref that reaches this light (at pLight with normal nLight for
    // triangles; ignored for the environment). Zero for delta lights.
    float pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight) const;

    // Radiance leaving an area light at normal n towards w, at the point with texture coordinates tc.
    glm::vec3 L(const glm::vec3& n, const glm::vec3& w, const TexCoords& tc = {}) const;
    // Environment radiance arriving from direction `dir` (a ray's direction escaping the scene).
    glm::vec3 Le(const glm::vec3& dir) const;

    std::optional<LightLeSample> sampleLe(const glm::vec2& u1, const glm::vec2& u2) const {
        return std::visit([&](const auto& k) { return k.sampleLe(u1, u2); }, kind_);
    }
    void pdfLe(const Ray& ray, const glm::vec3& nLight, float* pdfPos, float* pdfDir) const {
        std::visit([&](const auto& k) { k.pdfLe(ray, nLight, pdfPos, pdfDir); }, kind_);
    }

private:
    explicit Light(Kind kind) : kind_(std::move(kind)) {}
    Kind kind_;
};

}  // namespace woven
