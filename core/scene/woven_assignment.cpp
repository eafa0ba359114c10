#include "woven_assignment.h"

#include <fnmatch.h>

#include <filesystem>

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include <iostream>

#include "material_json.h"
#include "untrusted_json.h"
#include "scene_loader.h"
#include "u3m_material.h"
#include "uv_scale.h"

namespace woven {

namespace {

struct Target {
    enum class Kind { All, Material, Mesh, Node } kind = Kind::All;
    std::string pattern;
    bool glob = false;
};

Target parseTarget(const std::string& text) {
    Target t;
    if (text == "*") return t;
    const auto startsWith = [&](const char* prefix) { return text.rfind(prefix, 0) == 0; };
    if (startsWith("mesh:")) t.kind = Target::Kind::Mesh, t.pattern = text.substr(5);
    else if (startsWith("node:")) t.kind = Target::Kind::Node, t.pattern = text.substr(5);
    else if (startsWith("material:")) t.kind = Target::Kind::Material, t.pattern = text.substr(9);
    else t.kind = Target::Kind::Material, t.pattern = text;
    // A glob has an unescaped wildcard; "\\*" is a literal star.
    for (size_t i = 0; i < t.pattern.size() && !t.glob; ++i) {
        if (t.pattern[i] == '\\') ++i;
        else t.glob = t.pattern[i] == '*' || t.pattern[i] == '?' || t.pattern[i] == '[';
    }
    return t;
}

bool matches(const Target& t, const std::string& name) { return fnmatch(t.pattern.c_str(), name.c_str(), 0) == 0; }

std::string escapeGlob(const std::string& name) {
    std::string escaped;
    for (char c : name) {
        if (c == '*' || c == '?' || c == '[' || c == '\\') escaped += '\\';
        escaped += c;
    }
    return escaped;
}

// How specific `t` is for `mesh` of `material` (null: none), or -1 when it does not name it
// (the order in the header).
int specificity(const Target& t, const Mesh& mesh, const Material* material) {
    switch (t.kind) {
        case Target::Kind::All: return 0;
        case Target::Kind::Material:
            if (!material || !matches(t, material->name)) return -1;
            return t.glob ? 1 : 2;
        case Target::Kind::Mesh:
            if (!matches(t, mesh.meshName)) return -1;
            return t.glob ? 3 : 4;
        case Target::Kind::Node:
            for (size_t depth = mesh.nodePath.size(); depth-- > 0;)
                if (matches(t, mesh.nodePath[depth])) return 5 + 2 * int(depth) + (t.glob ? 0 : 1);
            return -1;
    }
    return -1;
}

// "keep_base_color" is read here, not by the model: takes it out of `layer`, nullopt where absent.
std::optional<bool> takeKeepBaseColor(nlohmann::json& layer) {
    if (!layer.is_object() || !layer.contains("keep_base_color")) return std::nullopt;
    const nlohmann::json& keep = layer["keep_base_color"];
    if (!keep.is_boolean()) throw std::invalid_argument("'keep_base_color' must be true or false");
    const bool value = keep.get<bool>();
    layer.erase("keep_base_color");
    return value;
}

// A thread count has two sides, ends and picks, each its own key: a layer that gives one side
// takes the other from the broader layers (the latest that gave it), so that the most specific
// target wins key by key for the pair too. `given` holds each side's key and value so far; a
// repeat or scale given replaces the counts, and clears them.
void layerThreadCounts(nlohmann::json& layer, nlohmann::json& given) {
    if (!layer.is_object()) return;
    if (layer.contains("repeat") || layer.contains("scale")) {
        given = nlohmann::json::object();
        return;
    }
    const std::pair<const char*, const char*> sides[] = {{"ends_per_cm", "ends_per_inch"}, {"picks_per_cm", "picks_per_inch"}};
    bool has[2] = {false, false};
    for (int s = 0; s < 2; ++s)
        for (const char* key : {sides[s].first, sides[s].second})
            if (layer.contains(key)) has[s] = true, given[s == 0 ? "ends" : "picks"] = {{key, layer[key]}};
    if (has[0] == has[1]) return;
    const char* missing = has[0] ? "picks" : "ends";
    if (given.contains(missing)) layer.update(given[missing]);
}

// Whether a layer gives the yarns colours of its own (a draft brings its threads' colours, a
// library fabric its own), which then win over a glTF material's base colour factor.
bool setsYarnColor(const nlohmann::json& layer) {
    for (const char* key : {"weft_color", "warp_color", "warp_colors", "weft_colors", "wif", "preset"})
        if (layer.contains(key)) return true;
    return false;
}

// A layer's "u3m" (u3m_material.h): woven's own file becomes its woven parameters, under the
// layer's other keys (a size of the layer's own replaces the file's thread counts); another
// tool's is returned, for the caller to put on the meshes at its real size.
std::optional<U3mMaterial> takeU3m(nlohmann::json& layer, const std::string& directory, SceneDescription& scene) {
    if (!layer.is_object() || !layer.contains("u3m")) return std::nullopt;
    if (!layer["u3m"].is_string()) throw std::invalid_argument("'u3m' must be the path of a .u3ma or .u3m file");
    const std::filesystem::path given = layer["u3m"].get<std::string>();
    const std::string path = (given.is_absolute() || directory.empty() ? given : std::filesystem::path(directory) / given).string();
    U3mMaterial u3m = readU3m(path);
    scene.inputFiles.push_back(path);
    layer.erase("u3m");
    if (!u3m.woven) {
        if (!layer.empty()) throw std::invalid_argument(path + ": another tool's U3M is a textured material, not woven: it takes no woven keys beside 'u3m'");
        return u3m;
    }
    nlohmann::json merged = *u3m.woven;
    for (const char* size : {"repeat", "scale", "ends_per_cm", "ends_per_inch", "picks_per_cm", "picks_per_inch"})
        if (layer.contains(size)) merged.erase("ends_per_cm"), merged.erase("picks_per_cm");
    for (const auto& [key, value] : layer.items()) merged[key] = value;
    layer = std::move(merged);
    return std::nullopt;
}

// A glTF material made woven keeps its surface (Material::keptSurface): the base colour factor
// becomes both yarn colours unless a layer sets one or `keep` (the layers' "keep_base_color")
// is false. A later call that turns the base colour off gives back woven's default colours where
// the factor had set them.
void keepGltfSurface(Material& material, WovenParams& params, std::optional<bool> keep, bool colorKeys, bool wasWoven) {
    KeptGltfSurface kept = material.keptSurface.value_or(KeptGltfSurface{});
    if (keep) kept.print = *keep;
    const bool fromFactor = kept.print && !colorKeys && (!wasWoven || keep || kept.colorsFromFactor);
    const WovenParams defaults;
    if (fromFactor) {
        params.weft_color = params.warp_color = glm::vec3(material.baseColor);
    } else if (kept.colorsFromFactor && !colorKeys) {
        params.weft_color = defaults.weft_color;
        params.warp_color = defaults.warp_color;
    }
    kept.colorsFromFactor = fromFactor;
    material.keptSurface = kept;
}

std::string quotedList(const std::set<std::string>& names) {
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "'" : ", '") + n + "'";
    return list.empty() ? "none" : list;
}

}  // namespace

