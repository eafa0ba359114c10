#include "light.h"

#include <algorithm>
#include <cmath>

#include "environment_mapping.h"
#include "frame.h"
#include "piecewise_constant.h"
#include "sampling.h"

namespace woven {

namespace {
constexpr float kPi = 3.14159265358979f;

glm::vec3 orthogonal(const glm::vec3& n, glm::vec3* b) {
    const Frame f = Frame::fromNormal(n);
    *b = f.y;
    return f.x;
}

glm::vec2 sampleUniformDisk(const glm::vec2& u) {
    const float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi)};
}

// Cone around +z up to cosMax, uniform in solid angle.
glm::vec3 sampleUniformCone(const glm::vec2& u, float cosMax) {
    const float cosTheta = 1.0f - u.x * (1.0f - cosMax);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * kPi * u.y;
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

float average(const glm::vec3& c) { return (c.r + c.g + c.b) / 3.0f; }

// KHR_lights_punctual's spot falloff: squared, linear in cos between the outer and inner cones.
struct SpotCone {
    float cosOuter, scale;
    SpotCone(float inner, float outer)
        : cosOuter(std::cos(outer)), scale(1.0f / std::max(1e-3f, std::cos(inner) - std::cos(outer))) {}
    float falloff(float cosTheta) const {
        const float f = std::clamp((cosTheta - cosOuter) * scale, 0.0f, 1.0f);
        return f * f;
    }
    // Integral of falloff over the sphere: 2 pi (width / 3 + (1 - cosOuter - width)).
    float solidAngle() const {
        const float width = std::min(1.0f / scale, 1.0f - cosOuter);
        const float rampEnd = width * scale;  // falloff at the ramp's end: 1 unless the cone is cut at the pole
        return 2.0f * kPi * (width * rampEnd * rampEnd / 3.0f + (1.0f - cosOuter - width));
    }
};
}  // namespace

struct Light::Data {
    // Triangle
    glm::vec3 a{0.0f}, b{0.0f}, c{0.0f}, n{0.0f};
    float area = 0.0f;
    bool twoSided = false;
    const SurfaceMaterial* emitter = nullptr;  // else the constant L
    std::array<TexCoords, 3> corners;
    // Point, spot, directional: position, direction of travel; L is the intensity (W/sr) or the
    // directional light's irradiance (W/m^2). Triangle: radiance. Environment: colour.
    glm::vec3 position{0.0f}, direction{0.0f, 0.0f, -1.0f};
    glm::vec3 L{0.0f};
    glm::vec3 spotX{0.0f}, spotY{0.0f};
    SpotCone cone{0.0f, 0.0f};
    // Environment
    std::shared_ptr<const Image> image;
    float rotation = 0.0f;
    std::shared_ptr<const PiecewiseConstant2D> distribution;  // over the image's (u, v)
    glm::vec3 meanRadiance{0.0f};                             // over the sphere of directions
    // Infinite lights
    Bounds bounds;
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

Light Light::triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& L, bool twoSided) {
    auto d = std::make_shared<Data>();
    d->a = a;
    d->b = b;
    d->c = c;
    const glm::vec3 cr = glm::cross(b - a, c - a);
    d->area = 0.5f * glm::length(cr);
    d->n = d->area > 0.0f ? glm::normalize(cr) : glm::vec3(0.0f);
    d->L = L;
    d->twoSided = twoSided;
    Light light;
    light.type_ = Type::Triangle;
    light.data_ = std::move(d);
    return light;
}

Light Light::triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const SurfaceMaterial& emitter,
                      const std::array<TexCoords, 3>& corners) {
    Light light = triangle(a, b, c, glm::vec3(0.0f), emitter.twoSidedEmission());
    auto d = std::make_shared<Data>(*light.data_);
    d->emitter = &emitter;
    d->corners = corners;
    light.data_ = d;
    // L only chooses lights by power: the mean over a 4 x 4 stratified set of points.
    glm::vec3 sum(0.0f);
    for (int i = 0; i < 16; ++i) sum += light.triangleRadiance(sampleTriangleBarycentrics({(i % 4 + 0.5f) / 4, (i / 4 + 0.5f) / 4}));
    d->L = sum / 16.0f;
    return light;
}

