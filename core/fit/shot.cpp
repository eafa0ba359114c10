#include "shot.h"

#include <cmath>
#include <filesystem>
#include <optional>

#include "camera_model.h"
#include "image_io.h"
#include "photo_model.h"
#include "render_job.h"
#include "scene_loader.h"
#include "scene_validation.h"
#include "woven_assignment.h"

namespace woven {

namespace {

// Where the ray meets triangle (a, b, c), Moller and Trumbore: barycentrics (b1, b2) and t.
std::optional<glm::dvec3> intersect(const Ray& ray, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 o(ray.o), d(ray.d), e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (!(std::abs(det) > 1e-300)) return std::nullopt;
    const glm::dvec3 s = o - a;
    const double b1 = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double b2 = glm::dot(d, q) / det;
    const double t = glm::dot(e2, q) / det;
    if (b1 < 0.0 || b2 < 0.0 || b1 + b2 > 1.0 || !(t > 0.0)) return std::nullopt;
    return glm::dvec3(b1, b2, t);
}

// Where the central ray meets the target, and the camera's footprint of one pixel there in the
// triangle's UVs.
struct CentralHit {
    glm::dvec3 centre, normal;
    glm::dmat2 uvPerPixel;
};

// The nearest hit of the ray on the target's meshes with texture coordinates, or none.
std::optional<CentralHit> centralHit(const SceneDescription& scene, const std::vector<size_t>& meshes, const CameraModel& model,
                                     const Ray& ray) {
    double nearest = INFINITY;
    CentralHit found{glm::dvec3(0.0), glm::dvec3(0.0), glm::dmat2(1.0)};
    for (size_t i : meshes) {
        const Mesh& mesh = scene.meshes[i];
        if (mesh.uvs.empty()) continue;
        for (const glm::uvec3& tri : mesh.triangles) {
            const glm::dvec3 a(mesh.positions[tri.x]), b(mesh.positions[tri.y]), c(mesh.positions[tri.z]);
            const auto hit = intersect(ray, a, b, c);
            if (!hit || hit->z >= nearest) continue;
            const glm::dvec2 ta(mesh.uvs[tri.x]), tb(mesh.uvs[tri.y]), tc(mesh.uvs[tri.z]);
            // dp = J d(u, v): J's columns are dp/du and dp/dv.
            const glm::dmat2 duv(tb - ta, tc - ta);
            if (!(std::abs(glm::determinant(duv)) > 0.0)) continue;
            const glm::dmat2 inv = glm::inverse(duv);
            const glm::dvec3 dpdu = (b - a) * inv[0][0] + (c - a) * inv[0][1];
            const glm::dvec3 dpdv = (b - a) * inv[1][0] + (c - a) * inv[1][1];
            const glm::dvec3 p = a + hit->x * (b - a) + hit->y * (c - a);
            const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
            const CameraModel::Footprint f = model.footprint(glm::vec3(p), glm::vec3(n));
            // Least squares of dp = dpdu du + dpdv dv for each pixel step.
            const glm::dmat2 g(glm::dot(dpdu, dpdu), glm::dot(dpdu, dpdv), glm::dot(dpdu, dpdv), glm::dot(dpdv, dpdv));
            if (!(std::abs(glm::determinant(g)) > 0.0)) continue;
            const glm::dmat2 gi = glm::inverse(g);
            const auto solve = [&](const glm::dvec3& dp) {
                return gi * glm::dvec2(glm::dot(dpdu, dp), glm::dot(dpdv, dp));
            };
            found.uvPerPixel = glm::dmat2(solve(glm::dvec3(f.dpdx)), solve(glm::dvec3(f.dpdy)));
            nearest = hit->z;
            found.centre = p;
            found.normal = n;
        }
    }
    if (!std::isfinite(nearest)) return std::nullopt;
    return found;
}

// Whether every light is behind the target as the camera sees it (at cameraAt): punctual ones, and
// emissive surfaces (a light box behind the swatch), each of whose corners must lie behind; and
// no environment light.
bool backlit(const SceneDescription& scene, const std::vector<size_t>& targetMeshes, const glm::dvec3& cameraAt,
             const CentralHit& hit) {
    const glm::dvec3 centre = hit.centre;
    const auto side = [&](const glm::dvec3& towards) { return glm::dot(towards, hit.normal) > 0.0; };
    const bool cameraSide = side(cameraAt - centre);
    bool anyLight = false, allBehind = true;
    const auto light = [&](const glm::dvec3& towards) {
        anyLight = true;
        allBehind = allBehind && side(towards) != cameraSide;
    };
    for (const PunctualLight& l : scene.lights)
        light(l.type == PunctualLight::Type::Directional ? -glm::dvec3(l.direction) : glm::dvec3(l.position) - centre);
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& mesh = scene.meshes[i];
        const bool target = std::find(targetMeshes.begin(), targetMeshes.end(), i) != targetMeshes.end();
        if (!target && mesh.material >= 0 && scene.materials[size_t(mesh.material)].emits())
            for (const glm::vec3& p : mesh.positions) light(glm::dvec3(p) - centre);
    }
    return anyLight && allBehind && scene.environment.color == glm::vec3(0.0f);
}

}  // namespace

