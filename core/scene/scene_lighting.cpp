#include "scene_lighting.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <vector>

#include "environment_mapping.h"
#include "studio_environments.h"
#include "image_io.h"
#include "light_limits.h"
#include "math_constants.h"
#include "mesh_instances.h"
#include "scene_camera.h"
#include "scene_loader.h"
#include "srgb.h"

namespace woven {

namespace {

bool anyPositive(const glm::vec3& c) { return c.r > 0.0f || c.g > 0.0f || c.b > 0.0f; }

// The mean linear colour of a texture's texels (an emissive texture: sRGB-decoded where it is
// sRGB): what it scales its factor by over the surface, taken as mapped evenly.
glm::vec3 meanTexel(const TextureImage& image, bool srgb) {
    glm::dvec3 sum(0.0);
    for (const glm::u8vec4& t : image.bytes)
        for (int c = 0; c < 3; ++c) sum[c] += srgb ? srgbToLinear(float(t[c]) / 255.0f) : float(t[c]) / 255.0f;
    for (const glm::vec4& t : image.floats)
        for (int c = 0; c < 3; ++c) sum[c] += std::isfinite(t[c]) ? std::max(t[c], 0.0f) : 0.0f;
    const size_t n = image.bytes.size() + image.floats.size();
    return n ? glm::vec3(sum / double(n)) : glm::vec3(1.0f);
}

// The radiance a material emits on average: its factor (with emissive_strength) times the mean
// of its emissive texture. A texture that is mostly black (the lamps of a helmet, a label's
// printing) emits a small part of what its factor says.
float meanEmittedLuminance(const SceneDescription& scene, const Material& material) {
    glm::vec3 emission = material.emission;
    const TextureRef& texture = material.emissiveTexture;
    if (texture && size_t(texture.image) < scene.textures.size())
        emission *= meanTexel(scene.textures[size_t(texture.image)], texture.srgb);
    return luminance(emission);
}

}  // namespace

bool hasLightSources(const SceneDescription& scene) {
    for (const PunctualLight& l : scene.lights)
        if (anyPositive(l.intensity)) return true;
    const Environment& env = scene.environment;
    if (anyPositive(env.color) &&
        (!env.image || std::any_of(env.image->pixels.begin(), env.image->pixels.end(), anyPositive)))
        return true;
    return emitterIrradiance(scene, sceneBounds(scene).centre()) >= kDimIrradiance;
}

float emitterIrradiance(const SceneDescription& scene, const glm::vec3& at) {
    double sum = 0.0;
    std::vector<float> emitted(scene.materials.size(), -1.0f);  // each material's, once: a texture is read whole
    for (const Mesh& mesh : scene.meshes) {
        if (mesh.material < 0 || size_t(mesh.material) >= scene.materials.size()) continue;
        const Material& material = scene.materials[size_t(mesh.material)];
        if (!material.emits()) continue;
        float& L = emitted[size_t(mesh.material)];
        if (L < 0.0f) L = meanEmittedLuminance(scene, material);
        if (!(L > 0.0f)) continue;
        const size_t n = copies(mesh);
        for (size_t copy = 0; copy < n; ++copy) {
            const glm::mat4 place = mesh.instances ? (*mesh.instances)[copy] : glm::mat4(1.0f);
            for (const glm::uvec3& t : mesh.triangles) {
                const glm::vec3 a = glm::vec3(place * glm::vec4(mesh.positions[t.x], 1.0f));
                const glm::vec3 b = glm::vec3(place * glm::vec4(mesh.positions[t.y], 1.0f));
                const glm::vec3 c = glm::vec3(place * glm::vec4(mesh.positions[t.z], 1.0f));
                const glm::vec3 n2 = glm::cross(b - a, c - a);  // twice the area along the normal
                const float area = 0.5f * glm::length(n2);
                if (!(area > 0.0f)) continue;
                const glm::vec3 toAt = at - (a + b + c) / 3.0f;
                const float d2 = std::max(glm::dot(toAt, toAt), area);
                // The front's emission (a two-sided material also lights from the back).
                float cosine = 0.5f * glm::dot(n2, toAt) / (area * std::sqrt(glm::dot(toAt, toAt)) + 1e-30f);
                if (material.doubleSided) cosine = std::abs(cosine);
                if (cosine > 0.0f) sum += double(L) * area * cosine / d2;
            }
        }
    }
    return float(sum);
}

Environment studioEnvironment() {
    // The default camera looks at a scene from +z: the key comes from the front left and above,
    // the fill from the right, the rim from behind.
    const SoftBox boxes[] = {
        {{-0.6f, 0.65f, 0.55f}, 0.30f, 0.22f, 0.08f, 9.0f},
        {{0.85f, 0.2f, 0.35f}, 0.40f, 0.30f, 0.15f, 1.8f},
        {{0.25f, 0.55f, -0.85f}, 0.25f, 0.12f, 0.06f, 5.0f},
    };
    auto image = std::make_shared<Image>();
    image->width = 512;
    image->height = 256;
    image->pixels.resize(size_t(image->width) * image->height);
    double weighted = 0.0, solidAngle = 0.0;
    for (int y = 0; y < image->height; ++y) {
        const double rowSolidAngle = std::sin(kPiDouble * (y + 0.5) / image->height);
        for (int x = 0; x < image->width; ++x) {
            const glm::vec3 d = equirectDirection({(x + 0.5f) / image->width, (y + 0.5f) / image->height});
            // A dome brighter at the zenith over a light grey floor, blended across the horizon:
            // the backdrop a camera sees behind a model is not much darker than a viewer's grey.
            const float dome = 0.55f + 0.15f * std::max(d.y, 0.0f);
            const float floorRadiance = 0.45f;
            const float t = std::clamp(d.y / 0.05f * 0.5f + 0.5f, 0.0f, 1.0f);
            float L = floorRadiance + (dome - floorRadiance) * t;
            for (const SoftBox& box : boxes) L += box.at(d);
            image->at(x, y) = glm::vec3(L);
            weighted += rowSolidAngle * L;
            solidAngle += rowSolidAngle;
        }
    }
    // As much light, over the sphere, as a uniform environment of radiance 1 (`--environment 1`,
    // the grey many glTF viewers light a model by): a model is as bright at the defaults as
    // there, on average, with the soft boxes' shape added.
    const float scale = float(solidAngle / weighted);
    for (glm::vec3& p : image->pixels) p *= scale;
    Environment env;
    env.color = glm::vec3(1.0f);
    env.image = std::move(image);
    return env;
}

float lightIrradianceAtCentre(const SceneDescription& scene) {
    const SceneBox box = sceneBounds(scene);
    const glm::vec3 centre = box.centre();
    float sum = 0.0f;
    for (const PunctualLight& l : scene.lights) {
        const float I = luminance(l.intensity);
        if (l.type == PunctualLight::Type::Directional) sum += I;
        else sum += I / std::max(glm::dot(l.position - centre, l.position - centre), 1e-6f);
    }
    // A uniform environment of radiance L gives pi L on a surface; an image, pi times its mean.
    const Environment& env = scene.environment;
    float mean = luminance(env.color);
    if (env.image && !env.image->pixels.empty()) {
        double total = 0.0;
        for (const glm::vec3& p : env.image->pixels) total += luminance(p);
        mean *= float(total / double(env.image->pixels.size()));
    }
    return sum + kPi * mean + emitterIrradiance(scene, centre);
}

DefaultLighting lightByDefault(SceneDescription& scene) {
    if (scene.lightingFromSceneFile) return DefaultLighting::None;
    const DefaultLighting why = !hasLightSources(scene)                               ? DefaultLighting::NoLight
                                : lightIrradianceAtCentre(scene) < kDimIrradiance ? DefaultLighting::TooDim
                                                                                    : DefaultLighting::None;
    if (why != DefaultLighting::None) scene.environment = studioEnvironment();
    return why;
}

std::shared_ptr<Image> readEnvironmentImage(const std::string& path) {
    auto image = std::make_shared<Image>(readImage(path, ChannelEncoding::Srgb));
    size_t negative = 0;
    for (size_t i = 0; i < image->pixels.size(); ++i) {
        glm::vec3& p = image->pixels[i];
        negative += p.r < 0.0f || p.g < 0.0f || p.b < 0.0f;
        p = glm::max(p, glm::vec3(0.0f));
        if (const std::string problem = lightValueProblem(p); !problem.empty())
            throw ImageError(path + ": pixel (" + std::to_string(i % size_t(image->width)) + ", " +
                             std::to_string(i / size_t(image->width)) + ") " + problem);
    }
    if (negative)
        std::cerr << "warning: " << path << ": " << negative << " pixels with negative values read as 0\n";
    return image;
}

Environment environmentFromOption(const std::string& value) {
    if (value == "none") return Environment{};  // black: the scene's punctual lights alone
    if (const StudioEnvironment* studio = findStudioEnvironment(value)) return studio->make();
    char* end = nullptr;
    const float grey = std::strtof(value.c_str(), &end);
    Environment env;
    if (!value.empty() && end == value.c_str() + value.size()) {
        if (!std::isfinite(grey) || grey < 0.0f || grey > 1e6f)
            throw SceneError("--environment " + value + ": a grey radiance must be a number from 0 to 1e6");
        env.color = glm::vec3(grey);
        return env;
    }
    try {
        env.image = readEnvironmentImage(value);
    } catch (const ImageError& e) {
        throw SceneError(std::string("--environment: ") + e.what());
    }
    env.color = glm::vec3(1.0f);
    return env;
}

}  // namespace woven
