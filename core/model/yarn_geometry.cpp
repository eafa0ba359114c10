#include "yarn_geometry.h"

#include <algorithm>
#include <cmath>

namespace woven {

glm::vec2 crossSectionNormal(float cy, float x) {
    const float up2 = std::max(0.0f, 1.0f - x * x);
    const glm::vec2 n(cy * x, std::sqrt(up2));
    const float len2 = n.x * n.x + up2;
    // c_y = 0 at |x| = 1 is 0/0: a flat yarn's normal is straight up everywhere.
    return len2 > 1e-24f ? n * (1.0f / std::sqrt(len2)) : glm::vec2(0.0f, 1.0f);
}

namespace {

// Crimp: along a float of L elements the yarn rises between the crossings that hold it down,
// h(q) = crimp (1 - 1/L) sin(pi q), q in [0, 1] along the float. A float of one element is
// held at both ends (plain weave stays tight); long floats (satin) bulge.
float crimpSlope(float crimp, WeavePattern::Float f, double alongInElement) {
    if (crimp <= 0.0f || f.length <= 1) return 0.0f;
    const double L = f.length;
    const double q = (f.position + alongInElement) / L;
    return float(crimp * (1.0 - 1.0 / L) * M_PI / L * std::cos(M_PI * q));
}

}  // namespace

glm::vec3 yarnNormal(int alongAxis, float cy, float x, float slope) {
    const glm::vec2 section = crossSectionNormal(cy, x);  // (across, up)
    // Rotate the section normal about the across axis by atan(slope): norm is preserved.
    const float inv = 1.0f / std::sqrt(1.0f + slope * slope);
    const float alongComp = -slope * inv * section.y;
    const float upComp = inv * section.y;
    glm::vec3 n;
    n[alongAxis] = alongComp;
    n[1 - alongAxis] = section.x;
    n.z = upComp;
    return n;
}

YarnPoint yarnAt(const Weave& weave, const WovenParams& p, bool backSide, glm::dvec2 uv) {
    // Double precision and 64-bit thread indices within one wrapped repeat keep any finite uv
    // free of overflow; the position across a thread's cell stays in [0, 1).
    const glm::dvec2 e = weave.wrapped(uv * glm::dvec2(p.repeat));
    const ThreadLayout::Cell end = weave.warp().locate(e.x), pick = weave.weft().locate(e.y);
    const YarnType top = weave.pattern(backSide).top(end.thread, pick.thread);
    const int warpYarn = weave.warp().yarn(end.slot), weftYarn = weave.weft().yarn(pick.slot);
    const Yarn &warp = weave.yarn(warpYarn), &weft = weave.yarn(weftYarn);
    // Across coordinates of the weft (across its pick's cell) and of the warp, in half widths.
    const float xWeft = float((pick.across - 0.5) / (0.5 * weft.width()));
    const float xWarp = float((end.across - 0.5) / (0.5 * warp.width()));

    YarnPoint y;
    auto onWeft = [&](float slope) {
        y.type = YarnType::Weft;
        y.yarnIndex = pick.thread;
        y.slot = pick.slot;
        y.yarn = weftYarn;
        y.along = e.x;
        y.normal = yarnNormal(0, weft.cy(), xWeft, slope);
    };
    auto onWarp = [&](float slope) {
        y.type = YarnType::Warp;
        y.yarnIndex = end.thread;
        y.slot = end.slot;
        y.yarn = warpYarn;
        y.along = e.y;
        y.normal = yarnNormal(1, warp.cy(), xWarp, slope);
    };
    // The slope of the top yarn's crimp along its float (no floats: the material has no crimp).
    auto crimp = [&](double alongInCell) {
        const WeaveFloats* floats = weave.floats();
        return floats ? crimpSlope(p.crimp, floats->at(end.thread, pick.thread, top), alongInCell) : 0.0f;
    };
    // The top yarn where it covers the point, else the crossing yarn below it in the gap
    // beside the top yarn (no crimp there: it is dipping under), else a true gap.
    if (top == YarnType::Weft) {
        if (std::fabs(xWeft) <= 1.0f) onWeft(crimp(end.across));
        else if (std::fabs(xWarp) <= 1.0f) onWarp(0.0f);
    } else {
        if (std::fabs(xWarp) <= 1.0f) onWarp(crimp(pick.across));
        else if (std::fabs(xWeft) <= 1.0f) onWeft(0.0f);
    }
    return y;
}

}  // namespace woven