Shot loadShot(const std::string& path, const std::string& target) {
    const auto fail = [&](const std::string& problem) -> FitError { return FitError(path + ": " + problem); };
    SceneDescription scene;
    try {
        scene = loadScene(path);
    } catch (const SceneError& e) {
        throw FitError(e.what());
    }
    if (!scene.photo)
        throw fail("no \"photo\" key: a shot for woven fit is a scene file with \"photo\": {\"image\": \"swatch.png\"} "
                   "(docs/FIT.md)");
    Shot shot;
    shot.path = path;
    shot.photo = *scene.photo;

    // The target's meshes are found before it is made woven: a material it splits is renamed.
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        const int m = scene.meshes[i].material;
        const Material* material = m >= 0 && m < int(scene.materials.size()) ? &scene.materials[size_t(m)] : nullptr;
        if (targetNames(target, scene.meshes[i], material)) shot.meshes.push_back(i);
    }
    try {
        assignWoven(scene, {{target, nlohmann::json::object(), "--target " + target, std::filesystem::path(path).parent_path().string()}});
        validateScene(scene);
    } catch (const SceneError& e) {
        throw FitError(e.what());
    }
    for (size_t i : shot.meshes) {
        const int m = scene.meshes[i].material;
        if (m >= 0 && std::find(shot.materials.begin(), shot.materials.end(), m) == shot.materials.end())
            shot.materials.push_back(m);
    }

    const RenderSettings frame = defaultRenderSettings(scene);
    try {
        shot.image = readPhoto(shot.photo);
    } catch (const ImageError& e) {
        throw fail("photo.image: " + std::string(e.what()));
    }
    if (shot.image.width != frame.width || shot.image.height != frame.height)
        throw fail("photo.image: " + shot.photo.image + " is " + std::to_string(shot.image.width) + "x" +
                   std::to_string(shot.image.height) + " but the render is " + std::to_string(frame.width) + "x" +
                   std::to_string(frame.height) +
                   " (the photo is the frame: give \"render\": {\"width\", \"height\"} its size, or resize it)");

    // The thread lattice's scale: where the central ray meets the target, the camera's footprint
    // of one pixel in the triangle's UVs.
    Camera camera = scene.camera;
    if (camera.aspect <= 0.0f) camera.aspect = float(frame.width) / float(frame.height);
    const CameraModel model(camera, frame.width, frame.height);
    const Ray ray = model.generateRay(glm::vec2(0.5f * float(frame.width), 0.5f * float(frame.height)));
    const std::optional<CentralHit> hit = centralHit(scene, shot.meshes, model, ray);
    if (!hit)
        throw fail("--target " + target + " is not what the image centre sees (or has no texture coordinates there): "
                   "a shot frames the swatch, the camera straight above it");
    shot.uvPerPixel = hit->uvPerPixel;
    shot.backlit = backlit(scene, shot.meshes, glm::dvec3(ray.o), *hit);
    shot.scene = std::make_shared<const SceneDescription>(std::move(scene));
    return shot;
}

Shot turnedShot(const Shot& shot, double radians) {
    Shot turned = shot;
    if (radians == 0.0) return turned;
    // UVs rotated by a (u' = u cos a - v sin a about the centre) move U's gradient in the image to
    // cos a gradU - sin a gradV: a's sign is the one that turns it by +radians there, which
    // depends on which way the camera sees the UVs' axes.
    const glm::dmat2& m = shot.uvPerPixel;
    const glm::dvec2 gradU = gradientU(m), gradV = gradientV(m);
    const glm::dvec2 g = std::cos(radians) * gradU - std::sin(radians) * gradV;
    const double a = (gradU.x * g.y - gradU.y * g.x) * radians >= 0.0 ? radians : -radians;
    const glm::dmat2 rotation(std::cos(a), std::sin(a), -std::sin(a), std::cos(a));
    turned.uvPerPixel = rotation * m;

    auto scene = std::make_shared<SceneDescription>(*shot.scene);
    glm::dvec2 centre(0.0);
    size_t count = 0;
    for (size_t i : shot.meshes)
        for (const glm::vec2& uv : scene->meshes[i].uvs) {
            centre += glm::dvec2(uv);
            ++count;
        }
    centre /= double(std::max<size_t>(count, 1));
    for (size_t i : shot.meshes) {
        Mesh& mesh = scene->meshes[i];
        mesh.tangents.clear();
        for (glm::vec2& uv : mesh.uvs) uv = glm::vec2(centre + rotation * (glm::dvec2(uv) - centre));
    }
    turned.scene = scene;
    return turned;
}

}  // namespace woven
