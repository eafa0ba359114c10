#include "light.h"

#include <algorithm>
#include <cmath>

#include "environment_mapping.h"
#include "frame.h"
#include "math_constants.h"
#include "piecewise_constant.h"
#include "sampling.h"
#include "spherical_rectangle.h"
#include "spherical_triangle.h"

namespace woven {

namespace {
glm::vec3 orthogonal(const glm::vec3& n, glm::vec3* b) {
    const Frame f = Frame::fromNormal(n);
    *b = f.y;
    return f.x;
}

float average(const glm::vec3& c) { return (c.r + c.g + c.b) / 3.0f; }

// The solid angle a planar light is sampled by from a point near its plane, where it lies within
// the bounds in which that is sound (spherical_triangle.h); else 0: sampled by area.
float samplableSolidAngle(float solidAngle) {
    return solidAngle >= kMinSphericalSampleArea && solidAngle <= kMaxSphericalSampleArea ? solidAngle : 0.0f;
}

// A ray towards the scene from infinitely far along -toLight: from a disk of the bounding
// sphere's radius, perpendicular to it and one radius outside the sphere's centre (pbrt-v3).
void infiniteLightRay(const SceneSphere& sphere, const glm::vec3& toLight, const glm::vec2& u, LightLeSample* s) {
    glm::vec3 v2;
    const glm::vec3 v1 = orthogonal(toLight, &v2);
    const glm::vec2 disk = sampleUniformDisk(u);
    s->ray.o = sphere.centre + sphere.radius * (disk.x * v1 + disk.y * v2 + toLight);
    s->ray.d = -toLight;
    s->nLight = s->ray.d;
    s->pdfPos = 1.0f / (kPi * sphere.radius * sphere.radius);
}

// The density of a ray's origin on that disk.
float infiniteLightPdfPos(const SceneSphere& sphere) { return 1.0f / (kPi * sphere.radius * sphere.radius); }

// A point light's sample towards ref: its intensity over the squared distance.
std::optional<LightLiSample> pointSampleLi(const glm::vec3& position, const glm::vec3& I, const glm::vec3& ref) {
    LightLiSample s;
    s.nLight = glm::vec3(0.0f);
    s.pLight = position;
    const glm::vec3 toLight = position - ref;
    const float dist2 = glm::dot(toLight, toLight);
    if (!(dist2 > 0.0f)) return std::nullopt;
    s.wi = toLight / std::sqrt(dist2);
    s.pdf = 1.0f;
    s.L = I / dist2;
    return s;
}
}  // namespace

SpotCone::SpotCone(float inner, float outer)
    : cosOuter(std::cos(outer)), scale(1.0f / std::max(1e-3f, std::cos(inner) - std::cos(outer))) {}

float SpotCone::falloff(float cosTheta) const {
    const float f = std::clamp((cosTheta - cosOuter) * scale, 0.0f, 1.0f);
    return f * f;
}

// 2 pi (width / 3 + (1 - cosOuter - width)).
float SpotCone::solidAngle() const {
    const float width = std::min(1.0f / scale, 1.0f - cosOuter);
    const float rampEnd = width * scale;  // falloff at the ramp's end: 1 unless the cone is cut at the pole
    return 2.0f * kPi * (width * rampEnd * rampEnd / 3.0f + (1.0f - cosOuter - width));
}

// Planar emitters: triangles and rectangles

glm::vec3 PlanarEmitter::power() const { return L * area * kPi * (twoSided ? 2.0f : 1.0f); }

bool PlanarEmitter::nearPlane(const glm::vec3& ref, const glm::vec3& pointOfPlane) const {
    const float height = glm::dot(n, ref - pointOfPlane);
    return height * height < longestEdge2;
}

std::optional<LightLiSample> PlanarEmitter::towards(const glm::vec3& ref, const glm::vec3& pLight, float solidAngle,
                                                    const glm::vec3& radiance) const {
    LightLiSample s;
    s.pLight = pLight;
    s.nLight = n;
    const glm::vec3 toLight = s.pLight - ref;
    const float dist2 = glm::dot(toLight, toLight);
    if (!(dist2 > 0.0f)) return std::nullopt;
    s.wi = toLight / std::sqrt(dist2);
    const float cosLight = glm::dot(n, -s.wi);
    if (!(std::abs(cosLight) > 0.0f)) return std::nullopt;
    s.pdf = solidAngle > 0.0f ? 1.0f / solidAngle : dist2 / (std::abs(cosLight) * area);
    s.L = twoSided || cosLight > 0.0f ? radiance : glm::vec3(0.0f);
    return s;
}

float PlanarEmitter::pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight,
                           float solidAngle) const {
    if (!(area > 0.0f)) return 0.0f;
    if (solidAngle > 0.0f) return 1.0f / solidAngle;
    const glm::vec3 toLight = pLight - ref;
    const float cosLight = std::abs(glm::dot(nLight, glm::normalize(wi)));
    if (!(cosLight > 0.0f)) return 0.0f;
    return glm::dot(toLight, toLight) / (cosLight * area);
}

