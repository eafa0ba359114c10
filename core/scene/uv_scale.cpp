#include "uv_scale.h"

#include <algorithm>
#include <cmath>

#include <stdexcept>

#include "mesh_instances.h"

namespace woven {

UvScale measureUvScale(const SceneDescription& scene, const std::vector<size_t>& meshes) {
    // Two passes: the area-weighted mean, then the spread about it.
    std::vector<std::pair<double, glm::dvec2>> triangles;  // area, lengths
    glm::dvec2 sum(0.0);
    double area = 0.0;
    for (size_t m : meshes) {
        const Mesh& mesh = scene.meshes.at(m);
        if (mesh.uvs.empty()) continue;
        // An instanced mesh's copies as they are placed. Up to kMeasuredCopies of them, evenly
        // spread: a mean over a million copies of a sound mesh is that of a few hundred, and
        // measuring each would cost a million meshes' time.
        constexpr size_t kMeasuredCopies = 256;
        const size_t n = copies(mesh), measured = std::min(n, kMeasuredCopies);
        for (size_t k = 0; k < measured; ++k) {
            const glm::dmat3 place = mesh.instances ? glm::dmat3(glm::mat3((*mesh.instances)[k * n / measured])) : glm::dmat3(1.0);
            for (const glm::uvec3& t : mesh.triangles) {
                const glm::dvec3 p0(mesh.positions[t.x]), e1 = place * (glm::dvec3(mesh.positions[t.y]) - p0),
                                                          e2 = place * (glm::dvec3(mesh.positions[t.z]) - p0);
                const glm::dvec2 uv0(mesh.uvs[t.x]), d1 = glm::dvec2(mesh.uvs[t.y]) - uv0, d2 = glm::dvec2(mesh.uvs[t.z]) - uv0;
                const double det = d1.x * d2.y - d2.x * d1.y;
                const double a = 0.5 * glm::length(glm::cross(e1, e2));
                if (!(std::fabs(det) > 1e-20) || !(a > 0.0)) continue;  // no UV mapping, or no area
                const glm::dvec3 dpdu = (e1 * d2.y - e2 * d1.y) / det, dpdv = (e2 * d1.x - e1 * d2.x) / det;
                const glm::dvec2 lengths(glm::length(dpdu), glm::length(dpdv));
                if (!std::isfinite(lengths.x) || !std::isfinite(lengths.y)) continue;
                sum += a * lengths;
                area += a;
                triangles.emplace_back(a, lengths);
            }
        }
    }
    if (!(area > 0.0))
        throw std::invalid_argument("no triangle with texture coordinates to measure, which \"scale\": \"draft\" and "
                                    "thread counts need");
    UvScale scale;
    scale.metresPerUv = sum / area;
    glm::dvec2 squares(0.0);
    for (const auto& [a, lengths] : triangles) {
        const glm::dvec2 d = lengths / scale.metresPerUv - 1.0;
        squares += a * d * d;
    }
    scale.spread = glm::sqrt(squares / area);
    return scale;
}

glm::dvec2 worldLengthPerUv(const SceneDescription& scene, const std::vector<size_t>& meshes) {
    return measureUvScale(scene, meshes).metresPerUv;
}

std::string unevenUvWarning(const UvScale& scale) {
    const double worst = std::max(scale.spread.x, scale.spread.y);
    if (!(worst > kMaxUvSpread)) return "";
    return "the mesh's UVs are too uneven for one physical scale (their length per UV unit varies by " +
           std::to_string(int(std::lround(100.0 * worst))) + " % along " + (scale.spread.x >= scale.spread.y ? "u" : "v") +
           "): the thread count holds on average, denser and sparser where they stretch";
}

glm::vec2 repeatForThreadsPerCm(const glm::dvec2& metresPerUv, const glm::vec2& threadsPerCm) {
    // Threads per UV unit = threads per cm x cm per UV unit (100 x the world length in metres).
    return glm::vec2(glm::dvec2(threadsPerCm) * 100.0 * metresPerUv);
}

glm::vec2 repeatForThreadsPerCm(const SceneDescription& scene, const std::vector<size_t>& meshes,
                                const glm::vec2& threadsPerCm) {
    return repeatForThreadsPerCm(worldLengthPerUv(scene, meshes), threadsPerCm);
}

WovenParams scaledToMeshes(const MaterialJson& read, const SceneDescription& scene, const std::vector<size_t>& meshes,
                           std::vector<std::string>& warnings) {
    WovenParams params = read.params;
    if (!read.threadsPerCm) return params;
    const UvScale scale = measureUvScale(scene, meshes);
    params.repeat = repeatForThreadsPerCm(scale.metresPerUv, *read.threadsPerCm);
    if (const std::string uneven = unevenUvWarning(scale); !uneven.empty()) warnings.push_back(read.scaleKey + ": " + uneven);
    try {
        validate(params);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(read.scaleKey + " gives " + e.what());
    }
    return params;
}

}  // namespace woven
