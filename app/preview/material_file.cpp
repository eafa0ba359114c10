#include "material_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "atomic_file.h"
#include "file_reading.h"
#include "untrusted_json.h"
#include "draft_material.h"
#include "woven_params_json.h"

namespace woven {

namespace {

constexpr size_t kMaxMaterialFileBytes = size_t(64) << 20;

nlohmann::json readJson(const std::string& path) {
    try {
        const std::vector<unsigned char> bytes = readRegularFile(path, kMaxMaterialFileBytes);
        return parseUntrustedJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    } catch (const FileReadError& e) {
        throw std::runtime_error(e.what());
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

void saveMaterialJson(const std::string& path, const std::string& materialName, const nlohmann::json& material,
                      const std::string& gltf) {
    nlohmann::json file;
    if (std::filesystem::exists(path)) {
        file = readJson(path);
        if (!file.is_object() || !file.contains("gltf"))
            throw std::runtime_error(path + ": not a woven scene file (no \"gltf\" key); not overwriting it");
        file["materials"][materialName] = material;
    } else if (!gltf.empty()) {
        file = {{"gltf", gltf}, {"materials", {{materialName, material}}}};
    } else {
        file = material;
    }
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp);
        out << file.dump(2) << "\n";
        if (!out) throw std::runtime_error(path + ": write failed");
    });
}

}  // namespace

void saveMaterial(const std::string& path, const std::string& materialName, const WovenParams& params,
                  const std::string& gltf) {
    saveMaterialJson(path, materialName, paramsToJson(params), gltf);
}

std::string saveMaterialWithDraft(const std::string& path, const std::string& materialName, const WovenParams& params,
                                  const std::string& gltf, DraftEditor& draft) {
    const std::filesystem::path wif = std::filesystem::path(path).replace_extension(".wif");
    nlohmann::json material = paramsToJson(params);
    for (const std::string& field : fieldsSetByDraft(draft.draft())) material.erase(field);
    material["wif"] = wif.filename().string();  // beside the material file
    draft.save(wif.string());
    saveMaterialJson(path, materialName, material, gltf);
    return wif.string();
}

MaterialJson loadMaterial(const std::string& path, const std::string& materialName, const WovenParams& base,
                          std::vector<std::string>& warnings) {
    const nlohmann::json file = readJson(path);
    const std::string directory = std::filesystem::path(path).parent_path().string();
    try {
        if (!file.is_object() || !file.contains("materials")) return materialFromJson(file, base, directory, warnings);
        const nlohmann::json& materials = file.at("materials");
        MaterialJson m;
        m.params = base;
        for (const char* key : {"*", materialName.c_str()}) {
            if (!materials.contains(key)) continue;
            MaterialJson next = materialFromJson(materials.at(key), m.params, directory, warnings);
            if (next.wif.empty()) next.wif = m.wif;  // a named entry refines "*"'s draft
            if (!next.threadsPerCm) next.threadsPerCm = m.threadsPerCm;
            m = next;
        }
        return m;
    } catch (const std::exception& e) {  // a bad key, or a draft (whose message names its file)
        throw std::runtime_error(path + ": " + e.what());
    }
}

}  // namespace woven
