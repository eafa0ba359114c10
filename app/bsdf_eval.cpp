#include "bsdf_eval.h"

#include <cmath>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "material_json.h"
#include "transmitting_yarn.h"
#include "untrusted_json.h"
#include "uv_precision.h"
#include "woven_material.h"
#include "woven_params_json.h"

namespace woven {

namespace {

const char* yarnName(YarnType t) {
    switch (t) {
        case YarnType::Weft: return "weft";
        case YarnType::Warp: return "warp";
        case YarnType::Gap: return "gap";
    }
    return "gap";
}

glm::vec3 readDirection(const nlohmann::json& j, const char* key) {
    if (!j.contains(key)) throw std::invalid_argument(std::string("missing '") + key + "'");
    const auto& v = j.at(key);
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
        throw std::invalid_argument(std::string("'") + key + "' must be an array of 3 numbers");
    glm::vec3 d(v[0].get<float>(), v[1].get<float>(), v[2].get<float>());
    const float len = glm::length(d);
    if (!std::isfinite(len) || len <= 0.0f)
        throw std::invalid_argument(std::string("'") + key + "' must be a finite non-zero vector");
    return d / len;
}

glm::dvec2 readUv(const nlohmann::json& j) {
    if (!j.contains("uv")) return glm::dvec2(0.0);
    const auto& v = j.at("uv");
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
        throw std::invalid_argument("'uv' must be an array of 2 numbers");
    glm::dvec2 uv(v[0].get<double>(), v[1].get<double>());
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) throw std::invalid_argument("'uv' must be finite");
    return uv;
}

}  // namespace

WovenParams flatSurfaceParams(const nlohmann::json& j) {
    // "wif" is read from the working directory, as for --woven.
    std::vector<std::string> warnings;
    MaterialJson read = materialFromJson(j, WovenParams{}, "", warnings);
    // The flat surface's UV unit is a metre (dp/du = +x, in glTF's unit), so thread counts
    // and "scale": "draft" put threads per cm x 100 on it.
    if (read.threadsPerCm) {
        read.params.repeat = *read.threadsPerCm * 100.0f;
        try {
            validate(read.params);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(read.scaleKey + " gives " + e.what());
        }
    }
    for (const std::string& w : warnings) std::cerr << "warning: " << w << "\n";
    return read.params;
}

// Materials are rebuilt only when a line's material differs from every one kept.
class BsdfEval::MaterialCache {
public:
    const WovenMaterial& get(const nlohmann::json& j) {
        const std::string key = j.dump();
        auto it = cache_.find(key);
        if (it != cache_.end()) return *it->second;
        auto material = std::make_unique<WovenMaterial>(flatSurfaceParams(j));
        // A stream of ever new materials must not grow without bound: start over when full.
        if (cache_.size() >= kMaxCachedMaterials) cache_.clear();
        return *cache_.emplace(key, std::move(material)).first->second;
    }

private:
    static constexpr size_t kMaxCachedMaterials = 64;
    std::map<std::string, std::unique_ptr<WovenMaterial>> cache_;
};

namespace {

// The flat surface of bsdf-eval: normal +z, dp/du = +x, dp/dv = +y. A viewer below it sees the
// back face.
ShadingInput flatSurface(const glm::dvec2& uv, const glm::vec3& wo) {
    ShadingInput in;
    in.uv = uv;
    in.backSide = wo.z < 0.0f;
    return in;
}

nlohmann::json evalQuery(const WovenMaterial& material, const nlohmann::json& query, bool& warnedFarUv) {
    const glm::vec3 wi = readDirection(query, "wi"), wo = readDirection(query, "wo");
    ShadingInput in = flatSurface(readUv(query), wo);
    nlohmann::json out;
    // A uv too large for a double to resolve a thread (uv_precision.h) is answered by the far field.
    if (!resolvesThreads(in.uv, resolvedUvLimit<double>(material.params().repeat))) {
        in.uvSpacing = uvSpacing<double>(in.uv);
        if (const auto filtered = material.shadeFiltered(in)) {
            if (!warnedFarUv)
                std::cerr << "warning: uv (" << in.uv.x << ", " << in.uv.y
                          << ") and larger cannot resolve the material's threads in double precision; answered with the weave's far field\n";
            warnedFarUv = true;
            const glm::vec3 f = filtered->eval(wo, wi);
            out["f"] = {f.r, f.g, f.b};
            out["pdf"] = filtered->pdf(wo, wi);
            out["yarn"] = "far";
            return out;
        }
    }
    const auto shading = material.shade(in);
    if (!shading) {
        out["f"] = {0.0, 0.0, 0.0};
        out["pdf"] = 0.0;
        out["yarn"] = "gap";
        return out;
    }
    // A yarn that transmits answers for wi on either side, as the renderer's BSDF does.
    const auto answer = [&](const auto& bsdf) {
        const glm::vec3 f = bsdf.eval(wo, wi);
        out["f"] = {f.r, f.g, f.b};
        out["pdf"] = bsdf.pdf(wo, wi);
    };
    if (shading->transmission) answer(transmittingYarn(shading->bsdf, *shading->transmission));
    else answer(shading->bsdf);
    out["yarn"] = yarnName(shading->yarn);
    return out;
}

}  // namespace

BsdfEval::BsdfEval() : materials_(std::make_unique<MaterialCache>()) {}
BsdfEval::~BsdfEval() = default;

std::string BsdfEval::answer(std::string_view line) {
    if (line.size() > kMaxBsdfEvalLineBytes)
        throw std::invalid_argument("the line is longer than woven's limit of " +
                                    std::to_string(kMaxBsdfEvalLineBytes >> 20) + " MiB");
    const nlohmann::json query = parseUntrustedJson(line);
    if (!query.is_object()) throw std::invalid_argument("each line must be a JSON object");
    // A misspelt key ("UV") must not be answered as if it were absent (uv (0, 0)).
    for (const auto& item : query.items())
        if (item.key() != "material" && item.key() != "uv" && item.key() != "wi" && item.key() != "wo")
            throw std::invalid_argument("unknown key " + nlohmann::json(item.key()).dump() + " (expected material, uv, wi, wo)");
    if (!query.contains("material")) throw std::invalid_argument("missing 'material'");
    return evalQuery(materials_->get(query.at("material")), query, warnedFarUv_).dump();
}

}  // namespace woven
