#include "bake_report.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "far_field.h"
#include "flat_cloth.h"
#include "gltf_material.h"
#include "display_transform.h"
#include "image_io.h"
#include "integrators.h"
#include "render_job.h"
#include "scene_camera.h"
#include "srgb.h"
#include "woven_surface_material.h"

namespace woven {

namespace {

constexpr float kYfov = 0.5f;  // radians

// The flat cloth: a square on y = 0 with one uv unit a metre, in `material` (over `textures`),
// seen from 45 degrees above across `threads` threads of `repeat` per uv unit, lit by a sun near
// the mirror direction of the view and a uniform sky.
SceneDescription clothScene(const Material& material, const std::vector<TextureImage>& textures, double threads, double repeat,
                            double aspect) {
    const double distance = threads / repeat / (2.0 * std::tan(0.5 * kYfov) * aspect);
    // Wide enough that the frame sees cloth only, also towards the horizon at 45 degrees.
    const float side = float(16.0 * distance + 2.0);
    const Mesh m = flatCloth(glm::vec2(side), "cloth");

    SceneDescription scene;
    scene.source = "the report's flat cloth";
    scene.meshes.push_back(m);
    scene.materials.push_back(material);
    scene.textures = textures;
    PunctualLight sun;
    sun.type = PunctualLight::Type::Directional;
    // The view's mirror direction (45 degrees, from the front) turned 25 degrees aside: the
    // yarns' bumped normals bring the highlight into the frame.
    sun.direction = -glm::normalize(glm::vec3(std::sin(0.44f), 1.0f, -std::cos(0.44f)));
    sun.intensity = glm::vec3(2.5f);
    scene.lights.push_back(sun);
    scene.environment.color = glm::vec3(0.35f, 0.38f, 0.42f);
    scene.lightingFromSceneFile = true;
    const float d = float(distance);
    scene.camera = lookAt(glm::vec3(0.0f, d * std::sqrt(0.5f), d * std::sqrt(0.5f)), glm::vec3(0.0f), glm::vec3(0, 1, 0), kYfov);
    scene.hasCamera = true;
    return scene;
}

Image renderCloth(const SceneDescription& scene, const ReportOptions& o, bool far, uint64_t seed) {
    RenderSettings settings;
    settings.width = far ? std::max(1, o.width / 4) : o.width;
    settings.height = far ? std::max(1, o.height / 4) : o.height;
    settings.spp = far ? 16 * o.spp : o.spp;
    settings.seed = seed;
    settings.threads = o.threads;
    settings.integrator = pathIntegrator().name;
    settings.maxDepth = 1;  // direct light: a flat cloth under a sun and a sky has nothing more
    RenderJob job(std::make_shared<const SceneDescription>(scene), settings);
    const std::atomic<bool> cancel{false};
    job.run(cancel);
    return job.snapshot().radiance;
}

double relativeRmse(const Image& a, const Image& reference) {
    double error = 0.0, norm = 0.0;
    for (size_t i = 0; i < a.pixels.size() && i < reference.pixels.size(); ++i) {
        const glm::dvec3 d = glm::dvec3(a.pixels[i]) - glm::dvec3(reference.pixels[i]);
        error += glm::dot(d, d);
        norm += glm::dot(glm::dvec3(reference.pixels[i]), glm::dvec3(reference.pixels[i]));
    }
    return norm > 0.0 ? std::sqrt(error / norm) : 0.0;
}

// The next mip level as a viewer builds it from the one above: each texel the mean of the 2 x 2
// below it, colour averaged in linear light (an sRGB texture), data as stored.
TextureImage boxFiltered(const TextureImage& t, bool srgb) {
    TextureImage out;
    out.name = t.name;
    out.width = std::max(1, t.width / 2);
    out.height = std::max(1, t.height / 2);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            glm::vec4 sum(0.0f);
            int n = 0;
            for (int j = 2 * y; j < std::min(2 * y + 2, t.height); ++j)
                for (int i = 2 * x; i < std::min(2 * x + 2, t.width); ++i, ++n) {
                    glm::vec4 v = glm::vec4(t.bytes[size_t(j) * t.width + i]) / 255.0f;
                    if (srgb)
                        for (int c = 0; c < 3; ++c) v[c] = srgbToLinear(v[c]);
                    sum += v;
                }
            glm::vec4 mean = sum / float(n);
            if (srgb)
                for (int c = 0; c < 3; ++c) mean[c] = linearToSrgb(mean[c]);
            out.bytes.push_back(glm::u8vec4(glm::round(glm::clamp(mean, 0.0f, 1.0f) * 255.0f)));
        }
    return out;
}

}  // namespace