std::string whatTargetsCanName(const SceneDescription& scene) {
    std::set<std::string> materials, meshes, nodes;
    for (const Material& m : scene.materials) materials.insert(m.name);
    for (const Mesh& m : scene.meshes) {
        if (!m.meshName.empty()) meshes.insert(m.meshName);
        nodes.insert(m.nodePath.begin(), m.nodePath.end());
    }
    return "the scene has materials " + quotedList(materials) + "; meshes " + quotedList(meshes) + "; nodes " +
           quotedList(nodes) + " (targets: NAME, material:NAME, mesh:NAME, node:NAME, globs, or \"*\")";
}

std::string literalTarget(TargetKind kind, const std::string& name) {
    switch (kind) {
        case TargetKind::Mesh: return "mesh:" + escapeGlob(name);
        case TargetKind::Node: return "node:" + escapeGlob(name);
        case TargetKind::Material: break;
    }
    // A bare name would be read as "*" or as a mesh or node target: say it is a material's.
    const bool ambiguous = name == "*" || name.rfind("mesh:", 0) == 0 || name.rfind("node:", 0) == 0 ||
                           name.rfind("material:", 0) == 0;
    return (ambiguous ? "material:" : "") + escapeGlob(name);
}

bool targetNames(const std::string& target, const Mesh& mesh, const Material* material) {
    return specificity(parseTarget(target), mesh, material) >= 0;
}

