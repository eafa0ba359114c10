#include "woven_params.h"

#include <cmath>
#include <cstddef>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace woven {

bool operator==(const YarnSpec& a, const YarnSpec& b) {
    for (int f = 0; f < kYarnFieldCount; ++f)
        if (a.set[f] != b.set[f] || (a.set[f] && a.value[f] != b.value[f])) return false;
    return true;
}

const std::vector<ParamInfo>& wovenParamTable() {
    using P = WovenParams;
    using T = ParamType;
    using S = YarnSide;
    static const std::vector<ParamInfo> table = {
        {"pattern", T::IVec3, offsetof(P, pattern), 0, 1024, false, "weave (i, j, k)", "weave (i, j, k), MODEL.md section 1", nullptr},
        {"tile", T::Rows, offsetof(P, tile), 0, 0, false, "weave tile ('-' weft, '|' warp)", "a general weave tile, one string a row: - where the weft is on top, a vertical bar where the warp is; replaces `pattern`", nullptr},
        {"repeat", T::Vec2, offsetof(P, repeat), 1e-6f, 1e6f, true, "threads per UV unit (1/n, 1/m)", "weave elements (threads, on average) per UV unit along u, v", nullptr},
        {"ex", T::Float, offsetof(P, ex), 0, 1e5f, true, "weft e_x (along yarn)", "weft Ashikhmin-Shirley exponent along the yarn", nullptr, kYarnEx, S::Weft},
        {"ey", T::Float, offsetof(P, ey), 0, 1e5f, true, "weft e_y (across yarn)", "weft Ashikhmin-Shirley exponent across the yarn", nullptr, kYarnEy, S::Weft},
        {"warp_ex", T::Float, offsetof(P, warp_ex), 0, 1e5f, true, "warp e_x (along yarn)", "warp exponent along the yarn", "ex", kYarnEx, S::Warp},
        {"warp_ey", T::Float, offsetof(P, warp_ey), 0, 1e5f, true, "warp e_y (across yarn)", "warp exponent across the yarn", "ey", kYarnEy, S::Warp},
        {"rs", T::Float, offsetof(P, rs), 0, 1, false, "R_s specular reflectance", "specular reflectance at normal incidence", nullptr, kYarnRs, S::Both},
        {"weft_color", T::Vec3, offsetof(P, weft_color), 0, 1, false, "weft R_d", "weft diffuse reflectance, linear RGB (or one number)", nullptr},
        {"warp_color", T::Vec3, offsetof(P, warp_color), 0, 1, false, "warp R_d", "warp diffuse reflectance, linear RGB (or one number)", "weft_color"},
        {"cy", T::Float, offsetof(P, cy), 0, 1, false, "c_y yarn curvature", "yarn cross-section curvature", nullptr, kYarnCy, S::Both},
        {"yarn_width", T::Float, offsetof(P, yarn_width), 1e-3f, 1, false, "weft yarn width", "weft yarn width as a fraction of its element", nullptr, kYarnWidth, S::Weft},
        {"warp_width", T::Float, offsetof(P, warp_width), 1e-3f, 1, false, "warp yarn width", "warp yarn width as a fraction of its element", "yarn_width", kYarnWidth, S::Warp},
        {"crimp", T::Float, offsetof(P, crimp), 0, 1, false, "crimp along floats", "rise and dip of the yarns along floats", nullptr},
        {"noise", T::Float, offsetof(P, noise), 0, 1, false, "per-yarn noise", "per-yarn colour noise", nullptr, kYarnNoise, S::Both},
        {"transmission", T::Float, offsetof(P, transmission), 0, 1, false, "yarn transmission", "fraction of the light a yarn does not reflect that it passes to the other side, in the yarn's hue deepened; 0 = opaque yarns (docs/MODEL_TRANSMISSION.md)", nullptr, kYarnTransmission, S::Both},
        {"transmission_gloss", T::Float, offsetof(P, transmission_gloss), 0, 1, false, "transmission gloss", "share of the transmitted light that leaves forward along the fibres (the Ashikhmin-Shirley lobe through the sheet); the rest leaves diffusely", nullptr, kYarnTransmissionGloss, S::Both},
        {"noise_scale", T::Float, offsetof(P, noise_scale), 1e-3f, 100, true, "noise features per element", "noise features per weave element", nullptr},
        {"backing", T::Int, offsetof(P, backing), 0, 1, false, "gaps show backing (else see-through)", "1: gaps show `backing_color`; 0: gaps are see-through (a bool also reads)", nullptr},
        {"backing_color", T::Vec3, offsetof(P, backing_color), 0, 1, false, "backing R_d", "diffuse reflectance of the backing seen through gaps", nullptr},
        {"warp_colors", T::Vec3List, offsetof(P, warp_colors), 0, 1, false, "R_d per warp end", "diffuse reflectance per warp end, repeating", nullptr},
        {"weft_colors", T::Vec3List, offsetof(P, weft_colors), 0, 1, false, "R_d per weft pick", "diffuse reflectance per weft pick, repeating", nullptr},
        {"yarns", T::YarnList, offsetof(P, yarns), 0, 0, false, "yarn types", "yarn types: objects with any of `ex`, `ey`, `rs`, `yarn_width`, `cy`, `noise`, `transmission`, `transmission_gloss`", nullptr},
        {"warp_yarns", T::IntList, offsetof(P, warp_yarns), 0, kMaxYarnTypes - 1, false, "yarn type per warp end", "yarn type per warp end, repeating", nullptr},
        {"weft_yarns", T::IntList, offsetof(P, weft_yarns), 0, kMaxYarnTypes - 1, false, "yarn type per weft pick", "yarn type per weft pick, repeating", nullptr},
        {"warp_spacing", T::FloatList, offsetof(P, warp_spacing), 1e-6f, 1e6f, false, "spacing per warp end", "relative spacing per warp end, repeating (proportions: only their ratios count)", nullptr},
        {"weft_spacing", T::FloatList, offsetof(P, weft_spacing), 1e-6f, 1e6f, false, "spacing per weft pick", "relative spacing per weft pick, repeating (proportions: only their ratios count)", nullptr},
    };
    return table;
}

