#include "preview_lights.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "environment_mapping.h"
#include "mesh_instances.h"

namespace woven {

namespace {

struct EmissiveTriangle {
    glm::vec3 a, b, c, L;
    bool twoSided;
};

// One light sample for a set of triangles: the area-weighted centroid and normal, carrying
// radiance x total area.
PreviewLight sampleOf(const EmissiveTriangle* first, const EmissiveTriangle* last) {
    glm::vec3 centroid(0.0f), normalSum(0.0f), power(0.0f);
    float area = 0.0f;
    bool twoSided = false;
    for (const EmissiveTriangle* t = first; t != last; ++t) {
        const glm::vec3 n2 = glm::cross(t->b - t->a, t->c - t->a);
        const float a = 0.5f * glm::length(n2);
        centroid += a * (t->a + t->b + t->c) / 3.0f;
        normalSum += 0.5f * n2;
        power += a * t->L;
        area += a;
        twoSided |= t->twoSided;
    }
    PreviewLight l;
    l.type = twoSided ? PreviewLight::AreaTwoSided : PreviewLight::Area;
    l.position = area > 0.0f ? centroid / area : first->a;
    const float len = glm::length(normalSum);
    l.axis = len > 0.0f ? normalSum / len : glm::vec3(0.0f, 0.0f, 1.0f);
    l.intensity = power;
    l.area = area;
    return l;
}

}  // namespace

namespace {

// environmentLights() for a white environment: the image's analysis, which only the image and
// the rotation change.
EnvironmentLights analyseEnvironmentImage(const Image& im, float rotation, int maxLights) {
    EnvironmentLights out;
    // Cells of at most 128 x 64 pixels' worth: radiance x solid angle summed exactly per pixel.
    const int gw = std::min(im.width, 128), gh = std::min(im.height, 64);
    std::vector<glm::dvec3> power(size_t(gw) * gh, glm::dvec3(0.0));  // sum of L dOmega
    std::vector<double> solidAngle(size_t(gw) * gh, 0.0);
    for (int y = 0; y < im.height; ++y) {
        const double dOmega = 2.0 * M_PI / im.width * (std::cos(M_PI * y / im.height) - std::cos(M_PI * (y + 1) / im.height));
        const int cy = int(int64_t(y) * gh / im.height);
        for (int x = 0; x < im.width; ++x) {
            const size_t cell = size_t(cy) * gw + size_t(int64_t(x) * gw / im.width);
            power[cell] += dOmega * glm::dvec3(glm::max(im.at(x, y), glm::vec3(0.0f)));  // as core's light
            solidAngle[cell] += dOmega;
        }
    }
    auto luminance = [](const glm::dvec3& c) { return double(woven::luminance(glm::vec3(c))); };
    glm::dvec3 total(0.0);
    for (const glm::dvec3& p : power) total += p;
    const double meanLuminance = luminance(total) / (4.0 * M_PI);

    // Connected bright regions (4-neighbours, wrapping around in u).
    std::vector<int> region(power.size(), -1);
    struct Region {
        glm::dvec3 power{0.0}, direction{0.0};
    };
    std::vector<Region> regions;
    auto bright = [&](size_t c) { return solidAngle[c] > 0.0 && luminance(power[c]) / solidAngle[c] > 8.0 * meanLuminance; };
    for (size_t seed = 0; seed < power.size(); ++seed) {
        if (region[seed] >= 0 || meanLuminance <= 0.0 || !bright(seed)) continue;
        Region r;
        double regionLuminance = 0.0;
        std::vector<size_t> stack{seed};
        region[seed] = int(regions.size());
        while (!stack.empty()) {
            const size_t c = stack.back();
            stack.pop_back();
            const int cx = int(c % gw), cy = int(c / gw);
            r.power += power[c];
            regionLuminance += luminance(power[c]);
            r.direction += luminance(power[c]) * glm::dvec3(equirectDirection({(cx + 0.5f) / gw, (cy + 0.5f) / gh}));
            const int nx[4] = {(cx + 1) % gw, (cx + gw - 1) % gw, cx, cx}, ny[4] = {cy, cy, cy - 1, cy + 1};
            for (int k = 0; k < 4; ++k) {
                if (ny[k] < 0 || ny[k] >= gh) continue;
                const size_t n = size_t(ny[k]) * gw + nx[k];
                if (region[n] < 0 && bright(n)) {
                    region[n] = int(regions.size());
                    stack.push_back(n);
                }
            }
        }
        // A region that wraps around (a ring, a band of horizon glow) has no one direction: it
        // stays ambient.
        if (glm::length(r.direction) >= 0.9 * regionLuminance) regions.push_back(r);
    }
    std::sort(regions.begin(), regions.end(),
              [&](const Region& a, const Region& b) { return luminance(a.power) > luminance(b.power); });
    glm::dvec3 rest = total;
    for (const Region& r : regions) {
        if (int(out.lights.size()) == maxLights) break;
        PreviewLight l;
        l.type = PreviewLight::Directional;
        // From the region's direction, travelling the other way.
        l.position = -rotateY(glm::normalize(glm::vec3(r.direction)), rotation);
        l.intensity = glm::vec3(r.power);
        out.lights.push_back(l);
        rest -= r.power;
    }
    out.ambient = glm::vec3(glm::max(rest, glm::dvec3(0.0)) / (4.0 * M_PI));
    return out;
}

}  // namespace

EnvironmentLights environmentLights(const Environment& env, int maxLights) {
    if (!env.image || env.image->width == 0 || env.image->height == 0) return {{}, env.color};
    // The window calls this for every light edit: the image is analysed once (per rotation).
    static std::weak_ptr<const Image> cachedImage;
    static float cachedRotation = 0.0f;
    static int cachedMaxLights = -1;
    static EnvironmentLights cached;
    if (cachedImage.lock() != env.image || cachedRotation != env.rotation || cachedMaxLights != maxLights) {
        cached = analyseEnvironmentImage(*env.image, env.rotation, maxLights);
        cachedImage = env.image;
        cachedRotation = env.rotation;
        cachedMaxLights = maxLights;
    }
    EnvironmentLights out = cached;
    for (PreviewLight& l : out.lights) l.intensity *= env.color;
    out.ambient *= env.color;
    return out;
}

PreviewLights PreviewLights::fromScene(const SceneDescription& scene) {
    PreviewLights out;
    for (const PunctualLight& p : scene.lights) {
        if (int(out.lights.size()) == kMaxLights) break;
        PreviewLight l;
        l.intensity = p.intensity;
        switch (p.type) {
            case PunctualLight::Type::Point: l.type = PreviewLight::Point; l.position = p.position; break;
            case PunctualLight::Type::Directional: l.type = PreviewLight::Directional; l.position = p.direction; break;
            case PunctualLight::Type::Spot:
                l.type = PreviewLight::Spot;
                l.position = p.position;
                l.axis = glm::normalize(p.direction);
                l.cosOuter = std::cos(p.outerConeAngle);
                l.cosInner = std::cos(p.innerConeAngle);
                break;
        }
        out.lights.push_back(l);
    }
    constexpr int kEnvironmentLights = 4;
    EnvironmentLights environment =
        environmentLights(scene.environment, std::min(kEnvironmentLights, kMaxLights - int(out.lights.size())));
    out.ambient = environment.ambient;
    out.lights.insert(out.lights.end(), environment.lights.begin(), environment.lights.end());

    std::vector<EmissiveTriangle> emissive;
    for (const Mesh& m : scene.meshes) {
        if (m.material < 0 || m.material >= int(scene.materials.size())) continue;
        const Material& mat = scene.materials[m.material];
        if (mat.emission == glm::vec3(0.0f)) continue;
        // Each copy of an instanced emitter where it is placed, a mirrored one's winding swapped
        // so that its front (the side a single-sided light shines to) stays the glTF rule's.
        for (size_t i = 0; i < copies(m); ++i) {
            const glm::mat4 place = m.instances ? (*m.instances)[i] : glm::mat4(1.0f);
            const auto at = [&](unsigned v) { return m.instances ? glm::vec3(place * glm::vec4(m.positions[v], 1.0f)) : m.positions[v]; };
            const bool mirrored = glm::determinant(glm::mat3(place)) < 0.0f;
            for (const glm::uvec3& t : m.triangles)
                emissive.push_back({at(t.x), at(mirrored ? t.z : t.y), at(mirrored ? t.y : t.z), mat.emission, mat.doubleSided});
        }
    }
    const int budget = kMaxLights - int(out.lights.size());
    if (emissive.empty() || budget <= 0) return out;
    if (int(emissive.size()) * 4 <= budget) {
        // Each triangle as its 4 midpoint-subdivided parts: close lights keep their extent.
        for (const EmissiveTriangle& t : emissive) {
            const glm::vec3 ab = 0.5f * (t.a + t.b), bc = 0.5f * (t.b + t.c), ca = 0.5f * (t.c + t.a);
            const EmissiveTriangle parts[4] = {{t.a, ab, ca, t.L, t.twoSided}, {ab, t.b, bc, t.L, t.twoSided},
                                               {ca, bc, t.c, t.L, t.twoSided}, {ab, bc, ca, t.L, t.twoSided}};
            for (const EmissiveTriangle& part : parts) out.lights.push_back(sampleOf(&part, &part + 1));
        }
    } else {
        // Consecutive triangles of a mesh lie close together: cluster them in order.
        const int clusters = std::min<int>(budget, int(emissive.size()));
        for (int c = 0; c < clusters; ++c) {
            const size_t first = emissive.size() * c / clusters, last = emissive.size() * (c + 1) / clusters;
            out.lights.push_back(sampleOf(&emissive[first], &emissive[0] + last));
        }
    }
    return out;
}

}  // namespace woven
