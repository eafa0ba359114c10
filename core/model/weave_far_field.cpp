#include "weave_far_field.h"

#include <algorithm>
#include <cmath>

#include "weave_coverage.h"
#include "yarn_geometry.h"

namespace woven {

float farFieldWeight(float elements) {
    const float t = std::clamp((elements - 0.25f) / 0.75f, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

namespace {
bool sameLobe(const FarFieldLobe& a, const FarFieldLobe& b) {
    return a.color == b.color && a.frame.x == b.frame.x && a.frame.z == b.frame.z && a.shape.ex == b.shape.ex &&
           a.shape.ey == b.shape.ey && a.shape.rs == b.shape.rs;
}
}  // namespace

WeaveFarField::WeaveFarField(const Weave& weave, const WovenParams& p, bool backSide) {
    const WeaveCoverage coverage = weaveCoverage(weave, backSide);
    const float gap = std::max(0.0f, 1.0f - coverage.weft - coverage.warp);
    const bool backing = p.backing != 0 && gap > 0.0f;
    const float opaque = coverage.weft + coverage.warp + (backing ? gap : 0.0f);
    if (!(opaque > 0.0f)) return;
    auto add = [&](const FarFieldLobe& lobe) {
        for (FarFieldLobe& l : lobes_)
            if (sameLobe(l, lobe)) {
                l.weight += lobe.weight;
                return;
            }
        lobes_.push_back(lobe);
    };
    // Weave::yarn() indices: 0 the warp's own, 1 the weft's own, then the types on the warp, then on the weft.
    const int types = int(p.yarns.size());
    for (int y = 0; y < weave.yarnCount(); ++y) {
        const float share = coverage.yarns[size_t(y)] / opaque;
        if (!(share > 0.0f)) continue;
        const bool weft = y == 1 || y >= 2 + types;
        const FarFieldColor color = weft ? FarFieldColor::Weft : FarFieldColor::Warp;
        const glm::vec3 sideColor = weft ? p.weft_color : p.warp_color;
        const LobeShape& shape = weave.lobeShape(y);
        const glm::vec3 axis = weft ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        for (int k = 0; k < kFarFieldSections; ++k) {
            const glm::vec3 n = yarnNormal(weft ? 0 : 1, weave.yarn(y).cy(), farFieldSection(k), 0.0f);
            add({Frame::fromNormalAndAxis(n, axis), shape, AshikhminShirley::specularProbability(shape.rs, sideColor),
                 share / float(kFarFieldSections), color});
        }
    }
    if (backing) {
        const LobeShape flat(0.0f, 0.0f, 0.0f);
        add({Frame{}, flat, AshikhminShirley::specularProbability(0.0f, p.backing_color), gap / opaque,
             FarFieldColor::Backing});
    }
    for (const FarFieldLobe& l : lobes_) share_[int(l.color)] += l.weight;

    // The split by top yarn, for footprints smaller than the repeat (evenly spaced threads only).
    const WeavePattern& pattern = weave.pattern(backSide);
    warpCells_ = coverage.warpCells;
    byFootprint_ = !weave.warp().spaced() && !weave.weft().spaced() && warpCells_ > 0.0f && warpCells_ < 1.0f;
    if (!byFootprint_) return;
    const float weftCells = 1.0f - warpCells_;
    const float gapInWarp = backing ? warpCells_ - coverage.weftInWarpCells - coverage.warpInWarpCells : 0.0f;
    const float gapInWeft = backing ? gap - gapInWarp : 0.0f;
    const float in[3] = {coverage.warpInWarpCells, coverage.weftInWarpCells, gapInWarp};
    const float out[3] = {coverage.warp - coverage.warpInWarpCells, coverage.weft - coverage.weftInWarpCells, gapInWeft};
    for (int c = 0; c < 3; ++c) {
        inWarpCells_[c] = std::max(0.0f, in[c]) / (warpCells_ * opaque);
        inWeftCells_[c] = std::max(0.0f, out[c]) / (weftCells * opaque);
    }
    tileWidth_ = pattern.width();
    tileHeight_ = pattern.height();
    const size_t stride = size_t(tileWidth_) + 1;
    warpTopSums_.assign(stride * (size_t(tileHeight_) + 1), 0.0f);
    for (int v = 0; v < tileHeight_; ++v)
        for (int u = 0; u < tileWidth_; ++u)
            warpTopSums_[(size_t(v) + 1) * stride + size_t(u) + 1] =
                warpTopSums_[size_t(v) * stride + size_t(u) + 1] + warpTopSums_[(size_t(v) + 1) * stride + size_t(u)] -
                warpTopSums_[size_t(v) * stride + size_t(u)] + (pattern.topInTile(u, v) == YarnType::Warp ? 1.0f : 0.0f);
}

double WeaveFarField::warpTopArea(double x0, double y0, double x1, double y1) const {
    // The cells' indicator integrated from the tile's corner to (x, y), for any x, y >= 0: whole
    // tiles, then the table bilinearly inside one (exact for a piecewise-constant function).
    const size_t stride = size_t(tileWidth_) + 1;
    auto at = [&](int u, int v) { return double(warpTopSums_[size_t(v) * stride + size_t(u)]); };
    auto inTile = [&](double x, double y) {  // 0 <= x <= width, 0 <= y <= height
        const int u = std::min(int(x), tileWidth_ - 1), v = std::min(int(y), tileHeight_ - 1);
        const double fx = x - u, fy = y - v;
        return (1 - fx) * (1 - fy) * at(u, v) + fx * (1 - fy) * at(u + 1, v) + (1 - fx) * fy * at(u, v + 1) +
               fx * fy * at(u + 1, v + 1);
    };
    auto integral = [&](double x, double y) {
        const double W = tileWidth_, H = tileHeight_;
        const double qx = std::floor(x / W), qy = std::floor(y / H);
        const double rx = x - qx * W, ry = y - qy * H;
        return qx * qy * at(tileWidth_, tileHeight_) + qx * inTile(W, ry) + qy * inTile(rx, H) + inTile(rx, ry);
    };
    return integral(x1, y1) - integral(x0, y1) - integral(x1, y0) + integral(x0, y0);
}

glm::vec3 WeaveFarField::footprintScales(const glm::dvec2& e0, const glm::dvec2& e1) const {
    if (!byFootprint_) return glm::vec3(1.0f);
    // The box moved into the first repeat, so the integrals stay small and exact for any uv.
    const glm::dvec2 tile(tileWidth_, tileHeight_);
    const glm::dvec2 shift = glm::floor(e0 / tile) * tile;
    const glm::dvec2 a = e0 - shift, b = e1 - shift;
    const double area = (b.x - a.x) * (b.y - a.y);
    if (!(area > 0.0)) return glm::vec3(1.0f);
    const float f = float(std::clamp(warpTopArea(a.x, a.y, b.x, b.y) / area, 0.0, 1.0));
    glm::vec3 scale;
    float total = 0.0f;
    for (int c = 0; c < 3; ++c) {
        const float boxShare = f * inWarpCells_[c] + (1.0f - f) * inWeftCells_[c];
        scale[c] = share_[c] > 0.0f ? boxShare / share_[c] : 0.0f;
        total += boxShare;
    }
    return total > 0.0f ? scale / total : glm::vec3(1.0f);
}

}  // namespace woven
