#include "scene_camera.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "mesh_instances.h"
#include "scene_loader.h"

namespace woven {

SceneBox sceneBounds(const SceneDescription& scene) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const Mesh& m : scene.meshes) {
        const MeshBox box = worldBox(m);
        lo = glm::min(lo, box.lo);
        hi = glm::max(hi, box.hi);
    }
    if (!(lo.x <= hi.x)) return {glm::vec3(-0.5f), glm::vec3(0.5f)};
    return {lo, hi};
}

Camera lookAt(const glm::vec3& position, const glm::vec3& target, const glm::vec3& up, float yfov) {
    // +z points from the target back to the eye. In double: a float's squared length overflows
    // for a view of about 1e19 and underflows for one of 1e-19, which left NaN axes.
    const glm::dvec3 z = glm::normalize(glm::dvec3(position) - glm::dvec3(target));
    const glm::dvec3 x = glm::normalize(glm::cross(glm::dvec3(up), z));
    const glm::dvec3 y = glm::cross(z, x);
    Camera camera;
    camera.cameraToWorld = glm::mat4(glm::vec4(glm::vec3(x), 0.0f), glm::vec4(glm::vec3(y), 0.0f),
                                     glm::vec4(glm::vec3(z), 0.0f), glm::vec4(position, 1.0f));
    camera.yfov = yfov;
    return camera;
}

CameraView viewOf(const Camera& camera) {
    CameraView view;
    view.position = glm::vec3(camera.cameraToWorld[3]);
    view.target = view.position - glm::vec3(camera.cameraToWorld[2]);
    view.up = glm::vec3(camera.cameraToWorld[1]);
    view.yfovDegrees = glm::degrees(camera.yfov);
    return view;
}

Camera cameraOf(const CameraView& view) {
    return lookAt(view.position, view.target, view.up, glm::radians(view.yfovDegrees));
}

Camera framingCamera(const SceneBox& box, float yfov) {
    constexpr float kPitch = -0.5f;  // radians: looking slightly down
    const float distance = std::max(box.radius(), 1e-3f) / std::sin(0.5f * yfov) * 1.05f;
    const glm::vec3 forward(0.0f, std::sin(kPitch), -std::cos(kPitch));
    return lookAt(box.centre() - distance * forward, box.centre(), glm::vec3(0.0f, 1.0f, 0.0f), yfov);
}

Camera sceneCamera(const SceneDescription& scene) {
    return scene.hasCamera ? scene.camera : framingCamera(sceneBounds(scene), scene.camera.yfov);
}

void chooseCamera(SceneDescription& scene, const std::string& choice) {
    if (choice == "auto") {
        scene.camera = Camera{};  // framed with the default field of view, not the file camera's
        scene.hasCamera = false;
        return;
    }
    const bool isIndex = !choice.empty() && choice.size() < 10 &&
                         std::all_of(choice.begin(), choice.end(), [](unsigned char c) { return std::isdigit(c) != 0; });
    const size_t index = isIndex ? std::stoul(choice) : 0;
    for (size_t i = 0; i < scene.cameras.size(); ++i) {
        const NamedCamera& c = scene.cameras[i];
        if (isIndex ? index == i : (c.name == choice || c.node == choice)) {
            scene.camera = c.camera;
            scene.hasCamera = true;
            return;
        }
    }
    std::string cameras;
    for (size_t i = 0; i < scene.cameras.size(); ++i)
        cameras += (i ? ", " : "") + std::to_string(i) + " '" + scene.cameras[i].name + "' (node '" +
                   scene.cameras[i].node + "')";
    throw SceneError(scene.source + ": --camera " + choice + ": no such camera; " +
                     (cameras.empty() ? "the file has none" : "its cameras are " + cameras) + ", or auto");
}

}  // namespace woven
