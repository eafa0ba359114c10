#include "woven_params.h"

#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>

namespace woven {

const std::vector<ParamInfo>& wovenParamTable() {
    using P = WovenParams;
    using T = ParamType;
    static const std::vector<ParamInfo> table = {
        {"pattern", T::IVec3, offsetof(P, pattern), 0, 1024, false, "weave (i, j, k)", nullptr},
        {"repeat", T::Vec2, offsetof(P, repeat), 1e-6f, 1e6f, true, "elements per UV unit (1/n, 1/m)", nullptr},
        {"ex", T::Float, offsetof(P, ex), 0, 1e5f, true, "weft e_x (along yarn)", nullptr},
        {"ey", T::Float, offsetof(P, ey), 0, 1e5f, true, "weft e_y (across yarn)", nullptr},
        {"warp_ex", T::Float, offsetof(P, warp_ex), 0, 1e5f, true, "warp e_x (along yarn)", "ex"},
        {"warp_ey", T::Float, offsetof(P, warp_ey), 0, 1e5f, true, "warp e_y (across yarn)", "ey"},
        {"rs", T::Float, offsetof(P, rs), 0, 1, false, "R_s specular reflectance", nullptr},
        {"weft_color", T::Vec3, offsetof(P, weft_color), 0, 1, false, "weft R_d", nullptr},
        {"warp_color", T::Vec3, offsetof(P, warp_color), 0, 1, false, "warp R_d", "weft_color"},
        {"cy", T::Float, offsetof(P, cy), 0, 1, false, "c_y yarn curvature", nullptr},
        {"yarn_width", T::Float, offsetof(P, yarn_width), 1e-3f, 1, false, "weft yarn width", nullptr},
        {"warp_width", T::Float, offsetof(P, warp_width), 1e-3f, 1, false, "warp yarn width", "yarn_width"},
        {"crimp", T::Float, offsetof(P, crimp), 0, 1, false, "crimp along floats", nullptr},
        {"noise", T::Float, offsetof(P, noise), 0, 1, false, "per-yarn noise", nullptr},
        {"noise_scale", T::Float, offsetof(P, noise_scale), 1e-3f, 100, true, "noise features per element", nullptr},
        {"backing", T::Int, offsetof(P, backing), 0, 1, false, "gaps show backing (else see-through)", nullptr},
        {"backing_color", T::Vec3, offsetof(P, backing_color), 0, 1, false, "backing R_d", nullptr},
    };
    return table;
}

namespace {

int componentCount(ParamType t) {
    switch (t) {
        case ParamType::Float: case ParamType::Int: return 1;
        case ParamType::Vec2: return 2;
        case ParamType::Vec3: case ParamType::IVec3: return 3;
    }
    return 0;
}

double component(const WovenParams& p, const ParamInfo& info, int c) {
    const char* base = reinterpret_cast<const char*>(&p) + info.offset;
    if (info.type == ParamType::Int || info.type == ParamType::IVec3)
        return reinterpret_cast<const int*>(base)[c];
    return reinterpret_cast<const float*>(base)[c];
}

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

}  // namespace

void validate(const WovenParams& p) {
    for (const ParamInfo& info : wovenParamTable()) {
        for (int c = 0; c < componentCount(info.type); ++c) {
            double v = component(p, info, c);
            if (!std::isfinite(v) || v < info.min || v > info.max) {
                std::ostringstream s;
                s << "'" << info.name << "'";
                if (componentCount(info.type) > 1) s << "[" << c << "]";
                s << " = " << v << " is outside [" << info.min << ", " << info.max << "]";
                fail(s.str());
            }
        }
    }
    if (p.tile.empty()) {
        if (p.pattern.x + p.pattern.y < 1) fail("'pattern': i + j must be at least 1");
        if (p.pattern.x + p.pattern.y > 1024) fail("'pattern': i + j must be at most 1024");
    } else {
        size_t width = p.tile[0].size();
        if (width == 0) fail("'tile': rows must not be empty");
        for (const std::string& row : p.tile) {
            if (row.size() != width) fail("'tile': all rows must have the same length");
            for (char ch : row)
                if (ch != '-' && ch != '|')
                    fail(std::string("'tile': unexpected character '") + ch + "' (use '-' weft, '|' warp)");
        }
        if (p.tile.size() > 1024 || width > 1024) fail("'tile': at most 1024 x 1024 cells");
    }
}

}  // namespace woven
