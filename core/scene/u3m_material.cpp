#include "u3m_material.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "file_reading.h"
#include "image_io.h"
#include "srgb.h"
#include "u3ma_archive.h"
#include "untrusted_json.h"

namespace woven {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr size_t kMaxU3mBytes = size_t(1) << 30;

// The .u3m's JSON and a way to its files, from an archive or a folder.
struct Package {
    std::string path;
    json document;
    std::map<std::string, std::vector<unsigned char>> archived;
    std::string folder;  // a .u3m's

    std::vector<unsigned char> file(const std::string& relative) const {
        if (relative.empty() || relative.front() == '/' || relative.find("..") != std::string::npos || relative.find('\\') != std::string::npos)
            throw std::invalid_argument(path + ": '" + relative + "' is not a relative path inside the material's folder");
        if (folder.empty()) {
            const auto it = archived.find(relative);
            if (it == archived.end()) throw std::invalid_argument(path + ": '" + relative + "' is not in the archive");
            return it->second;
        }
        return readRegularFile((fs::path(folder) / relative).string(), kMaxImageFileBytes);
    }
};

Package openPackage(const std::string& path) {
    Package p;
    p.path = path;
    std::string extension = fs::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    try {
        std::vector<unsigned char> bytes = readRegularFile(path, extension == ".u3ma" ? kMaxImageFileBytes : kMaxU3mBytes);
        if (extension == ".u3m") {
            p.folder = fs::path(path).parent_path().empty() ? "." : fs::path(path).parent_path().string();
            p.document = parseUntrustedJson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
            return p;
        }
        if (extension != ".u3ma") throw std::invalid_argument(path + ": a U3M file's name ends in .u3ma or .u3m");
        std::string root;
        for (ArchiveEntry& e : unpackU3ma(bytes, path, kMaxImageFileBytes)) {
            if (e.name.find('/') == std::string::npos && fs::path(e.name).extension() == ".u3m") {
                if (!root.empty()) throw std::invalid_argument(path + ": the archive holds more than one .u3m at its root");
                root = e.name;
            }
            p.archived[e.name] = std::move(e.bytes);
        }
        if (root.empty()) throw std::invalid_argument(path + ": the archive holds no .u3m at its root");
        const std::vector<unsigned char>& text = p.archived[root];
        p.document = parseUntrustedJson(std::string_view(reinterpret_cast<const char*>(text.data()), text.size()));
    } catch (const std::invalid_argument&) {
        throw;
    } catch (const std::exception& e) {  // a file that cannot be read, a damaged archive
        const std::string what = e.what();
        throw std::invalid_argument(what.rfind(path, 0) == 0 ? what : path + ": " + what);
    }
    return p;
}

// j[key], or null: a reference that outlives the call (json::value() returns a copy).
const json& member(const json& j, const char* key) {
    static const json none;
    return j.is_object() && j.contains(key) ? j[key] : none;
}

double number(const json& j, const char* key, double fallback) {
    return j.is_object() && j.contains(key) && j[key].is_number() ? j[key].get<double>() : fallback;
}

// A map's image of a texture_and_* element, or null.
const json* imageOf(const json& element) {
    if (!element.is_object() || !element.contains("texture") || !element["texture"].is_object()) return nullptr;
    const json& t = element["texture"];
    return t.contains("image") && t["image"].is_object() && t["image"].contains("path") && t["image"]["path"].is_string() ? &t["image"] : nullptr;
}

TextureImage decodeMap(const Package& p, const json& image) {
    const std::string file = image["path"].get<std::string>();
    const std::vector<unsigned char> bytes = p.file(file);
    try {
        TextureImage t = decodeTexture(bytes.data(), bytes.size(), p.path + ": " + file);
        if (t.isFloat()) throw std::invalid_argument(p.path + ": " + file + ": woven reads a U3M's 8-bit maps only");
        return t;
    } catch (const ImageError& e) {
        throw std::invalid_argument(e.what());
    }
}

// A scalar map (U3M: the mean of its channels, times factor, plus offset), clamped to [0, 1].
std::vector<float> scalarMap(const TextureImage& t, const json& element) {
    const double factor = number(element["texture"], "factor", 1.0), offset = number(element["texture"], "offset", 0.0);
    std::vector<float> v;
    v.reserve(t.bytes.size());
    for (const glm::u8vec4& b : t.bytes) v.push_back(float(std::clamp(offset + factor * (b.r + b.g + b.b) / 765.0, 0.0, 1.0)));
    return v;
}

uint8_t unorm8(float v) { return uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

U3mMaterial readU3m(const std::string& path) {
    const Package p = openPackage(path);
    const json& d = p.document;
    if (!d.is_object() || !d.contains("material") || !d["material"].is_object())
        throw std::invalid_argument(path + ": not a U3M (no \"material\" object)");
    U3mMaterial out;
    if (d.contains("custom") && d["custom"].is_object() && d["custom"].contains("woven") && d["custom"]["woven"].is_object() &&
        d["custom"]["woven"].contains("material")) {
        out.woven = d["custom"]["woven"]["material"];
        return out;
    }
    const json& m = d["material"];
    const json* face = nullptr;
    for (const char* key : {"front", "back", "side"})
        if (!face && m.contains(key) && m[key].is_object()) face = &m[key];
    if (!face) throw std::invalid_argument(path + ": the material has no front, back or side to show");
    const json& v = *face;
    Material& material = out.material;
    material.name = m.contains("name") && m["name"].is_string() ? m["name"].get<std::string>() : fs::path(path).stem().string();

    // Every map is drawn over the base colour's size (U3M gives each its own; tools tile them alike).
    const json* base = imageOf(member(v, "basecolor"));
    if (base) out.sizeMm = {number(*base, "width", 0.0), number(*base, "height", 0.0)};
    const auto add = [&](TextureImage t, bool srgb) {
        TextureRef ref;
        ref.image = int(out.textures.size());
        ref.srgb = srgb;
        out.textures.push_back(std::move(t));
        return ref;
    };
    const auto sameSize = [&](const json* image, const char* key) {
        if (!image) return false;
        const glm::dvec2 mm(number(*image, "width", 0.0), number(*image, "height", 0.0));
        if (base && glm::all(glm::lessThan(glm::abs(mm - out.sizeMm), glm::dvec2(1e-6)))) return true;
        out.warnings.push_back(path + ": the " + std::string(key) + " map is left out: its size differs from the base colour's");
        return false;
    };

    // Base colour (sRGB) with the alpha map in its alpha channel.
    const json& color = member(v, "basecolor");
    const json& constant = member(color, "constant");
    material.baseColor = glm::vec4(srgbToLinear(float(number(constant, "r", 1.0))), srgbToLinear(float(number(constant, "g", 1.0))),
                                   srgbToLinear(float(number(constant, "b", 1.0))), float(number(member(v, "alpha"), "constant", 1.0)));
    if (base) {
        if (out.sizeMm.x <= 0.0 || out.sizeMm.y <= 0.0) throw std::invalid_argument(path + ": the base colour map has no size in mm");
        TextureImage t = decodeMap(p, *base);
        const json& factor = member(color["texture"], "factor");
        material.baseColor = glm::vec4(float(number(factor, "r", 1.0)), float(number(factor, "g", 1.0)), float(number(factor, "b", 1.0)), 1.0f);
        if (member(color["texture"], "mode").is_string() && color["texture"]["mode"] != "multiply")
            out.warnings.push_back(path + ": the base colour's mode '" + color["texture"]["mode"].dump() + "' is read as multiply");
        const json& alpha = member(v, "alpha");
        if (const json* a = imageOf(alpha); a && sameSize(a, "alpha")) {
            const TextureImage at = decodeMap(p, *a);
            if (at.width == t.width && at.height == t.height) {
                const std::vector<float> values = scalarMap(at, alpha);
                for (size_t i = 0; i < t.bytes.size(); ++i) t.bytes[i].a = unorm8(values[i]);
                material.alphaMode = AlphaMode::Mask;
            } else {
                out.warnings.push_back(path + ": the alpha map is left out: its pixels differ from the base colour's");
            }
        } else {
            for (glm::u8vec4& b : t.bytes) b.a = 255;
            material.baseColor.a = float(number(alpha, "constant", 1.0));
        }
        material.baseColorTexture = add(std::move(t), true);
    }
    if (material.baseColor.a < 1.0f && material.alphaMode == AlphaMode::Opaque) material.alphaMode = AlphaMode::Blend;

    const json& normal = member(v, "normal");
    if (const json* n = imageOf(normal); n && sameSize(n, "normal")) {
        material.normalTexture = add(decodeMap(p, *n), false);
        material.normalTexture.scale = float(number(normal["texture"], "scale", 1.0));
    }
    // Roughness (G) and metalness (B) in one texture, as glTF keeps them.
    const json& roughness = member(v, "roughness"), &metalness = member(v, "metalness");
    material.roughness = float(number(roughness, "constant", 0.7));
    material.metallic = float(number(metalness, "constant", 0.0));
    if (const json* r = imageOf(roughness); r && sameSize(r, "roughness")) {
        TextureImage t = decodeMap(p, *r);
        const std::vector<float> values = scalarMap(t, roughness);
        for (size_t i = 0; i < t.bytes.size(); ++i) t.bytes[i] = glm::u8vec4(255, unorm8(values[i]), unorm8(material.metallic), 255);
        material.roughness = material.metallic = 1.0f;
        material.metallicRoughnessTexture = add(std::move(t), false);
    }
    material.ior = float(number(member(v, "ior"), "constant", 1.5));
    if (!(material.ior >= 1.0f && material.ior < 10.0f)) material.ior = 1.5f;
    material.anisotropy.strength = float(std::clamp(number(member(v, "anisotropy_value"), "constant", 0.0), 0.0, 1.0));
    material.anisotropy.rotation = float(2.0 * M_PI * number(member(v, "anisotropy_rotation"), "constant", 0.0));
    for (const char* key : {"anisotropy_value", "anisotropy_rotation", "sheen_value", "transmission", "displacement", "clearcoat_value"})
        if (imageOf(member(v, key)))
            out.warnings.push_back(path + ": its " + std::string(key) + " map is left out (woven reads the constant)");
    if (out.textures.empty()) out.sizeMm = {100.0, 100.0};  // constants alone: any size
    return out;
}

Material atRealSize(const U3mMaterial& u3m, const glm::dvec2& metresPerUv, int firstTexture) {
    Material m = u3m.material;
    // A texture spans sizeMm: uv' = uv x (metres per uv) / (metres per texture).
    const glm::dvec2 scale = metresPerUv * 1000.0 / u3m.sizeMm;
    for (TextureRef* ref : {&m.baseColorTexture, &m.normalTexture, &m.metallicRoughnessTexture}) {
        if (!*ref) continue;
        ref->image += firstTexture;
        ref->uvTransform = glm::mat3(float(scale.x), 0, 0, 0, float(scale.y), 0, 0, 0, 1);
    }
    return m;
}

}  // namespace woven
