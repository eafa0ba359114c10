#include "weave_far_field.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "weave_coverage.h"
#include "yarn_geometry.h"

namespace woven {

float farFieldWeight(float elements) {
    const float t = std::clamp((elements - 0.25f) / 0.75f, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

namespace {
// The integral over the box [e0, e1] of a function constant on each unit cell and periodic over
// width x height cells, from its table of sums below and left of each corner ((width + 1) x
// (height + 1)): the box moved into the first period (so the sums stay small and exact for any
// uv), then whole periods and the table bilinearly inside one (exact for a piecewise-constant
// function).
template <class Sum, class Stored>
Sum periodicBoxIntegral(const std::vector<Stored>& sums, glm::ivec2 size, const glm::dvec2& e0, const glm::dvec2& e1) {
    const size_t stride = size_t(size.x) + 1;
    auto at = [&](int u, int v) { return Sum(sums[size_t(v) * stride + size_t(u)]); };
    auto inPeriod = [&](double x, double y) {  // 0 <= x <= width, 0 <= y <= height
        const int u = std::min(int(x), size.x - 1), v = std::min(int(y), size.y - 1);
        const double fx = x - u, fy = y - v;
        return (1 - fx) * (1 - fy) * at(u, v) + fx * (1 - fy) * at(u + 1, v) + (1 - fx) * fy * at(u, v + 1) +
               fx * fy * at(u + 1, v + 1);
    };
    const glm::dvec2 period(size);
    auto integral = [&](double x, double y) {
        const double qx = std::floor(x / period.x), qy = std::floor(y / period.y);
        const double rx = x - qx * period.x, ry = y - qy * period.y;
        return qx * qy * at(size.x, size.y) + qx * inPeriod(period.x, ry) + qy * inPeriod(rx, period.y) + inPeriod(rx, ry);
    };
    const glm::dvec2 shift = glm::floor(e0 / period) * period;
    const glm::dvec2 a = e0 - shift, b = e1 - shift;
    return integral(b.x, b.y) - integral(a.x, b.y) - integral(b.x, a.y) + integral(a.x, a.y);
}

// The table of sums below and left of each corner of f(u, v) over width x height cells.
template <class T, class F>
std::vector<T> cornerSums(glm::ivec2 size, F f) {
    const size_t stride = size_t(size.x) + 1;
    std::vector<T> sums(stride * (size_t(size.y) + 1), T(0));
    for (int v = 0; v < size.y; ++v)
        for (int u = 0; u < size.x; ++u)
            sums[(size_t(v) + 1) * stride + size_t(u) + 1] = sums[size_t(v) * stride + size_t(u) + 1] +
                                                             sums[(size_t(v) + 1) * stride + size_t(u)] -
                                                             sums[size_t(v) * stride + size_t(u)] + f(u, v);
    return sums;
}

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
    auto warpTop = [&](int u, int v) { return pattern.topInTile(u, v) == YarnType::Warp ? 1.0f : 0.0f; };
    warpTopSums_ = cornerSums<float>({tileWidth_, tileHeight_}, warpTop);

    // footprintColors()'s tables, over the joint period of the tile and each side's colours: a
    // float table counts cells exactly up to 2^24, and a draft's periods rarely pass a few hundred.
    constexpr int64_t kMaxColorTable = int64_t(1) << 20;
    const ThreadLayout* sides[2] = {&weave.warp(), &weave.weft()};
    for (int side = 0; side < 2; ++side) {
        const int period = sides[side]->period();
        if (period == 1) continue;
        const int tile = side == 0 ? tileWidth_ : tileHeight_;
        const int64_t joint = std::min(std::lcm(int64_t(tile), int64_t(period)), kMaxColorTable);
        const glm::ivec2 size = side == 0 ? glm::ivec2(int(joint), tileHeight_) : glm::ivec2(tileWidth_, int(joint));
        if ((int64_t(size.x) + 1) * (int64_t(size.y) + 1) > kMaxColorTable) continue;
        colorTableSize_[side] = size;
        colorTops_[side] = cornerSums<glm::vec4>(size, [&](int u, int v) {
            const float top = warpTop(u % tileWidth_, v % tileHeight_);
            return glm::vec4(top * sides[side]->color((side == 0 ? u : v) % period), top);
        });
    }
}

glm::vec3 WeaveFarField::footprintScales(const glm::dvec2& e0, const glm::dvec2& e1) const {
    if (!byFootprint_) return glm::vec3(1.0f);
    const double area = (e1.x - e0.x) * (e1.y - e0.y);
    if (!(area > 0.0)) return glm::vec3(1.0f);
    const double warpTop = periodicBoxIntegral<double>(warpTopSums_, {tileWidth_, tileHeight_}, e0, e1);
    const float f = float(std::clamp(warpTop / area, 0.0, 1.0));
    glm::vec3 scale;
    float total = 0.0f;
    for (int c = 0; c < 3; ++c) {
        const float boxShare = f * inWarpCells_[c] + (1.0f - f) * inWeftCells_[c];
        scale[c] = share_[c] > 0.0f ? boxShare / share_[c] : 0.0f;
        total += boxShare;
    }
    return total > 0.0f ? scale / total : glm::vec3(1.0f);
}

void WeaveFarField::footprintColors(const glm::dvec2& e0, const glm::dvec2& e1, glm::vec3& warp, glm::vec3& weft) const {
    const double area = (e1.x - e0.x) * (e1.y - e0.y);
    if (!(area > 0.0)) return;
    // Each side's yarn covers one share of the cells where it is on top and another of the
    // others: its colour is the mean over the box of each cell's colour weighted by that share.
    glm::vec3* colors[2] = {&warp, &weft};
    const double inTop[2] = {inWarpCells_[0], inWeftCells_[1]}, inOther[2] = {inWeftCells_[0], inWarpCells_[1]};
    for (int side = 0; side < 2; ++side) {
        if (!weightsColors(side)) continue;
        const glm::dvec4 s = periodicBoxIntegral<glm::dvec4>(colorTops_[side], colorTableSize_[side], e0, e1);
        const glm::dvec3 all = glm::dvec3(*colors[side]) * area, inWarpTop(s);
        const double warpTop = std::clamp(s.w, 0.0, area);
        const glm::dvec3 topColor = side == 0 ? inWarpTop : all - inWarpTop, otherColor = all - topColor;
        const double top = side == 0 ? warpTop : area - warpTop;
        const double weight = inTop[side] * top + inOther[side] * (area - top);
        if (weight > 1e-9 * area) *colors[side] = glm::vec3((inTop[side] * topColor + inOther[side] * otherColor) / weight);
    }
}

}  // namespace woven