std::optional<LightLeSample> PlanarEmitter::leaving(const glm::vec3& origin, const glm::vec2& u2) const {
    LightLeSample s;
    s.ray.o = origin;
    // Two-sided: u2.x picks the face, then is stretched back to [0, 1).
    glm::vec2 uDir = u2;
    glm::vec3 face = n;
    float sidePdf = 1.0f;
    if (twoSided) {
        sidePdf = 0.5f;
        if (uDir.x < 0.5f) uDir.x *= 2.0f;
        else { uDir.x = 2.0f * uDir.x - 1.0f; face = -face; }
    }
    const glm::vec3 local = sampleCosineHemisphere(uDir);
    s.ray.d = Frame::fromNormal(face).toWorld(local);
    s.nLight = face;
    s.pdfPos = 1.0f / area;
    s.pdfDir = sidePdf * local.z / kPi;
    if (!(s.pdfDir > 0.0f)) return std::nullopt;
    return s;
}

void PlanarEmitter::pdfLe(const Ray& ray, const glm::vec3& nLight, float* pdfPos, float* pdfDir) const {
    const float cosTheta = glm::dot(nLight, ray.d);
    *pdfPos = area > 0.0f ? 1.0f / area : 0.0f;
    *pdfDir = twoSided ? 0.5f * std::abs(cosTheta) / kPi : std::max(cosTheta, 0.0f) / kPi;
}

glm::vec3 TriangleLight::radiance(const glm::vec2& bary) const {
    if (!emitter) return L;
    const float b0 = 1.0f - bary.x - bary.y;
    TexCoords tc = corners[0];
    for (int set = 0; set < 2; ++set)
        tc.uv[set] = b0 * corners[0].uv[set] + bary.x * corners[1].uv[set] + bary.y * corners[2].uv[set];
    tc.color = b0 * corners[0].color + bary.x * corners[1].color + bary.y * corners[2].color;
    return emitter->emission(tc);
}

float TriangleLight::solidAngleSampled(const glm::vec3& ref) const {
    return nearPlane(ref, a) ? samplableSolidAngle(triangleSolidAngle(a, b, c, ref)) : 0.0f;
}

std::optional<LightLiSample> TriangleLight::sampleLi(const glm::vec3& ref, const glm::vec2& u) const {
    if (!(area > 0.0f) || darkFrom(ref, a)) return std::nullopt;
    const float solidAngle = solidAngleSampled(ref);
    glm::vec2 bary;
    if (solidAngle > 0.0f) {
        const auto sampled = sampleSphericalTriangle(a, b, c, ref, solidAngle, u);
        if (!sampled) return std::nullopt;
        bary = *sampled;
    } else {
        bary = sampleTriangleBarycentrics(u);
    }
    return towards(ref, (1.0f - bary.x - bary.y) * a + bary.x * b + bary.y * c, solidAngle, radiance(bary));
}

