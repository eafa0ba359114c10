#include "fabric_choice.h"

#include "uv_scale.h"

namespace woven {

MaterialJson readFabricMaterial(const std::string& name, std::vector<std::string>& warnings) {
    return materialFromJson({{"preset", name}}, WovenParams{}, "", warnings);
}

ChosenFabric chooseFabric(const std::string& target, const std::string& name, const SceneDescription& scene,
                          const std::vector<size_t>& meshes, std::vector<std::string>& warnings) {
    const MaterialJson read = readFabricMaterial(name, warnings);
    return {target, name, scaledToMeshes(read, scene, meshes, warnings), read.textile, read.wif};
}

FabricMeasures measureOnMesh(const WovenParams& p, const glm::dvec2& metresPerUv, const ChosenFabric* chosen) {
    const glm::dvec2 threadsPerCm = glm::dvec2(p.repeat) / (100.0 * metresPerUv);
    if (!chosen) return measureFabric(p, threadsPerCm, std::nullopt, std::nullopt, fibres().front().density);
    // A count describes the yarn only at the spacing and width it was turned into.
    const bool countsHold = p.repeat == chosen->params.repeat && p.warp_width == chosen->params.warp_width &&
                            p.yarn_width == chosen->params.yarn_width;
    const TextileKeys& t = chosen->textile;
    return measureFabric(p, threadsPerCm, countsHold ? t.warpTex : std::nullopt, countsHold ? t.weftTex : std::nullopt,
                         t.fibreDensity);
}

}  // namespace woven
