#include "demo_scene.h"

#include <cmath>

namespace woven {

WovenParams demoClothParams() {
    WovenParams p;
    p.pattern = glm::ivec3(1, 2, 1);
    p.repeat = glm::vec2(60.0f);
    p.weft_color = glm::vec3(0.60f, 0.10f, 0.08f);
    p.warp_color = glm::vec3(0.70f, 0.62f, 0.45f);
    p.cy = 0.6f;
    p.yarn_width = 0.9f;
    p.warp_width = 0.9f;
    p.noise = 0.2f;
    return p;
}

SceneDescription wavyClothScene(const WovenParams& material, int resolution) {
    // Height field y = A sin(k x) cos(k z / 2): analytic normals from its gradient.
    const float A = 0.06f, k = 3.0f;
    Mesh m;
    m.name = "wavy cloth";
    m.material = 0;
    const int n = resolution;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float u = float(i) / n, v = float(j) / n;
            const float x = 2.0f * u - 1.0f, z = 1.0f - 2.0f * v;
            const float y = A * std::sin(k * x) * std::cos(0.5f * k * z);
            const float dydx = A * k * std::cos(k * x) * std::cos(0.5f * k * z);
            const float dydz = -0.5f * A * k * std::sin(k * x) * std::sin(0.5f * k * z);
            m.positions.emplace_back(x, y, z);
            m.normals.push_back(glm::normalize(glm::vec3(-dydx, 1.0f, -dydz)));
            m.uvs.emplace_back(u, v);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const unsigned a = j * (n + 1) + i, b = a + 1, c = a + (n + 1), d = c + 1;
            m.triangles.emplace_back(a, b, d);  // counter-clockwise seen from +y
            m.triangles.emplace_back(a, d, c);
        }

    SceneDescription scene;
    scene.source = "procedural wavy cloth";
    scene.meshes.push_back(std::move(m));
    Material cloth;
    cloth.name = "cloth";
    cloth.woven = material;
    scene.materials.push_back(cloth);

    PunctualLight key;
    key.type = PunctualLight::Type::Point;
    key.position = glm::vec3(-1.2f, 2.0f, 1.5f);
    key.intensity = glm::vec3(6.0f);
    PunctualLight fill;
    fill.type = PunctualLight::Type::Directional;
    fill.direction = glm::normalize(glm::vec3(0.6f, -1.0f, -0.3f));
    fill.intensity = glm::vec3(0.8f);
    scene.lights = {key, fill};
    scene.environment.color = glm::vec3(0.05f);

    scene.hasCamera = true;
    const glm::vec3 eye(0.0f, 1.6f, 2.2f), target(0.0f, 0.0f, 0.0f);
    const glm::vec3 forward = glm::normalize(target - eye);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    const glm::vec3 up = glm::cross(right, forward);
    scene.camera.cameraToWorld = glm::mat4(glm::vec4(right, 0.0f), glm::vec4(up, 0.0f), glm::vec4(-forward, 0.0f),
                                           glm::vec4(eye, 1.0f));
    scene.camera.yfov = 0.7f;
    return scene;
}

}  // namespace woven
