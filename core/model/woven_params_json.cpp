#include "woven_params_json.h"

#include <cstdint>
#include <limits>
#include <stdexcept>

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

// How messages name a field: 'cy'. An element of a list is named 'warp_colors'[3].
std::string quoted(const char* name) { return std::string("'") + name + "'"; }

float readNumber(const nlohmann::json& v, const std::string& where) {
    if (!v.is_number()) fail(where + " must be a number");
    return v.get<float>();
}

// get<int>() wraps values beyond int silently (4294967297 -> 1), so check the range first.
int readInteger(const nlohmann::json& v, const std::string& where, const char* what) {
    if (!v.is_number_integer()) fail(where + " " + what);
    const bool fits = v.is_number_unsigned()
                          ? v.get<uint64_t>() <= uint64_t(std::numeric_limits<int>::max())
                          : v.get<int64_t>() >= std::numeric_limits<int>::min() &&
                                v.get<int64_t>() <= std::numeric_limits<int>::max();
    if (!fits) fail(where + " = " + v.dump() + " does not fit an integer");
    return v.get<int>();
}

glm::vec3 readColor(const nlohmann::json& v, const std::string& where) {
    if (v.is_number()) return glm::vec3(v.get<float>());  // grey shorthand
    if (!v.is_array() || v.size() != 3) fail(where + " must be an array of 3 numbers (or one for grey)");
    glm::vec3 c;
    for (int i = 0; i < 3; ++i) c[i] = readNumber(v[size_t(i)], where);
    return c;
}

// The JSON array of a list field, element by element.
template <class Read>
void readList(const nlohmann::json& v, const ParamInfo& info, const char* what, Read read) {
    if (!v.is_array()) fail(quoted(info.name) + " must be an array of " + what);
    for (size_t i = 0; i < v.size(); ++i) read(v[i], quoted(info.name) + "[" + std::to_string(i) + "]");
}

YarnSpec readYarnType(const nlohmann::json& v, const std::string& where) {
    if (!v.is_object()) fail(where + " must be an object of yarn fields (ex, ey, rs, yarn_width, cy, noise)");
    YarnSpec yarn;
    for (const auto& item : v.items()) {
        const ParamInfo* field = nullptr;
        for (const ParamInfo& info : wovenParamTable())
            if (info.yarnField >= 0 && info.yarnSide != YarnSide::Warp && item.key() == info.name) field = &info;
        if (!field) fail(where + ": unknown yarn field '" + item.key() + "' (a yarn type has ex, ey, rs, yarn_width, cy, noise)");
        yarn.value[size_t(field->yarnField)] = readNumber(item.value(), where + "." + item.key());
        yarn.set[size_t(field->yarnField)] = true;
    }
    return yarn;
}