glm::vec3 Light::triangleRadiance(const glm::vec2& b) const {
    const Data& d = *data_;
    if (!d.emitter) return d.L;
    const float b0 = 1.0f - b.x - b.y;
    TexCoords tc = d.corners[0];
    for (int set = 0; set < 2; ++set)
        tc.uv[set] = b0 * d.corners[0].uv[set] + b.x * d.corners[1].uv[set] + b.y * d.corners[2].uv[set];
    tc.color = b0 * d.corners[0].color + b.x * d.corners[1].color + b.y * d.corners[2].color;
    return d.emitter->emission(tc);
}

Light Light::punctual(const PunctualLight& p) {
    auto d = std::make_shared<Data>();
    d->position = p.position;
    d->direction = glm::normalize(p.direction);
    d->L = p.intensity;
    Light light;
    switch (p.type) {
    case PunctualLight::Type::Point: light.type_ = Type::Point; break;
    case PunctualLight::Type::Spot:
        light.type_ = Type::Spot;
        d->cone = SpotCone(p.innerConeAngle, p.outerConeAngle);
        d->spotX = orthogonal(d->direction, &d->spotY);
        break;
    case PunctualLight::Type::Directional: light.type_ = Type::Directional; break;
    }
    light.data_ = std::move(d);
    return light;
}

Light Light::environment(const Environment& env) {
    auto d = std::make_shared<Data>();
    d->L = env.color;
    d->rotation = env.rotation;
    d->meanRadiance = env.color;
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
        d->meanRadiance = env.color * glm::vec3(weighted / weights);
        d->distribution = std::make_shared<PiecewiseConstant2D>(func, w, h);
        d->image = std::move(image);
    }
    Light light;
    light.type_ = Type::Environment;
    light.data_ = std::move(d);
    return light;
}

void Light::setSceneBounds(const Bounds& b) {
    auto d = std::make_shared<Data>(*data_);
    d->bounds = b;
    d->centre = b.centre();
    d->radius = std::max(b.radius(), 1e-3f);
    data_ = std::move(d);
}

glm::vec3 Light::power() const {
    const Data& d = *data_;
    switch (type_) {
    case Type::Triangle: return d.L * d.area * kPi * (d.twoSided ? 2.0f : 1.0f);
    case Type::Point: return 4.0f * kPi * d.L;
    case Type::Spot: return d.L * d.cone.solidAngle();
    case Type::Directional: return d.L * kPi * d.radius * d.radius;
    // Flux arriving on the scene's bounding sphere (pbrt-v4's 4 pi^2 r^2 L).
    case Type::Environment: return 4.0f * kPi * kPi * d.radius * d.radius * d.meanRadiance;
    }
    return glm::vec3(0.0f);
}

glm::vec3 Light::L(const glm::vec3& n, const glm::vec3& w, const TexCoords& tc) const {
    if (type_ != Type::Triangle) return glm::vec3(0.0f);
    if (!data_->twoSided && !(glm::dot(n, w) > 0.0f)) return glm::vec3(0.0f);
    return data_->emitter ? data_->emitter->emission(tc) : data_->L;
}

glm::vec3 Light::Le(const glm::vec3& dir) const {
    if (type_ != Type::Environment) return glm::vec3(0.0f);
    const Data& d = *data_;
    if (!d.image) return d.L;
    const glm::vec2 uv = equirectUv(rotateY(glm::normalize(dir), -d.rotation));
    // fmin/fmax also map a NaN (from a zero direction) to a pixel rather than to undefined behaviour.
    const int x = int(std::fmin(std::fmax(uv.x * d.image->width, 0.0f), float(d.image->width - 1)));
    const int y = int(std::fmin(std::fmax(uv.y * d.image->height, 0.0f), float(d.image->height - 1)));
    return d.L * d.image->at(x, y);
}