std::optional<LightLiSample> TriangleLight::centroidLi(const glm::vec3& ref) const {
    if (!(area > 0.0f)) return std::nullopt;
    return towards(ref, (a + b + c) / 3.0f, 0.0f, L);
}

float TriangleLight::pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight) const {
    return PlanarEmitter::pdfLi(ref, wi, pLight, nLight, solidAngleSampled(ref));
}

std::optional<LightLeSample> TriangleLight::sampleLe(const glm::vec2& u1, const glm::vec2& u2) const {
    if (!(area > 0.0f)) return std::nullopt;
    const glm::vec2 bary = sampleTriangleBarycentrics(u1);
    auto s = leaving((1.0f - bary.x - bary.y) * a + bary.x * b + bary.y * c, u2);
    if (s) s->L = radiance(bary);
    return s;
}

float RectangleLight::solidAngleSampled(const glm::vec3& ref) const {
    return nearPlane(ref, corner) ? samplableSolidAngle(SphericalRectangle(corner, ex, ey, ref).solidAngle()) : 0.0f;
}

std::optional<LightLiSample> RectangleLight::sampleLi(const glm::vec3& ref, const glm::vec2& u) const {
    if (!(area > 0.0f) || darkFrom(ref, corner)) return std::nullopt;
    if (nearPlane(ref, corner)) {  // as solidAngleSampled(), keeping the rectangle to sample
        const SphericalRectangle rectangle(corner, ex, ey, ref);
        if (const float solidAngle = samplableSolidAngle(rectangle.solidAngle()); solidAngle > 0.0f)
            return towards(ref, rectangle.sample(u), solidAngle, L);
    }
    return towards(ref, corner + u.x * ex + u.y * ey, 0.0f, L);
}

std::optional<LightLiSample> RectangleLight::centroidLi(const glm::vec3& ref) const {
    if (!(area > 0.0f)) return std::nullopt;
    return towards(ref, corner + 0.5f * (ex + ey), 0.0f, L);
}

float RectangleLight::pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight,
                            const glm::vec3& nLight) const {
    return PlanarEmitter::pdfLi(ref, wi, pLight, nLight, solidAngleSampled(ref));
}

std::optional<LightLeSample> RectangleLight::sampleLe(const glm::vec2& u1, const glm::vec2& u2) const {
    if (!(area > 0.0f)) return std::nullopt;
    auto s = leaving(corner + u1.x * ex + u1.y * ey, u2);
    if (s) s->L = L;
    return s;
}

std::optional<LightLiSample> Light::fixedPointLi(const glm::vec3& ref) const {
    if (const TriangleLight* t = get<TriangleLight>()) return t->centroidLi(ref);
    if (const RectangleLight* r = get<RectangleLight>()) return r->centroidLi(ref);
    return sampleLi(ref, glm::vec2(0.5f));
}

// Point

glm::vec3 PointLight::power() const { return 4.0f * kPi * I; }

std::optional<LightLiSample> PointLight::sampleLi(const glm::vec3& ref, const glm::vec2&) const {
    return pointSampleLi(position, I, ref);
}

std::optional<LightLeSample> PointLight::sampleLe(const glm::vec2& u1, const glm::vec2&) const {
    LightLeSample s;
    s.ray.o = position;
    s.nLight = glm::vec3(0.0f);
    s.pdfPos = 1.0f;
    s.L = I;
    s.ray.d = sampleUniformSphere(u1);
    s.pdfDir = 1.0f / (4.0f * kPi);
    return s;
}

void PointLight::pdfLe(const Ray&, const glm::vec3&, float* pdfPos, float* pdfDir) const {
    *pdfPos = 0.0f;
    *pdfDir = 1.0f / (4.0f * kPi);
}

