#include "woven_params_json.h"

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

float readNumber(const nlohmann::json& v, const char* name) {
    if (!v.is_number()) fail(std::string("'") + name + "' must be a number");
    return v.get<float>();
}

// get<int>() wraps values beyond int silently (4294967297 -> 1), so check the range first.
int readInteger(const nlohmann::json& v, const char* name, const char* what) {
    if (!v.is_number_integer()) fail(std::string("'") + name + "' " + what);
    const bool fits = v.is_number_unsigned()
                          ? v.get<uint64_t>() <= uint64_t(std::numeric_limits<int>::max())
                          : v.get<int64_t>() >= std::numeric_limits<int>::min() &&
                                v.get<int64_t>() <= std::numeric_limits<int>::max();
    if (!fits) fail(std::string("'") + name + "' = " + v.dump() + " does not fit an integer");
    return v.get<int>();
}

void readField(const nlohmann::json& v, const ParamInfo& info, WovenParams& p) {
    char* base = reinterpret_cast<char*>(&p) + info.offset;
    auto readArray = [&](int n) {
        if (!v.is_array() || int(v.size()) != n)
            fail(std::string("'") + info.name + "' must be an array of " + std::to_string(n) + " numbers");
    };
    switch (info.type) {
        case ParamType::Float: *reinterpret_cast<float*>(base) = readNumber(v, info.name); break;
        case ParamType::Int: {
            if (v.is_boolean()) { *reinterpret_cast<int*>(base) = v.get<bool>() ? 1 : 0; break; }
            *reinterpret_cast<int*>(base) = readInteger(v, info.name, "must be an integer");
            break;
        }
        case ParamType::Vec2:
        case ParamType::Vec3: {
            int n = info.type == ParamType::Vec2 ? 2 : 3;
            if (v.is_number() && info.type == ParamType::Vec3) {  // grey shorthand
                for (int c = 0; c < 3; ++c) reinterpret_cast<float*>(base)[c] = v.get<float>();
                break;
            }
            readArray(n);
            for (int c = 0; c < n; ++c) reinterpret_cast<float*>(base)[c] = readNumber(v[c], info.name);
            break;
        }
        case ParamType::IVec3: {
            readArray(3);
            for (int c = 0; c < 3; ++c)
                reinterpret_cast<int*>(base)[c] = readInteger(v[c], info.name, "must hold integers");
            break;
        }
    }
}

}  // namespace

WovenParams paramsFromJson(const nlohmann::json& j, const WovenParams& baseParams) {
    if (!j.is_object()) fail("a woven material must be a JSON object");
    WovenParams p = baseParams;
    const auto& table = wovenParamTable();
    for (const auto& item : j.items()) {
        if (item.key() == "tile") continue;
        bool known = false;
        for (const ParamInfo& info : table) known |= item.key() == info.name;
        if (!known) fail("unknown woven material field '" + item.key() + "'");
    }
    for (const ParamInfo& info : table) {
        if (j.contains(info.name)) readField(j.at(info.name), info, p);
        else if (info.fallback && j.contains(info.fallback)) readField(j.at(info.fallback), info, p);
    }
    if (j.contains("tile")) {
        const auto& t = j.at("tile");
        if (!t.is_array()) fail("'tile' must be an array of strings");
        p.tile.clear();
        for (const auto& row : t) {
            if (!row.is_string()) fail("'tile' must be an array of strings");
            p.tile.push_back(row.get<std::string>());
        }
    }
    validate(p);
    return p;
}

nlohmann::json paramsToJson(const WovenParams& p) {
    nlohmann::json j = nlohmann::json::object();
    for (const ParamInfo& info : wovenParamTable()) {
        const char* base = reinterpret_cast<const char*>(&p) + info.offset;
        const float* f = reinterpret_cast<const float*>(base);
        const int* i = reinterpret_cast<const int*>(base);
        switch (info.type) {
            case ParamType::Float: j[info.name] = f[0]; break;
            case ParamType::Int: j[info.name] = i[0]; break;
            case ParamType::Vec2: j[info.name] = {f[0], f[1]}; break;
            case ParamType::Vec3: j[info.name] = {f[0], f[1], f[2]}; break;
            case ParamType::IVec3: j[info.name] = {i[0], i[1], i[2]}; break;
        }
    }
    if (!p.tile.empty()) j["tile"] = p.tile;
    return j;
}

}  // namespace woven
