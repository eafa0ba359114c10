#include "flat_cloth.h"

#include <cmath>

#include "scene_materials.h"
#include "yarn_noise.h"

namespace woven::test {

SceneDescription flatClothScene(const WovenParams& material) {
    Material cloth;
    cloth.woven = material;
    return flatScene(cloth);
}

SceneDescription flatScene(const Material& material) {
    Mesh m;
    m.name = "flat cloth";
    m.positions = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.tangents.assign(4, glm::vec4(1, 0, 0, 1));  // along +u; n x t = -z runs along +v
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.material = 0;

    SceneDescription scene;
    scene.source = "flat cloth";
    scene.meshes.push_back(m);
    scene.materials.push_back(material);

    PunctualLight point;
    point.type = PunctualLight::Type::Point;
    point.position = {-0.8f, 1.5f, 0.8f};
    point.intensity = glm::vec3(3.0f, 2.8f, 2.5f);
    PunctualLight sun;
    sun.type = PunctualLight::Type::Directional;
    sun.direction = glm::normalize(glm::vec3(0.5f, -1.0f, -0.2f));
    sun.intensity = glm::vec3(0.7f);
    scene.lights = {point, sun};

    scene.hasCamera = true;
    const glm::vec3 eye(0.0f, 1.3f, 1.7f);
    const glm::vec3 forward = glm::normalize(-eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, forward);
    scene.camera.cameraToWorld = glm::mat4(glm::vec4(right, 0), glm::vec4(up, 0), glm::vec4(-forward, 0), glm::vec4(eye, 1));
    scene.camera.yfov = 0.8f;
    return scene;
}

namespace {

glm::vec3 directLight(const SceneDescription& scene, const Bsdf& bsdf, const glm::vec3& p, const glm::vec3& ng,
                      const glm::vec3& wo) {
    glm::vec3 sum(0.0f);
    for (const PunctualLight& light : scene.lights) {
        glm::vec3 wi, L;
        if (light.type == PunctualLight::Type::Directional) {
            wi = -glm::normalize(light.direction);
            L = light.intensity;
        } else {
            const glm::vec3 d = light.position - p;
            wi = glm::normalize(d);
            L = light.intensity / glm::dot(d, d);
        }
        // A light in front with its cosine clamped, as lighting.glsl; one behind the cloth
        // reaches wo only through a BSDF that transmits. A BSDF that transmits connects wo and wi
        // where its shading normal parts them as the surface does (the integrators' connects()),
        // with their cosine.
        const glm::vec3& ns = bsdf.shadingNormal();
        const bool front = glm::dot(wi, ng) > 0.0f, shadingFront = glm::dot(wo, ns) * glm::dot(wi, ns) > 0.0f;
        if (!bsdf.transmits()) {
            if (front) sum += bsdf.eval(wo, wi) * L * std::fmax(0.0f, glm::dot(wi, ns));
        } else if (front == shadingFront) {
            sum += bsdf.eval(wo, wi) * L * std::fabs(glm::dot(wi, cosineNormal(bsdf, wo, wi)));
        }
    }
    return sum;
}

}  // namespace

glm::vec3 cameraRayDirection(const Camera& camera, float x, float y, int width, int height) {
    const float tanHalf = std::tan(0.5f * camera.yfov), aspect = float(width) / float(height);
    const glm::vec3 local((2.0f * x / width - 1.0f) * tanHalf * aspect, (1.0f - 2.0f * y / height) * tanHalf, -1.0f);
    return glm::normalize(glm::mat3(camera.cameraToWorld) * local);
}

Image coreDirectLighting(const SceneDescription& scene, int width, int height, int n, std::vector<uint8_t>* hitMask,
                         bool jittered) {
    const SceneMaterials materials(scene);
    const Camera& cam = scene.camera;
    const glm::vec3 eye(cam.cameraToWorld[3]);
    const glm::vec3 dpdu(2, 0, 0), dpdv(0, 0, -2), up(0, 1, 0);

    Image image;
    image.width = width;
    image.height = height;
    image.pixels.assign(size_t(width) * height, glm::vec3(0.0f));
    if (hitMask) hitMask->assign(image.pixels.size(), 0);
    for (int py = 0; py < height; ++py)
        for (int px = 0; px < width; ++px) {
            glm::vec3 sum(0.0f);
            int yarnHits = 0;
            for (int sy = 0; sy < n; ++sy)
                for (int sx = 0; sx < n; ++sx) {
                    glm::vec2 at(0.5f);
                    if (jittered) {
                        const uint32_t key = ((uint32_t(py) * uint32_t(width) + uint32_t(px)) * uint32_t(n * n) +
                                              uint32_t(sy * n + sx)) * 2U;
                        at = glm::vec2(float(hash32(key) >> 8), float(hash32(key + 1U) >> 8)) * 0x1p-24f;
                    }
                    const glm::vec3 d = cameraRayDirection(cam, px + (sx + at.x) / n, py + (sy + at.y) / n, width, height);
                    const float t = -eye.y / d.y;
                    const glm::vec3 p = eye + t * d;
                    glm::vec3 L = scene.environment.color;
                    bool onYarn = false;
                    if (t > 0.0f && std::fabs(p.x) <= 1.0f && std::fabs(p.z) <= 1.0f) {
                        SurfaceHit hit;
                        hit.p = p;
                        hit.ng = hit.ns = up;
                        hit.dpdu = dpdu;
                        hit.dpdv = dpdv;
                        hit.tex.uv[0] = glm::vec2((p.x + 1.0f) / 2.0f, (1.0f - p.z) / 2.0f);
                        hit.tex.hasUv = true;
                        hit.material = 0;
                        const glm::vec3 wo = -d;
                        const auto bsdf = materials[0].passesThrough(hit.tex, 0.0f) ? std::nullopt : materials.bsdf(hit, wo);
                        if (bsdf) {
                            L = directLight(scene, *bsdf, p, glm::dot(wo, up) < 0.0f ? -up : up, wo);
                            onYarn = true;
                        }
                    }
                    sum += L;
                    yarnHits += onYarn;
                }
            image.at(px, py) = sum / float(n * n);
            if (hitMask) (*hitMask)[size_t(py) * width + px] = yarnHits == n * n;
        }
    return image;
}

}  // namespace woven::test