// Spot

glm::vec3 SpotLight::power() const { return I * cone.solidAngle(); }

std::optional<LightLiSample> SpotLight::sampleLi(const glm::vec3& ref, const glm::vec2&) const {
    std::optional<LightLiSample> s = pointSampleLi(position, I, ref);
    if (s) s->L *= cone.falloff(glm::dot(-s->wi, direction));
    return s;
}

std::optional<LightLeSample> SpotLight::sampleLe(const glm::vec2& u1, const glm::vec2&) const {
    LightLeSample s;
    s.ray.o = position;
    s.nLight = glm::vec3(0.0f);
    s.pdfPos = 1.0f;
    s.L = I;
    const glm::vec3 local = sampleUniformCone(u1, cone.cosOuter);
    s.ray.d = local.x * x + local.y * y + local.z * direction;
    s.pdfDir = 1.0f / (2.0f * kPi * (1.0f - cone.cosOuter));
    s.L *= cone.falloff(local.z);
    return s;
}

void SpotLight::pdfLe(const Ray& ray, const glm::vec3&, float* pdfPos, float* pdfDir) const {
    *pdfPos = 0.0f;
    *pdfDir = glm::dot(ray.d, direction) >= cone.cosOuter ? 1.0f / (2.0f * kPi * (1.0f - cone.cosOuter)) : 0.0f;
}

// Directional

glm::vec3 DirectionalLight::power() const { return E * kPi * sphere.radius * sphere.radius; }

std::optional<LightLiSample> DirectionalLight::sampleLi(const glm::vec3& ref, const glm::vec2&) const {
    LightLiSample s;
    s.nLight = glm::vec3(0.0f);
    s.wi = -direction;
    s.pLight = ref + s.wi * (2.0f * sphere.radius);
    s.pdf = 1.0f;
    s.L = E;
    return s;
}

std::optional<LightLeSample> DirectionalLight::sampleLe(const glm::vec2&, const glm::vec2& u2) const {
    LightLeSample s;
    s.pdfDir = 1.0f;
    infiniteLightRay(sphere, -direction, u2, &s);
    s.L = E;
    return s;
}

void DirectionalLight::pdfLe(const Ray&, const glm::vec3&, float* pdfPos, float* pdfDir) const {
    *pdfPos = infiniteLightPdfPos(sphere);
    *pdfDir = 0.0f;
}

// Environment

glm::vec3 EnvironmentLight::Le(const glm::vec3& dir) const {
    if (!image) return color;
    const glm::vec2 uv = equirectUv(rotateY(glm::normalize(dir), -rotation));
    // fmin/fmax also map a NaN (from a zero direction) to a pixel rather than to undefined behaviour.
    const int px = int(std::fmin(std::fmax(uv.x * image->width, 0.0f), float(image->width - 1)));
    const int py = int(std::fmin(std::fmax(uv.y * image->height, 0.0f), float(image->height - 1)));
    return color * image->at(px, py);
}

glm::vec3 EnvironmentLight::sampleDirection(const glm::vec2& u, float* pdf) const {
    if (!distribution) {
        *pdf = 1.0f / (4.0f * kPi);
        return sampleUniformSphere(u);
    }
    float pdfUv;
    const glm::vec2 uv = distribution->sample(u, &pdfUv);
    const float sinTheta = std::sin(kPi * uv.y);
    // dOmega = sin(theta) dtheta dphi = 2 pi^2 sin(theta) du dv
    *pdf = sinTheta > 0.0f ? pdfUv / (2.0f * kPi * kPi * sinTheta) : 0.0f;
    return rotateY(equirectDirection(uv), rotation);
}

