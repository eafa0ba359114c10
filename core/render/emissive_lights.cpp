// RenderScene's lights: one for each emissive triangle, or for each rectangle of two that share a
// diagonal and one radiance; the scene's punctual lights and its environment; the direct-light
// pass's choice among them and the light samplers over them.
#include <algorithm>
#include <array>

#include "luminance.h"
#include "mesh_instances.h"
#include "render_scene_impl.h"
#include "triangle_corners.h"

namespace woven {

namespace {
// Two triangles that together make a rectangle, as a modeller splits a quad: sharing a diagonal
// (two vertex indices), wound alike, and the far corners mirror images about the diagonal's
// midpoint with a right angle there. Returns the rectangle's corner and edges (their cross
// product along the first triangle's normal). The tolerance is relative to the edges, far below
// anything a render could show; a quad whose placed corners round beyond it stays two triangles,
// which is always right.
struct RectangleShape {
    glm::vec3 corner, ex, ey;
};
std::optional<RectangleShape> rectangleOf(const Corners& first, const Corners& second) {
    constexpr float kTolerance = 1e-5f;
    int shared = 0, lone1 = -1, lone2 = -1;
    for (int i = 0; i < 3; ++i) {
        bool inSecond = false;
        for (int j = 0; j < 3; ++j) inSecond = inSecond || first.tri[i] == second.tri[j];
        if (inSecond) ++shared;
        else lone1 = i;
    }
    for (int j = 0; j < 3; ++j)
        if (second.tri[j] != first.tri[0] && second.tri[j] != first.tri[1] && second.tri[j] != first.tri[2]) lone2 = j;
    if (shared != 2 || lone1 < 0 || lone2 < 0) return std::nullopt;
    const glm::vec3 u = first.p[lone1], v = second.p[lone2];
    const glm::vec3 x = first.p[(lone1 + 1) % 3], y = first.p[(lone1 + 2) % 3];
    const glm::vec3 ex = x - u, ey = y - u;
    const float width = glm::length(ex), height = glm::length(ey);
    // Relative to the shorter edge and to both, so that a long thin strip is held as tightly.
    if (!(std::min(width, height) > 0.0f) || glm::length(u + v - x - y) > kTolerance * std::min(width, height) ||
        std::abs(glm::dot(ex, ey)) > kTolerance * width * height)
        return std::nullopt;
    const glm::vec3 n1 = glm::cross(first.p[1] - first.p[0], first.p[2] - first.p[0]);
    const glm::vec3 n2 = glm::cross(second.p[1] - second.p[0], second.p[2] - second.p[0]);
    if (!(glm::dot(n1, n2) > 0.0f)) return std::nullopt;
    // (u, x, y) is the first triangle's winding, so ex x ey is along its normal.
    return RectangleShape{u, ex, ey};
}
}  // namespace

void RenderScene::Impl::buildLights() {
    triangleLights.resize(scene->meshes.size());
    for (size_t m = 0; m < scene->meshes.size(); ++m) {
        const Mesh& mesh = scene->meshes[m];
        const SurfaceMaterial& material = (*materials)[mesh.material];
        if (!material.emits()) continue;
        // An instanced emitter's copies are each a light (by instance, then triangle).
        const size_t n = mesh.triangles.size();
        triangleLights[m].assign(copies(mesh) * n, -1);
        for (size_t i = 0; i < copies(mesh); ++i)
            for (size_t t = 0; t < n; ++t) {
                const int instance = mesh.instances ? int(i) : -1;
                if (material.uniformEmission() && t + 1 < n) {
                    // A rectangle of one radiance is one light, sampled whole (spherical_rectangle.h).
                    const std::optional<RectangleShape> r = rectangleOf(cornerPositions(mesh, instance, unsigned(t), 0.0f, 0.0f),
                                                                        cornerPositions(mesh, instance, unsigned(t + 1), 0.0f, 0.0f));
                    if (r) {
                        Light light = Light::rectangle(r->corner, r->ex, r->ey, material.emission(TexCoords{}),
                                                       material.twoSidedEmission());
                        if (light.power() != glm::vec3(0.0f)) {
                            triangleLights[m][i * n + t] = triangleLights[m][i * n + t + 1] = int(lights.size());
                            lights.push_back(std::move(light));
                        }
                        ++t;
                        continue;
                    }
                }
                const Corners c = hitCorners(mesh, instance, unsigned(t), 0.0f, 0.0f);
                const std::array<TexCoords, 3> corners = {interpolateTexCoords(mesh, unsigned(t), 0.0f, 0.0f),
                                                          interpolateTexCoords(mesh, unsigned(t), 1.0f, 0.0f),
                                                          interpolateTexCoords(mesh, unsigned(t), 0.0f, 1.0f)};
                const bool mirrored = c.tri != mesh.triangles[t];
                Light light = Light::triangle(c.p[0], c.p[1], c.p[2], material,
                                              mirrored ? std::array<TexCoords, 3>{corners[0], corners[2], corners[1]} : corners);
                if (!(light.power() != glm::vec3(0.0f))) continue;  // degenerate: never hit, never sampled
                triangleLights[m][i * n + t] = int(lights.size());
                lights.push_back(std::move(light));
            }
    }
    for (const PunctualLight& p : scene->lights) lights.push_back(Light::punctual(p));
    const Environment& env = scene->environment;
    bool envShines = glm::max(env.color.r, glm::max(env.color.g, env.color.b)) > 0.0f;
    if (envShines && env.image)
        envShines = std::any_of(env.image->pixels.begin(), env.image->pixels.end(),
                                [](const glm::vec3& p) { return glm::max(p.r, glm::max(p.g, p.b)) > 0.0f; });
    if (envShines) {
        environment = int(lights.size());
        lights.push_back(Light::environment(env));
    }
    for (Light& light : lights) light.setSceneBounds(bounds);
    // The direct-light pass's lights: the most powerful, each a BSDF evaluation per camera sample;
    // ties go to the lower index, so the choice is the same on every machine.
    std::vector<std::pair<float, int>> byPower;
    for (size_t i = 0; i < lights.size(); ++i)
        if (int(i) != environment) byPower.push_back({-luminance(lights[i].power()), int(i)});
    const size_t kept = std::min(byPower.size(), size_t(kDirectPassLights));
    std::partial_sort(byPower.begin(), byPower.begin() + ptrdiff_t(kept), byPower.end());
    for (size_t i = 0; i < kept; ++i) directPassLights.push_back(byPower[i].second);
    lightSampler.emplace(lights);
    lightTree.emplace(lights);
}

}  // namespace woven