void readField(const nlohmann::json& v, const ParamInfo& info, WovenParams& p) {
    char* base = reinterpret_cast<char*>(&p) + info.offset;
    auto readArray = [&](int n) {
        if (!v.is_array() || int(v.size()) != n)
            fail(quoted(info.name) + " must be an array of " + std::to_string(n) + " numbers");
    };
    switch (info.type) {
        case ParamType::Float: *reinterpret_cast<float*>(base) = readNumber(v, quoted(info.name)); break;
        case ParamType::Int: {
            if (v.is_boolean()) { *reinterpret_cast<int*>(base) = v.get<bool>() ? 1 : 0; break; }
            *reinterpret_cast<int*>(base) = readInteger(v, quoted(info.name), "must be an integer");
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
            for (int c = 0; c < n; ++c) reinterpret_cast<float*>(base)[c] = readNumber(v[c], quoted(info.name));
            break;
        }
        case ParamType::IVec3: {
            readArray(3);
            for (int c = 0; c < 3; ++c)
                reinterpret_cast<int*>(base)[c] = readInteger(v[c], quoted(info.name), "must hold integers");
            break;
        }
        case ParamType::Rows: {
            auto& rows = *reinterpret_cast<std::vector<std::string>*>(base);
            rows.clear();
            readList(v, info, "strings", [&](const nlohmann::json& row, const std::string&) {
                if (!row.is_string()) fail(quoted(info.name) + " must be an array of strings");
                rows.push_back(row.get<std::string>());
            });
            break;
        }
        case ParamType::Vec3List: {
            auto& list = *reinterpret_cast<std::vector<glm::vec3>*>(base);
            list.clear();
            readList(v, info, "colours", [&](const nlohmann::json& c, const std::string& where) { list.push_back(readColor(c, where)); });
            break;
        }
        case ParamType::IntList: {
            auto& list = *reinterpret_cast<std::vector<int>*>(base);
            list.clear();
            readList(v, info, "integers", [&](const nlohmann::json& i, const std::string& where) {
                list.push_back(readInteger(i, where, "must be an integer"));
            });
            break;
        }
        case ParamType::FloatList: {
            auto& list = *reinterpret_cast<std::vector<float>*>(base);
            list.clear();
            readList(v, info, "numbers", [&](const nlohmann::json& f, const std::string& where) { list.push_back(readNumber(f, where)); });
            break;
        }
        case ParamType::YarnList: {
            auto& list = *reinterpret_cast<std::vector<YarnSpec>*>(base);
            list.clear();
            readList(v, info, "yarn types", [&](const nlohmann::json& y, const std::string& where) { list.push_back(readYarnType(y, where)); });
            break;
        }
    }
}

nlohmann::json yarnTypeToJson(const YarnSpec& yarn) {
    nlohmann::json j = nlohmann::json::object();
    for (const ParamInfo& info : wovenParamTable())
        if (info.yarnField >= 0 && info.yarnSide != YarnSide::Warp && yarn.set[size_t(info.yarnField)])
            j[info.name] = yarn.value[size_t(info.yarnField)];
    return j;
}

}  // namespace

WovenParams paramsFromJson(const nlohmann::json& j, const WovenParams& baseParams) {
    if (!j.is_object()) fail("a woven material must be a JSON object");
    WovenParams p = baseParams;
    const auto& table = wovenParamTable();
    for (const auto& item : j.items()) {
        bool known = false;
        for (const ParamInfo& info : table) known |= item.key() == info.name;
        if (!known && (item.key() == "wif" || item.key() == "scale"))
            fail("'" + item.key() + "' is read where a file can be found: in scene files, --woven and material files"
                 " (docs/DRAFTS.md)");
        if (!known) fail("unknown woven material field '" + item.key() + "'");
    }
    for (const ParamInfo& info : table) {
        if (j.contains(info.name)) readField(j.at(info.name), info, p);
        else if (info.fallback && j.contains(info.fallback)) readField(j.at(info.fallback), info, p);
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
            // Lists are written only when they say something: empty is the default.
            case ParamType::Rows: {
                const auto& rows = *reinterpret_cast<const std::vector<std::string>*>(base);
                if (!rows.empty()) j[info.name] = rows;
                break;
            }
            case ParamType::Vec3List: {
                const auto& list = *reinterpret_cast<const std::vector<glm::vec3>*>(base);
                if (list.empty()) break;
                nlohmann::json& out = j[info.name] = nlohmann::json::array();
                for (const glm::vec3& c : list) out.push_back({c.x, c.y, c.z});
                break;
            }
            case ParamType::IntList: {
                const auto& list = *reinterpret_cast<const std::vector<int>*>(base);
                if (!list.empty()) j[info.name] = list;
                break;
            }
            case ParamType::FloatList: {
                const auto& list = *reinterpret_cast<const std::vector<float>*>(base);
                if (!list.empty()) j[info.name] = list;
                break;
            }
            case ParamType::YarnList: {
                const auto& list = *reinterpret_cast<const std::vector<YarnSpec>*>(base);
                if (list.empty()) break;
                nlohmann::json& out = j[info.name] = nlohmann::json::array();
                for (const YarnSpec& yarn : list) out.push_back(yarnTypeToJson(yarn));
                break;
            }
        }
    }
    return j;
}

}  // namespace woven
