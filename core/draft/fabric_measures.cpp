#include "fabric_measures.h"

#include <cstdio>
#include <numeric>

#include "textile_units.h"
#include "thread_layout.h"
#include "weave_pattern.h"

namespace woven {

FabricMeasures measureFabric(const WovenParams& p, const glm::dvec2& threadsPerCm, std::optional<double> warpTex,
                             std::optional<double> weftTex, double fibreDensity) {
    FabricMeasures m;
    m.threadsPerCm = threadsPerCm;
    const double widths[2] = {p.warp_width, p.yarn_width};
    const std::optional<double> counts[2] = {warpTex, weftTex};
    double tex[2];
    for (int side = 0; side < 2; ++side) {
        const double spacingCm = 1.0 / threadsPerCm[side];
        m.weightFromWidths |= !counts[side];
        tex[side] = counts[side].value_or(yarnTex(widths[side] * spacingCm, fibreDensity));
        m.cover[side] = yarnDiameterCm(tex[side], fibreDensity) / spacingCm;
    }
    const glm::dvec2 c = glm::min(m.cover, glm::dvec2(1.0));
    m.clothCover = c.x + c.y - c.x * c.y;
    m.gramsPerSquareMetre = (threadsPerCm.x * tex[0] + threadsPerCm.y * tex[1]) / 10.0;
    // The weave's tile and each side's lists repeat together (ThreadLayout's period).
    const WeavePattern pattern = WeavePattern::fromParams(p);
    const ThreadLayout warp(p.warp_colors, p.warp_yarns, p.warp_spacing, p.warp_color, 0, 0),
                       weft(p.weft_colors, p.weft_yarns, p.weft_spacing, p.weft_color, 0, 0);
    m.repeatThreads = {std::lcm(pattern.width(), warp.period()), std::lcm(pattern.height(), weft.period())};
    m.repeatCm = glm::dvec2(m.repeatThreads) / threadsPerCm;
    return m;
}

std::optional<FabricMeasures> measureMaterial(const MaterialJson& m) {
    if (!m.threadsPerCm) return std::nullopt;
    return measureFabric(m.params, glm::dvec2(*m.threadsPerCm), m.textile.warpTex, m.textile.weftTex,
                         m.textile.fibreDensity);
}

std::string describe(const FabricMeasures& m) {
    char line[400];
    std::snprintf(line, sizeof line,
                  "%.4g x %.4g threads/cm (%.4g x %.4g per inch), repeat %d x %d threads = %.3g x %.3g cm, "
                  "cover %.2f warp %.2f weft %.2f cloth, ",
                  m.threadsPerCm.x, m.threadsPerCm.y, m.threadsPerCm.x * kCmPerInch, m.threadsPerCm.y * kCmPerInch,
                  m.repeatThreads.x, m.repeatThreads.y, m.repeatCm.x, m.repeatCm.y, m.cover.x, m.cover.y, m.clothCover);
    // A weight guessed from the yarns' widths alone is off by the fibre's packing and the
    // crimp (a cloth of 2 mm threads "weighed" 38777 g/m2): only yarn counts give one.
    if (m.weightFromWidths) return std::string(line) + "no weight: set yarn counts (warp_count, weft_count) for it";
    char weight[64];
    std::snprintf(weight, sizeof weight, "%.0f g/m2", m.gramsPerSquareMetre);
    return line + std::string(weight);
}

}  // namespace woven
