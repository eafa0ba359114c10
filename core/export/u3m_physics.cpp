#include "u3m_physics.h"

#include <map>

#include "weave_construction.h"
#include "weave_pattern.h"

namespace woven {

namespace {

// U3M's composition types for woven's fibres (textile_units.h); viscose is sold as rayon.
nlohmann::json compositionPart(const std::string& fibre) {
    static const std::map<std::string, const char*> types = {
        {"cotton", "Cotton"}, {"linen", "Linen"},       {"wool", "Wool"}, {"silk", "Silk"},
        {"viscose", "Rayon"}, {"polyester", "Polyester"}, {"nylon", "Nylon"}, {"acrylic", "Acrylic"},
    };
    const auto it = types.find(fibre);
    if (it == types.end()) return {{"ratio", 1.0}, {"type", "other"}, {"name", fibre}};
    return {{"ratio", 1.0}, {"type", it->second}, {"name", nullptr}};
}

}  // namespace

double clothThicknessMm(const WovenParams& params, const FabricMeasures& measures, const TextileKeys& textile) {
    const double widths[2] = {params.warp_width, params.yarn_width};
    const std::optional<double> counts[2] = {textile.warpTex, textile.weftTex};
    const double density = textile.fibreDensity > 0.0 ? textile.fibreDensity : fibres().front().density;
    double mm = 0.0;
    for (int side = 0; side < 2; ++side)
        mm += 10.0 * (counts[side] ? yarnDiameterCm(*counts[side], density) : widths[side] / measures.threadsPerCm[side]);
    return mm;
}

nlohmann::json u3mPhysics(const WovenParams& params, const FabricMeasures& measures, const TextileKeys& textile) {
    nlohmann::json composition = nullptr;
    if (!textile.fibre.empty()) composition = {{"parts", nlohmann::json::array({compositionPart(textile.fibre)})}};
    return {
        {"weight", measures.gramsPerSquareMetre},
        {"thickness", clothThicknessMm(params, measures, textile)},
        {"composition", composition},
        {"devices", {{"fab", "null"}}},
        {"material_type", {{"type", "Woven"}, {"name", nullptr}}},
        {"construction", {{"type", u3mConstructionName(construction(WeavePattern::fromParams(params)))}, {"name", nullptr}}},
    };
}

}  // namespace woven