MipComparison compareMipLevels(const WovenParams& params, const BakedMaterial& baked) {
    Material wovenOnly;
    wovenOnly.woven = params;
    const WovenSurfaceMaterial woven(wovenOnly, {});
    const std::vector<glm::dvec2> points = farFieldPoints(baked.uvSize, 4096);
    const std::vector<glm::vec3> target = farField(woven, points, farFieldDirections());
    const auto farFieldOf = [&](const std::vector<TextureImage>& textures) {
        return relativeRmse(farField(GltfMaterial(baked.material, textures), points, farFieldDirections()), target);
    };
    std::vector<TextureImage> fitted, filtered;
    for (int map = 0; map < int(baked.textures.size()); ++map) {
        fitted.push_back(baked.mipLevels[size_t(map)].empty() ? baked.textures[size_t(map)] : baked.mipLevels[size_t(map)].back());
        TextureImage t = baked.textures[size_t(map)];
        while (t.width > 1 || t.height > 1)
            t = boxFiltered(t, map == BakedMaterial::kBaseColor || map == BakedMaterial::kDiffuseTransmission);
        filtered.push_back(t);
    }
    return {farFieldOf(baked.textures), farFieldOf(fitted), farFieldOf(filtered)};
}

BakeReport reportBake(const Material& wovenMaterial, const BakedMaterial& baked, const ReportOptions& o) {
    BakeReport report;
    report.material = wovenMaterial.name;
    const double aspect = double(o.width) / double(o.height);
    const double repeat = wovenMaterial.woven->repeat.x;
    Material plainWoven;  // the model alone: the report compares reflection, not emission
    plainWoven.name = wovenMaterial.name;
    plainWoven.woven = wovenMaterial.woven;
    plainWoven.doubleSided = wovenMaterial.doubleSided;

    struct Variant {
        std::string what;
        Material material;
    };
    std::vector<Variant> variants{{"bake", baked.material}};
    const auto without = [&](const std::string& what, auto change) {
        Material m = baked.material;
        change(m);
        variants.push_back({what, m});
    };
    if (baked.material.anisotropy.strength > 0.0f) without("without anisotropy", [](Material& m) { m.anisotropy = AnisotropyParams{}; });
    without("without the normal map (bump)", [](Material& m) { m.normalTexture = TextureRef{}; });
    if (baked.material.alphaMode == AlphaMode::Mask)
        without("without the gaps (opaque)", [](Material& m) { m.alphaMode = AlphaMode::Opaque; });
    if (baked.material.sheen.color != glm::vec3(0.0f)) without("without the sheen", [](Material& m) { m.sheen = SheenParams{}; });

    // The bake is rendered with another seed than the model, so that its noise and the model's
    // are independent: the expected squared error is then bias^2 + the noise of two renders,
    // which the model against itself with a third seed measures.
    std::vector<ReportRow> rows(variants.size() + 1);
    for (int view = 0; view < 2; ++view) {
        const double threads = view == 0 ? o.nearThreads : o.farThreads;
        const char* name = view == 0 ? "near" : "far";
        const bool far = view == 1;
        const Image model = renderCloth(clothScene(plainWoven, {}, threads, repeat, aspect), o, far, o.seed);
        const Image again = renderCloth(clothScene(plainWoven, {}, threads, repeat, aspect), o, far, o.seed + 1);
        const double noise = relativeRmse(again, model);
        rows.back().what = "noise (the model, another seed)";
        (view == 0 ? rows.back().nearError : rows.back().farError) = noise;
        for (size_t v = 0; v < variants.size(); ++v) {
            const Image bake = renderCloth(clothScene(variants[v].material, baked.textures, threads, repeat, aspect), o, far, o.seed + 2);
            rows[v].what = variants[v].what;
            const double raw = relativeRmse(bake, model);
            (view == 0 ? rows[v].nearError : rows[v].farError) = std::sqrt(std::max(0.0, raw * raw - noise * noise));
            if (v == 0 && !o.imageFolder.empty()) {
                for (const auto& [image, kind] : {std::make_pair(&model, "model"), std::make_pair(&bake, "bake")}) {
                    const std::string path = (std::filesystem::path(o.imageFolder) / (o.imagePrefix + report.material + "_" + name + "_" + kind + ".png")).string();
                    writePng(path, *image);
                    report.images.push_back(path);
                }
            }
        }
    }
    report.rows = rows;

    report.farField = compareMipLevels(*wovenMaterial.woven, baked);
    return report;
}

std::string formatReport(const BakeReport& r, const ReportOptions& o) {
    std::ostringstream s;
    s << "material '" << r.material << "': relative RMSE of the bake against the model, noise removed (woven's path tracer, "
      << o.width << "x" << o.height << " at " << o.spp << " spp near, " << std::max(1, o.width / 4) << "x"
      << std::max(1, o.height / 4) << " at " << 16 * o.spp << " far; a flat cloth from 45 degrees under a sun and a sky)\n";
    char line[160];
    std::snprintf(line, sizeof line, "  %-34s %14s %14s\n", "", "near", "far");
    s << line;
    std::snprintf(line, sizeof line, "  %-34s %6.0f threads %6.0f threads\n", "", o.nearThreads, o.farThreads);
    s << line;
    for (const ReportRow& row : r.rows) {
        std::snprintf(line, sizeof line, "  %-34s %14.4f %14.4f\n", row.what.c_str(), row.nearError, row.farError);
        s << line;
    }
    std::snprintf(line, sizeof line,
                  "  far field (1280 direction pairs): level 0 %.4f; the 1 x 1 level fitted in the model %.4f, box-filtered %.4f\n",
                  r.farField.level0, r.farField.coarsestFitted, r.farField.coarsestBoxFiltered);
    s << line;
    for (const std::string& image : r.images) s << "  wrote " << image << "\n";
    return s.str();
}

}  // namespace woven