float EnvironmentLight::pdfDirection(const glm::vec3& dir) const {
    if (!distribution) return 1.0f / (4.0f * kPi);
    const glm::vec2 uv = equirectUv(rotateY(glm::normalize(dir), -rotation));
    const float sinTheta = std::sin(kPi * uv.y);
    return sinTheta > 0.0f ? distribution->pdf(uv) / (2.0f * kPi * kPi * sinTheta) : 0.0f;
}

// Flux arriving on the scene's bounding sphere (pbrt-v4's 4 pi^2 r^2 L).
glm::vec3 EnvironmentLight::power() const { return 4.0f * kPi * kPi * sphere.radius * sphere.radius * meanRadiance; }

std::optional<LightLiSample> EnvironmentLight::sampleLi(const glm::vec3& ref, const glm::vec2& u) const {
    LightLiSample s;
    s.nLight = glm::vec3(0.0f);
    s.wi = sampleDirection(u, &s.pdf);
    if (!(s.pdf > 0.0f)) return std::nullopt;
    s.pLight = ref + s.wi * (2.0f * sphere.radius);
    s.L = Le(s.wi);
    return s;
}

float EnvironmentLight::pdfLi(const glm::vec3&, const glm::vec3& wi, const glm::vec3&, const glm::vec3&) const {
    return pdfDirection(wi);
}

std::optional<LightLeSample> EnvironmentLight::sampleLe(const glm::vec2& u1, const glm::vec2& u2) const {
    LightLeSample s;
    const glm::vec3 toLight = sampleDirection(u1, &s.pdfDir);
    if (!(s.pdfDir > 0.0f)) return std::nullopt;
    infiniteLightRay(sphere, toLight, u2, &s);
    s.L = Le(toLight);
    return s;
}

void EnvironmentLight::pdfLe(const Ray& ray, const glm::vec3&, float* pdfPos, float* pdfDir) const {
    *pdfPos = infiniteLightPdfPos(sphere);
    *pdfDir = pdfDirection(-ray.d);
}

// Light

Light Light::triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& L, bool twoSided) {
    TriangleLight t;
    t.a = a;
    t.b = b;
    t.c = c;
    const glm::vec3 cr = glm::cross(b - a, c - a);
    t.area = 0.5f * glm::length(cr);
    t.n = t.area > 0.0f ? glm::normalize(cr) : glm::vec3(0.0f);
    const glm::vec3 e0 = b - a, e1 = c - b, e2 = a - c;
    t.longestEdge2 = std::max({glm::dot(e0, e0), glm::dot(e1, e1), glm::dot(e2, e2)});
    t.L = L;
    t.twoSided = twoSided;
    return Light(t);
}

Light Light::triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const SurfaceMaterial& emitter,
                      const std::array<TexCoords, 3>& corners) {
    TriangleLight t = std::get<TriangleLight>(triangle(a, b, c, glm::vec3(0.0f), emitter.twoSidedEmission()).kind_);
    t.emitter = &emitter;
    t.corners = corners;
    // L only chooses lights by power: the mean over a 4 x 4 stratified set of points.
    glm::vec3 sum(0.0f);
    for (int i = 0; i < 16; ++i) sum += t.radiance(sampleTriangleBarycentrics({(i % 4 + 0.5f) / 4, (i / 4 + 0.5f) / 4}));
    t.L = sum / 16.0f;
    return Light(t);
}

Light Light::rectangle(const glm::vec3& corner, const glm::vec3& ex, const glm::vec3& ey, const glm::vec3& L,
                       bool twoSided) {
    RectangleLight r;
    r.corner = corner;
    r.ex = ex;
    r.ey = ey;
    const glm::vec3 cr = glm::cross(ex, ey);
    r.area = glm::length(cr);
    r.n = r.area > 0.0f ? cr / r.area : glm::vec3(0.0f);
    r.longestEdge2 = std::max(glm::dot(ex, ex), glm::dot(ey, ey));
    r.L = L;
    r.twoSided = twoSided;
    return Light(r);
}

