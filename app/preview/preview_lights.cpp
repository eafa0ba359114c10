#include "preview_lights.h"

#include <algorithm>
#include <cmath>

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
    return l;
}

}  // namespace

glm::vec3 meanEnvironmentRadiance(const Environment& env) {
    if (!env.image || env.image->width == 0 || env.image->height == 0) return env.color;
    const Image& im = *env.image;
    glm::dvec3 sum(0.0);
    double weight = 0.0;
    for (int y = 0; y < im.height; ++y) {
        const double w = std::sin(M_PI * (y + 0.5) / im.height);  // solid angle of the row
        for (int x = 0; x < im.width; ++x) sum += w * glm::dvec3(im.at(x, y));
        weight += w * im.width;
    }
    return env.color * glm::vec3(sum / weight);
}

PreviewLights PreviewLights::fromScene(const SceneDescription& scene) {
    PreviewLights out;
    out.ambient = out.background = meanEnvironmentRadiance(scene.environment);
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
    std::vector<EmissiveTriangle> emissive;
    for (const Mesh& m : scene.meshes) {
        if (m.material < 0 || m.material >= int(scene.materials.size())) continue;
        const Material& mat = scene.materials[m.material];
        if (mat.emission == glm::vec3(0.0f)) continue;
        for (const glm::uvec3& t : m.triangles)
            emissive.push_back({m.positions[t.x], m.positions[t.y], m.positions[t.z], mat.emission, mat.doubleSided});
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
