#include "woven_uv_check.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "uv_precision.h"

namespace woven {

bool uvsAllEqual(const Mesh& mesh) {
    return !mesh.uvs.empty() && std::all_of(mesh.uvs.begin(), mesh.uvs.end(), [&](const glm::vec2& uv) { return uv == mesh.uvs[0]; });
}

namespace {
// The largest finite |u| and |v| of the mesh (TexCoords reads non-finite ones as 0).
glm::dvec2 largestUv(const Mesh& mesh) {
    glm::dvec2 largest(0.0);
    for (const glm::vec2& uv : mesh.uvs)
        for (int a = 0; a < 2; ++a)
            if (std::isfinite(uv[a])) largest[a] = std::max(largest[a], std::fabs(double(uv[a])));
    return largest;
}
}  // namespace

std::vector<bool> checkWovenUvs(const SceneDescription& scene, int material) {
    const Material& m = scene.materials[size_t(material)];
    const glm::dvec2 limit = resolvedUvLimit<float>(m.woven->repeat);
    std::vector<bool> flat(scene.meshes.size(), false);
    double worst = 0.0, worstUv = 0.0;  // the largest |uv| / limit, and that |uv|
    const Mesh* worstMesh = nullptr;
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& mesh = scene.meshes[i];
        if (mesh.material != material || mesh.uvs.empty()) continue;
        // All equal where a float cannot resolve the threads anyway (1e10 + a few units): the far field.
        if (uvsAllEqual(mesh) && resolvesThreads(mesh.uvs[0], limit)) {
            flat[i] = true;
            std::cerr << "warning: " << scene.source << ": mesh '" << mesh.name << "' (woven material '" << m.name
                      << "'): its UVs are all (" << mesh.uvs[0].x << ", " << mesh.uvs[0].y
                      << "), which maps no weave; shaded as solid cloth, as without UVs\n";
            continue;
        }
        const glm::dvec2 largest = largestUv(mesh), ratio = largest / limit;
        if (std::max(ratio.x, ratio.y) > std::max(worst, 1.0)) {
            worst = std::max(ratio.x, ratio.y);
            worstUv = std::max(largest.x, largest.y);
            worstMesh = &mesh;
        }
    }
    if (worstMesh) {
        std::ostringstream s;
        s.precision(3);
        s << "warning: " << scene.source << ": woven material '" << m.name << "': UVs reach " << worstUv << " (mesh '"
          << worstMesh->name << "'), where a float's values lie " << worstUv * double(std::numeric_limits<float>::epsilon())
          << " apart, too far to resolve its " << m.woven->repeat.x << " x " << m.woven->repeat.y
          << " threads per UV unit; shaded by the weave's far field beyond |uv| = " << std::min(limit.x, limit.y) << "\n";
        std::cerr << s.str();
    }
    return flat;
}

}  // namespace woven