void assignWoven(SceneDescription& scene, const std::vector<WovenAssignment>& assignments) {
    const auto fail = [&](const WovenAssignment& a, const std::string& problem) {
        throw SceneError(scene.source + ": " + a.where + ": " + problem);
    };
    std::vector<Target> targets;
    for (const WovenAssignment& a : assignments) targets.push_back(parseTarget(a.target));

    // Per primitive, the assignments that name it, least specific first (stable: ties keep
    // their order). Primitives of one material with the same list form one group.
    std::map<std::pair<int, std::vector<size_t>>, std::vector<size_t>> groups;
    std::vector<bool> used(assignments.size(), false);
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        std::vector<std::pair<int, size_t>> layers;
        for (size_t a = 0; a < targets.size(); ++a) {
            const Mesh& mesh = scene.meshes[m];
            const int s = specificity(targets[a], mesh, mesh.material >= 0 ? &scene.materials[size_t(mesh.material)] : nullptr);
            if (s >= 0) layers.emplace_back(s, a), used[a] = true;
        }
        if (layers.empty()) continue;
        std::stable_sort(layers.begin(), layers.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        std::vector<size_t> order;
        for (const auto& layer : layers) order.push_back(layer.second);
        groups[{scene.meshes[m].material, order}].push_back(m);
    }
    for (size_t a = 0; a < assignments.size(); ++a)
        if (!used[a]) fail(assignments[a], "'" + assignments[a].target + "' names nothing: " + whatTargetsCanName(scene));

    // How many primitives use each material, to know when a group has all of them.
    std::map<int, size_t> users;
    for (const Mesh& mesh : scene.meshes) ++users[mesh.material];
    for (const auto& [key, meshes] : groups) {
        const auto& [materialIndex, order] = key;
        Material material = materialIndex >= 0 ? scene.materials[size_t(materialIndex)] : Material{};
        if (materialIndex < 0) material.name = "(no material)";
        const bool wasWoven = material.woven.has_value();
        WovenParams params = material.woven.value_or(WovenParams{});
        std::optional<bool> keepBaseColor;
        bool colorKeys = false;
        nlohmann::json threadCounts = nlohmann::json::object();
        std::string names;
        std::optional<Material> textured;  // another tool's U3M, which ends the layers
        for (size_t a : order) {
            std::vector<std::string> warnings;
            if (textured) fail(assignments[a], "comes after another tool's U3M, which is a textured material and cannot be made woven");
            try {
                nlohmann::json layer = assignments[a].params;
                if (std::optional<U3mMaterial> u3m = takeU3m(layer, assignments[a].directory, scene)) {
                    textured = atRealSize(*u3m, measureUvScale(scene, meshes).metresPerUv, int(scene.textures.size()));
                    scene.textures.insert(scene.textures.end(), u3m->textures.begin(), u3m->textures.end());
                    warnings = u3m->warnings;
                    textured->name = material.name;
                    textured->doubleSided = material.doubleSided;
                } else {
                    if (const auto keep = takeKeepBaseColor(layer)) keepBaseColor = keep;
                    colorKeys |= setsYarnColor(layer);
                    layerThreadCounts(layer, threadCounts);
                    const MaterialJson read = materialFromJson(layer, params, assignments[a].directory, warnings);
                    params = scaledToMeshes(read, scene, meshes, warnings);
                    if (!read.wif.empty()) material.draft = read.wif;
                    if (read.threadsPerCm) {
                        material.textile = read.textile;
                        material.textile->threadsPerCm = glm::dvec2(*read.threadsPerCm);
                    } else if (layer.contains("repeat")) {
                        material.textile.reset();  // a size of its own, no longer the cloth's real one
                    }
                }
            } catch (const std::exception& e) {  // a bad key, a draft that cannot be used, no UVs to scale by
                fail(assignments[a], e.what());
            }
            for (const std::string& w : warnings) {
                const std::string line = scene.source + ": " + assignments[a].where + ": " + w;
                if (std::find(scene.warnings.begin(), scene.warnings.end(), line) != scene.warnings.end()) continue;
                scene.warnings.push_back(line);
                std::cerr << "warning: " << line << "\n";
            }
            names += (names.empty() ? "" : ", ") + assignments[a].target;
        }
        // A material woven in its file keeps its woven colours; a primitive without a material has
        // no glTF surface to keep.
        if (textured) {
            material = std::move(*textured);
        } else {
            if (materialIndex >= 0 && (!wasWoven || material.keptSurface))
                keepGltfSurface(material, params, keepBaseColor, colorKeys, wasWoven);
            material.woven = params;
        }
        if (materialIndex >= 0 && meshes.size() == users[materialIndex]) {
            scene.materials[size_t(materialIndex)] = std::move(material);
            continue;
        }
        material.name += " [" + names + "]";
        scene.materials.push_back(std::move(material));
        for (size_t m : meshes) scene.meshes[m].material = int(scene.materials.size()) - 1;
    }
}

WovenAssignment parseWovenOption(const SceneDescription& scene, const std::string& option) {
    const size_t eq = option.find('=');
    if (eq == std::string::npos || eq == 0)
        throw SceneError(scene.source + ": --woven '" + option + "': expected TARGET=JSON, e.g. cloth='{\"ex\":100}'");
    WovenAssignment a;
    a.target = option.substr(0, eq);
    a.where = "--woven " + a.target;
    const std::string value = option.substr(eq + 1);
    const std::string extension = std::filesystem::path(value).extension().string();
    if (value.find('{') == std::string::npos && (extension == ".u3ma" || extension == ".u3m")) {
        a.params = {{"u3m", value}};  // a U3M file, as a scene file's "u3m" key gives it
        return a;
    }
    try {
        a.params = parseUntrustedJson(value);
    } catch (const std::invalid_argument& e) {
        throw SceneError(scene.source + ": " + a.where + ": " + e.what());
    }
    return a;
}

}  // namespace woven
