#pragma once
// What a weaver quotes of a cloth, from a woven material at a known thread count
// (docs/FABRICS.md): Peirce's cover factor, the weight per square metre and the size of one
// repeat. Printed by `woven pattern --material`, `woven fabrics` and the previewer's panel.
#include <glm/glm.hpp>

#include <optional>
#include <string>

#include "material_json.h"
#include "woven_params.h"

namespace woven {

struct FabricMeasures {
    glm::dvec2 threadsPerCm{0.0};  // ends, picks
    // Fractional cover of each side: yarn diameter x threads per cm, above 1 where the yarns are
    // jammed (Peirce 1937); and the cloth's, c1 + c2 - c1 c2 with each side at most 1.
    glm::dvec2 cover{0.0};
    double clothCover = 0.0;
    // (ends/cm x warp tex + picks/cm x weft tex) / 10, crimp left out (it adds a few percent).
    double gramsPerSquareMetre = 0.0;
    bool weightFromWidths = false;  // a side without a yarn count: its tex from its yarn width and fibre
    glm::ivec2 repeatThreads{1};    // ends and picks in one repeat of the weave and its thread lists
    glm::dvec2 repeatCm{0.0};
};

// `warpTex` / `weftTex`: the yarn counts where given; otherwise that side's count is the one whose
// diameter is its yarn width (warp_width, yarn_width) of the thread spacing, in a fibre of
// `fibreDensity`. `p` must be valid.
FabricMeasures measureFabric(const WovenParams& p, const glm::dvec2& threadsPerCm, std::optional<double> warpTex,
                             std::optional<double> weftTex, double fibreDensity);

// The measures of a material that gives its thread counts (MaterialJson::threadsPerCm), nullopt
// for one that does not.
std::optional<FabricMeasures> measureMaterial(const MaterialJson& m);

// One line: "25 x 16 threads/cm (63.5 x 40.6 per inch), repeat 4 x 4 = 0.16 x 0.25 cm, cover 0.86
// warp 0.46 weft 0.92 cloth, 304 g/m2".
std::string describe(const FabricMeasures& m);

}  // namespace woven
