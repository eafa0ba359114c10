#include "fabric_library.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "file_reading.h"
#include "untrusted_json.h"

namespace woven {

namespace {

constexpr size_t kMaxFabricFileBytes = size_t(1) << 20;  // a fabric file is a few hundred bytes

bool isFabricName(const std::string& name) {
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
    });
}

std::string requiredString(const nlohmann::json& j, const char* key, const std::string& file) {
    if (!j.contains(key) || !j[key].is_string() || j[key].get<std::string>().empty())
        throw std::invalid_argument(file + ": '" + key + "' must be a non-empty string");
    return j[key].get<std::string>();
}

// The fabric's keys that a material's key replaces, beyond the key itself.
const std::map<std::string, std::vector<std::string>>& replacedKeys() {
    static const std::vector<std::string> scale = {"repeat", "scale", "ends_per_cm", "ends_per_inch", "picks_per_cm",
                                                   "picks_per_inch"};
    static const std::map<std::string, std::vector<std::string>> keys = {
        {"repeat", scale},
        {"scale", scale},
        {"ends_per_cm", {"repeat", "scale", "ends_per_inch"}},
        {"ends_per_inch", {"repeat", "scale", "ends_per_cm"}},
        {"picks_per_cm", {"repeat", "scale", "picks_per_inch"}},
        {"picks_per_inch", {"repeat", "scale", "picks_per_cm"}},
        {"yarn_width", {"weft_count"}},
        {"weft_count", {"yarn_width"}},
        {"warp_width", {"warp_count"}},
        {"warp_count", {"warp_width"}},
        // A weave replaces the fabric's weave but not its draft's threads (materialFromJson()).
        {"pattern", {"tile"}},
        {"tile", {"pattern"}},
        {"wif", {"pattern", "tile"}},
    };
    return keys;
}

}  // namespace

std::string fabricDirectory() {
    if (const char* dir = std::getenv("WOVEN_FABRIC_DIR")) return dir;
    return WOVEN_FABRIC_DIR;
}

std::vector<std::string> fabricNames() {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(fabricDirectory(), ec))
        if (entry.path().extension() == ".json" && isFabricName(entry.path().stem().string()))
            names.push_back(entry.path().stem().string());
    if (ec) throw std::invalid_argument(fabricDirectory() + ": cannot list the fabric library (" + ec.message() +
                                        "; set WOVEN_FABRIC_DIR to assets/fabrics)");
    std::sort(names.begin(), names.end());
    return names;
}

Fabric readFabric(const std::string& name) {
    const std::vector<std::string> names = fabricNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        throw std::invalid_argument("'preset': \"" + name + "\" is no fabric in " + fabricDirectory() +
                                    " (the library has " + (list.empty() ? "none" : list) + ")");
    }
    Fabric f;
    f.name = name;
    f.file = (std::filesystem::path(fabricDirectory()) / (name + ".json")).string();
    nlohmann::json j;
    try {
        const std::vector<unsigned char> bytes = readRegularFile(f.file, kMaxFabricFileBytes);
        j = parseUntrustedJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    } catch (const FileReadError& e) {
        throw std::invalid_argument(e.what());
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(f.file + ": " + e.what());
    }
    if (!j.is_object()) throw std::invalid_argument(f.file + ": a fabric file must be a JSON object");
    if (requiredString(j, "name", f.file) != name)
        throw std::invalid_argument(f.file + ": 'name' is \"" + j["name"].get<std::string>() + "\", not its file's name");
    f.title = requiredString(j, "title", f.file);
    f.source = requiredString(j, "source", f.file);
    if (j.contains("note")) f.note = requiredString(j, "note", f.file);
    if (!j.contains("material") || !j["material"].is_object())
        throw std::invalid_argument(f.file + ": 'material' must be a woven material (a JSON object)");
    f.material = j["material"];
    if (f.material.contains("preset")) throw std::invalid_argument(f.file + ": 'material': a fabric cannot name a 'preset'");
    if (f.material.contains("wif") && f.material["wif"].is_string()) {
        const std::filesystem::path wif(f.material["wif"].get<std::string>());
        if (wif.is_relative()) f.material["wif"] = (std::filesystem::path(fabricDirectory()) / wif).string();
    }
    return f;
}

nlohmann::json withPreset(const nlohmann::json& material, Fabric& fabric) {
    const nlohmann::json& preset = material["preset"];
    if (!preset.is_string() || !isFabricName(preset.get<std::string>()))
        throw std::invalid_argument("'preset' = " + preset.dump() + ": need a fabric's name (woven fabrics lists them)");
    fabric = readFabric(preset.get<std::string>());
    nlohmann::json merged = fabric.material;
    // A key given replaces the preset's keys it contradicts, never another key given: a pair of
    // those (yarn_width with weft_count) is left for the checks to refuse, as without a preset.
    for (const auto& [key, value] : material.items()) {
        if (key == "preset") continue;
        if (const auto replaced = replacedKeys().find(key); replaced != replacedKeys().end())
            for (const std::string& r : replaced->second)
                if (!material.contains(r)) merged.erase(r);
        merged[key] = value;
    }
    return merged;
}

}  // namespace woven