glm::vec3 Light::sampleEnvironment(const glm::vec2& u, float* pdf) const {
    const Data& d = *data_;
    if (!d.distribution) {
        *pdf = 1.0f / (4.0f * kPi);
        return sampleUniformSphere(u);
    }
    float pdfUv;
    const glm::vec2 uv = d.distribution->sample(u, &pdfUv);
    const float sinTheta = std::sin(kPi * uv.y);
    // dOmega = sin(theta) dtheta dphi = 2 pi^2 sin(theta) du dv
    *pdf = sinTheta > 0.0f ? pdfUv / (2.0f * kPi * kPi * sinTheta) : 0.0f;
    return rotateY(equirectDirection(uv), d.rotation);
}

float Light::environmentPdf(const glm::vec3& dir) const {
    const Data& d = *data_;
    if (!d.distribution) return 1.0f / (4.0f * kPi);
    const glm::vec2 uv = equirectUv(rotateY(glm::normalize(dir), -d.rotation));
    const float sinTheta = std::sin(kPi * uv.y);
    return sinTheta > 0.0f ? d.distribution->pdf(uv) / (2.0f * kPi * kPi * sinTheta) : 0.0f;
}

std::optional<LightLiSample> Light::sampleLi(const glm::vec3& ref, const glm::vec2& u) const {
    const Data& d = *data_;
    LightLiSample s;
    s.nLight = glm::vec3(0.0f);
    switch (type_) {
    case Type::Triangle: {
        if (!(d.area > 0.0f)) return std::nullopt;
        const glm::vec2 b = sampleTriangleBarycentrics(u);
        s.pLight = (1.0f - b.x - b.y) * d.a + b.x * d.b + b.y * d.c;
        s.nLight = d.n;
        const glm::vec3 toLight = s.pLight - ref;
        const float dist2 = glm::dot(toLight, toLight);
        if (!(dist2 > 0.0f)) return std::nullopt;
        s.wi = toLight / std::sqrt(dist2);
        const float cosLight = std::abs(glm::dot(d.n, s.wi));
        if (!(cosLight > 0.0f)) return std::nullopt;
        s.pdf = dist2 / (cosLight * d.area);
        s.L = data_->twoSided || glm::dot(d.n, -s.wi) > 0.0f ? triangleRadiance(b) : glm::vec3(0.0f);
        break;
    }
    case Type::Point:
    case Type::Spot: {
        s.pLight = d.position;
        const glm::vec3 toLight = d.position - ref;
        const float dist2 = glm::dot(toLight, toLight);
        if (!(dist2 > 0.0f)) return std::nullopt;
        s.wi = toLight / std::sqrt(dist2);
        s.pdf = 1.0f;
        s.L = d.L / dist2;
        if (type_ == Type::Spot) s.L *= d.cone.falloff(glm::dot(-s.wi, d.direction));
        break;
    }
    case Type::Directional:
        s.wi = -d.direction;
        s.pLight = ref + s.wi * (2.0f * d.radius);
        s.pdf = 1.0f;
        s.L = d.L;
        break;
    case Type::Environment: {
        s.wi = sampleEnvironment(u, &s.pdf);
        if (!(s.pdf > 0.0f)) return std::nullopt;
        s.pLight = ref + s.wi * (2.0f * d.radius);
        s.L = Le(s.wi);
        break;
    }
    }
    return s;
}

float Light::pdfLi(const glm::vec3& ref, const glm::vec3& wi, const glm::vec3& pLight, const glm::vec3& nLight) const {
    switch (type_) {
    case Type::Triangle: {
        const glm::vec3 toLight = pLight - ref;
        const float cosLight = std::abs(glm::dot(nLight, glm::normalize(wi)));
        if (!(cosLight > 0.0f) || !(data_->area > 0.0f)) return 0.0f;
        return glm::dot(toLight, toLight) / (cosLight * data_->area);
    }
    case Type::Environment: return environmentPdf(wi);
    default: return 0.0f;
    }
}

