#pragma once
// KHR_materials_sheen's layer: the "Charlie" microfibre distribution of Conty Estevez and Kulla
// (2017) with their visibility term, and the directional albedo E(cos theta) that scales the
// layer below (the extension's albedo-scaling technique). Local frame, z = the normal;
// reflection only. Sampled by the cosine-weighted hemisphere: the lobe is broad, and its
// density stays bounded where the distribution peaks at grazing half vectors.
#include <array>
#include <glm/glm.hpp>

namespace woven {

class SheenLobe {
public:
    // No sheen (active() is false), for nothing: GltfBxdf builds one for every surface.
    SheenLobe() = default;
    // `roughness` is the extension's sheenRoughness, clamped to [kMinRoughness, 1]; the
    // distribution's alpha is its square, as the extension's reference implementation has it.
    SheenLobe(const glm::vec3& color, float roughness);
    static constexpr float kMinRoughness = 0.07f;

    bool active() const { return maxColor_ > 0.0f; }
    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const;
    // 1 - max(colour) E(cos theta): how much of the layer below a direction still sees.
    float baseScale(float cosTheta) const;
    // Directional albedo of the lobe with colour 1, from a table integrated once (bilinear in
    // cos theta and roughness).
    float albedo(float cosTheta) const;
    float maxColor() const { return maxColor_; }

    // The albedo table, row r = roughness r / (N - 1), column m = cos theta m / (N - 1): the
    // preview samples the same numbers.
    static constexpr int kAlbedoTableSize = 32;
    static const std::array<float, kAlbedoTableSize * kAlbedoTableSize>& albedoTable();

    float distribution(const glm::vec3& h) const;
    float visibility(float cosO, float cosI) const;

private:
    glm::vec3 color_{0.0f};
    float roughness_ = 1.0f, alpha_ = 1.0f, maxColor_ = 0.0f;
};

}  // namespace woven
