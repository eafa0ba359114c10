#include "material_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "atomic_file.h"
#include "woven_params_json.h"

namespace woven {

namespace {

nlohmann::json readJson(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error(path + ": not valid JSON (" + e.what() + ")");
    }
}

}  // namespace

void saveMaterial(const std::string& path, const std::string& materialName, const WovenParams& params,
                  const std::string& gltf) {
    nlohmann::json file;
    if (std::filesystem::exists(path)) {
        file = readJson(path);
        if (!file.is_object() || !file.contains("gltf"))
            throw std::runtime_error(path + ": not a woven scene file (no \"gltf\" key); not overwriting it");
        file["materials"][materialName] = paramsToJson(params);
    } else if (!gltf.empty()) {
        file = {{"gltf", gltf}, {"materials", {{materialName, paramsToJson(params)}}}};
    } else {
        file = paramsToJson(params);
    }
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp);
        out << file.dump(2) << "\n";
        if (!out) throw std::runtime_error(path + ": write failed");
    });
}

WovenParams loadMaterial(const std::string& path, const std::string& materialName, const WovenParams& base) {
    const nlohmann::json file = readJson(path);
    try {
        if (!file.is_object() || !file.contains("materials")) return paramsFromJson(file, base);
        const nlohmann::json& materials = file.at("materials");
        WovenParams p = base;
        if (materials.contains("*")) p = paramsFromJson(materials.at("*"), p);
        if (materials.contains(materialName)) p = paramsFromJson(materials.at(materialName), p);
        return p;
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

}  // namespace woven