std::optional<LightLeSample> Light::sampleLe(const glm::vec2& u1, const glm::vec2& u2) const {
    const Data& d = *data_;
    LightLeSample s;
    switch (type_) {
    case Type::Triangle: {
        if (!(d.area > 0.0f)) return std::nullopt;
        const glm::vec2 b = sampleTriangleBarycentrics(u1);
        s.ray.o = (1.0f - b.x - b.y) * d.a + b.x * d.b + b.y * d.c;
        // Two-sided: u2.x picks the face, then is stretched back to [0, 1).
        glm::vec2 uDir = u2;
        glm::vec3 n = d.n;
        float sidePdf = 1.0f;
        if (d.twoSided) {
            sidePdf = 0.5f;
            if (uDir.x < 0.5f) uDir.x *= 2.0f;
            else { uDir.x = 2.0f * uDir.x - 1.0f; n = -n; }
        }
        const glm::vec3 local = sampleCosineHemisphere(uDir);
        s.ray.d = Frame::fromNormal(n).toWorld(local);
        s.nLight = n;
        s.pdfPos = 1.0f / d.area;
        s.pdfDir = sidePdf * local.z / kPi;
        if (!(s.pdfDir > 0.0f)) return std::nullopt;
        s.L = triangleRadiance(b);
        break;
    }
    case Type::Point:
    case Type::Spot: {
        s.ray.o = d.position;
        s.nLight = glm::vec3(0.0f);
        s.pdfPos = 1.0f;
        s.L = d.L;
        if (type_ == Type::Point) {
            s.ray.d = sampleUniformSphere(u1);
            s.pdfDir = 1.0f / (4.0f * kPi);
        } else {
            const glm::vec3 local = sampleUniformCone(u1, d.cone.cosOuter);
            s.ray.d = local.x * d.spotX + local.y * d.spotY + local.z * d.direction;
            s.pdfDir = 1.0f / (2.0f * kPi * (1.0f - d.cone.cosOuter));
            s.L *= d.cone.falloff(local.z);
        }
        break;
    }
    case Type::Directional:
    case Type::Environment: {
        // A ray towards the scene from a disk of the bounding sphere's radius, perpendicular to
        // its direction and one radius outside the sphere's centre (pbrt-v3).
        glm::vec3 toLight;
        if (type_ == Type::Directional) {
            toLight = -d.direction;
            s.pdfDir = 1.0f;
        } else {
            toLight = sampleEnvironment(u1, &s.pdfDir);
            if (!(s.pdfDir > 0.0f)) return std::nullopt;
        }
        glm::vec3 v2;
        const glm::vec3 v1 = orthogonal(toLight, &v2);
        const glm::vec2 disk = sampleUniformDisk(u2);
        s.ray.o = d.centre + d.radius * (disk.x * v1 + disk.y * v2 + toLight);
        s.ray.d = -toLight;
        s.nLight = s.ray.d;
        s.pdfPos = 1.0f / (kPi * d.radius * d.radius);
        s.L = type_ == Type::Directional ? d.L : Le(toLight);
        break;
    }
    }
    return s;
}

void Light::pdfLe(const Ray& ray, const glm::vec3& nLight, float* pdfPos, float* pdfDir) const {
    const Data& d = *data_;
    switch (type_) {
    case Type::Triangle: {
        const float cosTheta = glm::dot(nLight, ray.d);
        *pdfPos = d.area > 0.0f ? 1.0f / d.area : 0.0f;
        *pdfDir = d.twoSided ? 0.5f * std::abs(cosTheta) / kPi : std::max(cosTheta, 0.0f) / kPi;
        break;
    }
    case Type::Point:
        *pdfPos = 0.0f;
        *pdfDir = 1.0f / (4.0f * kPi);
        break;
    case Type::Spot:
        *pdfPos = 0.0f;
        *pdfDir = glm::dot(ray.d, d.direction) >= d.cone.cosOuter ? 1.0f / (2.0f * kPi * (1.0f - d.cone.cosOuter)) : 0.0f;
        break;
    case Type::Directional:
        *pdfPos = 1.0f / (kPi * d.radius * d.radius);
        *pdfDir = 0.0f;
        break;
    case Type::Environment:
        *pdfPos = 1.0f / (kPi * d.radius * d.radius);
        *pdfDir = environmentPdf(-ray.d);
        break;
    }
}

}  // namespace woven