Light Light::punctual(const PunctualLight& p) {
    const glm::vec3 direction = glm::normalize(p.direction);
    switch (p.type) {
    case PunctualLight::Type::Point: return Light(PointLight{p.position, p.intensity});
    case PunctualLight::Type::Spot: {
        SpotLight s;
        s.position = p.position;
        s.direction = direction;
        s.I = p.intensity;
        s.cone = SpotCone(p.innerConeAngle, p.outerConeAngle);
        s.x = orthogonal(direction, &s.y);
        return Light(s);
    }
    case PunctualLight::Type::Directional: {
        DirectionalLight d;
        d.direction = direction;
        d.E = p.intensity;
        return Light(d);
    }
    }
    return Light(PointLight{p.position, p.intensity});
}

Light Light::environment(const Environment& env) {
    EnvironmentLight e;
    e.color = env.color;
    e.rotation = env.rotation;
    e.meanRadiance = env.color;
    if (env.image && env.image->width > 0 && env.image->height > 0) {
        auto image = std::make_shared<Image>(*env.image);
        for (glm::vec3& p : image->pixels) p = glm::max(p, glm::vec3(0.0f));  // negative radiance is noise
        const int w = image->width, h = image->height;
        // Radiance is a nearest-pixel lookup (as pbrt-v4's image infinite light does), so this
        // piecewise-constant density is proportional to the channel mean times sin(theta) of the
        // row's centre, the Jacobian of the equirectangular map.
        std::vector<float> func(size_t(w) * h);
        glm::dvec3 weighted(0.0);
        double weights = 0.0;
        for (int y = 0; y < h; ++y) {
            const float sinTheta = std::sin(kPi * (y + 0.5f) / h);
            for (int x = 0; x < w; ++x) {
                const glm::vec3& p = image->at(x, y);
                func[size_t(y) * w + x] = average(p) * sinTheta;
                weighted += glm::dvec3(p) * double(sinTheta);
            }
            weights += double(sinTheta) * w;
        }
        e.meanRadiance = env.color * glm::vec3(weighted / weights);
        e.distribution = std::make_shared<PiecewiseConstant2D>(func, w, h);
        e.image = std::move(image);
    }
    return Light(e);
}

void Light::setSceneBounds(const Bounds& b) {
    const SceneSphere sphere{b.centre(), std::max(b.radius(), 1e-3f)};
    if (auto* d = std::get_if<DirectionalLight>(&kind_)) d->sphere = sphere;
    if (auto* e = std::get_if<EnvironmentLight>(&kind_)) e->sphere = sphere;
}

const PlanarEmitter* Light::planar() const {
    if (const TriangleLight* t = get<TriangleLight>()) return t;
    return get<RectangleLight>();
}

float Light::pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight) const {
    if (const auto* t = std::get_if<TriangleLight>(&kind_)) return t->pdfLi(ref, wi, pLight, nLight);
    if (const auto* r = std::get_if<RectangleLight>(&kind_)) return r->pdfLi(ref, wi, pLight, nLight);
    if (const auto* e = std::get_if<EnvironmentLight>(&kind_)) return e->pdfLi(ref, wi, pLight, nLight);
    return 0.0f;  // a delta light: no direction reaches it by chance
}

glm::vec3 Light::L(const glm::vec3& n, const glm::vec3& w, const TexCoords& tc) const {
    const PlanarEmitter* e = planar();
    if (!e) return glm::vec3(0.0f);
    if (!e->twoSided && !(glm::dot(n, w) > 0.0f)) return glm::vec3(0.0f);
    const TriangleLight* t = get<TriangleLight>();
    return t && t->emitter ? t->emitter->emission(tc) : e->L;
}

glm::vec3 Light::Le(const glm::vec3& dir) const {
    const auto* e = std::get_if<EnvironmentLight>(&kind_);
    return e ? e->Le(dir) : glm::vec3(0.0f);
}

}  // namespace woven