bool isNumeric(ParamType t) {
    switch (t) {
        case ParamType::Float: case ParamType::Int: case ParamType::Vec2: case ParamType::Vec3: case ParamType::IVec3:
            return true;
        default: return false;
    }
}

namespace {

int componentCount(ParamType t) {
    switch (t) {
        case ParamType::Vec2: return 2;
        case ParamType::Vec3: case ParamType::IVec3: return 3;
        default: return 1;
    }
}

double component(const WovenParams& p, const ParamInfo& info, int c) {
    const char* base = reinterpret_cast<const char*>(&p) + info.offset;
    if (info.type == ParamType::Int || info.type == ParamType::IVec3)
        return reinterpret_cast<const int*>(base)[c];
    return reinterpret_cast<const float*>(base)[c];
}

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

void checkRange(double v, const ParamInfo& info, const std::string& where) {
    if (std::isfinite(v) && v >= info.min && v <= info.max) return;
    std::ostringstream s;
    s << where << " = " << v << " is outside [" << info.min << ", " << info.max << "]";
    fail(s.str());
}

// How messages name a field, or an element of a list: 'cy', 'warp_colors'[3].
std::string quoted(const ParamInfo& info) { return "'" + std::string(info.name) + "'"; }
std::string element(const ParamInfo& info, size_t i) { return quoted(info) + "[" + std::to_string(i) + "]"; }

void checkLength(size_t n, const ParamInfo& info, size_t max) {
    if (n > max) fail(quoted(info) + " has " + std::to_string(n) + " entries, at most " + std::to_string(max));
}

void validateList(const WovenParams& p, const ParamInfo& info) {
    const char* base = reinterpret_cast<const char*>(&p) + info.offset;
    switch (info.type) {
        case ParamType::Vec3List: {
            const auto& list = *reinterpret_cast<const std::vector<glm::vec3>*>(base);
            checkLength(list.size(), info, kMaxThreadPeriod);
            for (size_t i = 0; i < list.size(); ++i)
                for (int c = 0; c < 3; ++c) checkRange(list[i][c], info, element(info, i));
            break;
        }
        case ParamType::IntList: {
            const auto& list = *reinterpret_cast<const std::vector<int>*>(base);
            checkLength(list.size(), info, kMaxThreadPeriod);
            for (size_t i = 0; i < list.size(); ++i) {
                checkRange(list[i], info, element(info, i));
                if (size_t(list[i]) >= p.yarns.size())
                    fail(element(info, i) + " = " + std::to_string(list[i]) + " names no yarn type ('yarns' has " +
                         std::to_string(p.yarns.size()) + ")");
            }
            break;
        }
        case ParamType::FloatList: {
            const auto& list = *reinterpret_cast<const std::vector<float>*>(base);
            checkLength(list.size(), info, kMaxThreadPeriod);
            for (size_t i = 0; i < list.size(); ++i) checkRange(list[i], info, element(info, i));
            break;
        }
        case ParamType::YarnList:
            checkLength(p.yarns.size(), info, kMaxYarnTypes);
            for (size_t i = 0; i < p.yarns.size(); ++i)
                for (const ParamInfo& field : wovenParamTable())
                    if (field.yarnField >= 0 && field.yarnSide != YarnSide::Warp && p.yarns[i].set[size_t(field.yarnField)])
                        checkRange(p.yarns[i].value[size_t(field.yarnField)], field,
                                   element(info, i) + "." + field.name);
            break;
        default: break;
    }
}

void validateTile(const std::vector<std::string>& tile) {
    const size_t width = tile[0].size();
    if (width == 0) fail("'tile': rows must not be empty");
    for (const std::string& row : tile) {
        if (row.size() != width) fail("'tile': all rows must have the same length");
        for (char ch : row)
            if (ch != '-' && ch != '|') fail(std::string("'tile': unexpected character '") + ch + "' (use '-' weft, '|' warp)");
    }
    if (tile.size() > size_t(kMaxTileSide) || width > size_t(kMaxTileSide) || tile.size() * width > kMaxTileCells)
        fail("'tile': " + std::to_string(width) + " x " + std::to_string(tile.size()) + " is beyond woven's limit of " +
             std::to_string(kMaxTileSide) + " threads either way and " + std::to_string(kMaxTileCells) + " cells");
}

// The lists of one side repeat together every lcm of their lengths threads, the period the
// model expands them to (ThreadLayout).
void validatePeriod(const char* side, size_t colors, size_t yarns, size_t spacing) {
    size_t period = 1;
    for (size_t n : {colors, yarns, spacing})
        if (n > 0) period = std::lcm(period, n);
    if (period > size_t(kMaxThreadPeriod))
        fail(std::string("'") + side + "_colors' (" + std::to_string(colors) + "), '" + side + "_yarns' (" +
             std::to_string(yarns) + ") and '" + side + "_spacing' (" + std::to_string(spacing) +
             " entries) repeat together only every " + std::to_string(period) + " threads, more than " +
             std::to_string(kMaxThreadPeriod));
}

}  // namespace

void validate(const WovenParams& p) {
    for (const ParamInfo& info : wovenParamTable()) {
        if (!isNumeric(info.type)) {
            validateList(p, info);
            continue;
        }
        for (int c = 0; c < componentCount(info.type); ++c) {
            std::string where = quoted(info);
            if (componentCount(info.type) > 1) where += "[" + std::to_string(c) + "]";
            checkRange(component(p, info, c), info, where);
        }
    }
    if (p.tile.empty()) {
        if (p.pattern.x + p.pattern.y < 1) fail("'pattern': i + j must be at least 1");
        if (p.pattern.x + p.pattern.y > 1024) fail("'pattern': i + j must be at most 1024");
    } else {
        validateTile(p.tile);
    }
    validatePeriod("warp", p.warp_colors.size(), p.warp_yarns.size(), p.warp_spacing.size());
    validatePeriod("weft", p.weft_colors.size(), p.weft_yarns.size(), p.weft_spacing.size());
}

bool hasThreadLists(const WovenParams& p) {
    return !p.warp_colors.empty() || !p.weft_colors.empty() || !p.warp_yarns.empty() || !p.weft_yarns.empty() ||
           !p.warp_spacing.empty() || !p.weft_spacing.empty();
}

}  // namespace woven
