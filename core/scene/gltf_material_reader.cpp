#include "gltf_material_reader.h"

#include <cmath>
#include <filesystem>

#include "image_io.h"
#include "light_limits.h"
#include "scene_loader.h"
#include "short_number.h"
#include "woven_params_json.h"

namespace woven {

namespace {

using json = nlohmann::json;

// Values this close outside a range are float noise from exporters (1.0000001): clamped.
constexpr float kRangeSlack = 1e-4f;

const json& member(const json& object, const char* key) {
    static const json none;
    if (!object.is_object()) return none;
    const auto it = object.find(key);
    return it == object.end() ? none : *it;
}

TextureWrap wrapMode(int mode) {
    switch (mode) {
        case 33071: return TextureWrap::ClampToEdge;
        case 33648: return TextureWrap::MirroredRepeat;
        default: return TextureWrap::Repeat;
    }
}

// KHR_texture_transform: uv' = T R S uv, with the extension's rotation sense (counter-clockwise
// in the image as displayed, v down).
glm::mat3 textureTransform(glm::vec2 offset, float rotation, glm::vec2 scale) {
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 t(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::mat3 r(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::mat3 sc(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    return t * r * sc;
}

}  // namespace

GltfMaterialReader::GltfMaterialReader(std::string path, const nlohmann::json& document, const EncodedImages& images,
                                       AbsentImages absent, bool strict, std::function<void(const std::string&)> warn)
    : path_(std::move(path)), document_(document), images_(images), absent_(std::move(absent)), strict_(strict),
      warn_(std::move(warn)) {}

void GltfMaterialReader::fail(const std::string& where, const std::string& problem) const {
    throw SceneError(path_ + ": " + where + ": " + problem);
}

float GltfMaterialReader::number(const json& object, const char* key, float fallback, float lo, float hi,
                                 const std::string& where) const {
    const json& v = member(object, key);
    if (v.is_null()) return fallback;
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(where + "." + key, "must be a finite number");
    const double x = v.get<double>();
    if (x < lo - kRangeSlack || x > hi + kRangeSlack) {
        const std::string range = std::isinf(hi) ? ">= " + shortNumber(lo) : "in [" + shortNumber(lo) + ", " + shortNumber(hi) + "]";
        fail(where + "." + key, "is " + shortNumber(x) + ", must be " + range);
    }
    return std::clamp(float(x), lo, hi);
}

glm::vec4 GltfMaterialReader::unitColor(const json& object, const char* key, int count, const std::string& where) const {
    const json& factor = member(object, key);
    glm::vec4 c(1.0f);
    if (factor.is_null()) return c;
    if (!factor.is_array() || factor.size() != size_t(count))
        fail(where + "." + key, "must be an array of " + std::to_string(count) + " numbers");
    for (int i = 0; i < count; ++i) {
        const json& v = factor[size_t(i)];
        if (!v.is_number() || !(v.get<double>() >= -kRangeSlack && v.get<double>() <= 1.0 + kRangeSlack))
            fail(where + "." + key, "must hold numbers in [0, 1]");
        c[i] = std::clamp(v.get<float>(), 0.0f, 1.0f);
    }
    return c;
}

glm::vec3 GltfMaterialReader::color3(const json& object, const char* key, glm::vec3 fallback, const std::string& where) const {
    const json& v = member(object, key);
    if (v.is_null()) return fallback;
    if (!v.is_array() || v.size() < 3) fail(where + "." + key, "must be an array of 3 numbers");
    glm::vec3 c;
    for (int i = 0; i < 3; ++i) {
        if (!v[size_t(i)].is_number() || !std::isfinite(v[size_t(i)].get<double>()) || v[size_t(i)].get<double>() < 0.0)
            fail(where + "." + key, "must hold finite numbers >= 0");
        c[i] = v[size_t(i)].get<float>();
    }
    return c;
}

void GltfMaterialReader::read(SceneDescription& scene) {
    const json& materials = member(document_, "materials");
    if (materials.is_null()) return;
    if (!materials.is_array()) fail("materials", "must be an array");
    for (size_t i = 0; i < materials.size(); ++i) {
        const json& name = member(materials[i], "name");
        const std::string materialName = name.is_string() && !name.get<std::string>().empty()
                                             ? name.get<std::string>() : "material" + std::to_string(i);
        scene.materials.push_back(readMaterial(materials[i], materialName, scene));
    }
}

Material GltfMaterialReader::readMaterial(const json& source, const std::string& name, SceneDescription& scene) {
    const std::string where = "material '" + name + "'";
    if (!source.is_object()) fail(where, "must be a JSON object");
    // glTF's defaults, which differ from woven's default material.
    Material m;
    m.name = name;
    m.baseColor = glm::vec4(1.0f);
    m.metallic = 1.0f;
    m.roughness = 1.0f;
    m.doubleSided = false;

    const json& pbr = member(source, "pbrMetallicRoughness");
    if (!pbr.is_null()) {
        const std::string at = where + ".pbrMetallicRoughness";
        m.baseColor = unitColor(pbr, "baseColorFactor", 4, at);
        m.metallic = number(pbr, "metallicFactor", 1.0f, 0.0f, 1.0f, at);
        m.roughness = number(pbr, "roughnessFactor", 1.0f, 0.0f, 1.0f, at);
        m.baseColorTexture = readTexture(member(pbr, "baseColorTexture"), true, at + ".baseColorTexture", scene);
        m.metallicRoughnessTexture = readTexture(member(pbr, "metallicRoughnessTexture"), false, at + ".metallicRoughnessTexture", scene);
    }
    m.normalTexture = readTexture(member(source, "normalTexture"), false, where + ".normalTexture", scene);
    m.occlusionTexture = readTexture(member(source, "occlusionTexture"), false, where + ".occlusionTexture", scene);
    m.emissiveTexture = readTexture(member(source, "emissiveTexture"), true, where + ".emissiveTexture", scene);
    // Values above glTF's [0, 1] are accepted: some exporters write them instead of emissive_strength.
    m.emission = color3(source, "emissiveFactor", glm::vec3(0.0f), where);

    const json& alphaMode = member(source, "alphaMode");
    if (!alphaMode.is_null()) {
        const std::string mode = alphaMode.is_string() ? alphaMode.get<std::string>() : "";
        if (mode == "OPAQUE") m.alphaMode = AlphaMode::Opaque;
        else if (mode == "MASK") m.alphaMode = AlphaMode::Mask;
        else if (mode == "BLEND") m.alphaMode = AlphaMode::Blend;
        else fail(where + ".alphaMode", "must be \"OPAQUE\", \"MASK\" or \"BLEND\"");
    }
    m.alphaCutoff = number(source, "alphaCutoff", 0.5f, 0.0f, std::numeric_limits<float>::infinity(), where);
    const json& doubleSided = member(source, "doubleSided");
    if (!doubleSided.is_null()) {
        if (!doubleSided.is_boolean()) fail(where + ".doubleSided", "must be true or false");
        m.doubleSided = doubleSided.get<bool>();
    }

    readExtensions(member(source, "extensions"), m, name, scene);
    // An emitter is a light: held to the lights' limit (light_limits.h), factor and strength together.
    if (const std::string problem = lightValueProblem(m.emission); !problem.empty())
        fail(where, "its emission (emissiveFactor x KHR_materials_emissive_strength) " + problem);

    const json& extras = member(source, "extras");
    const json* woven = nullptr;
    std::string wovenWhere;
    if (const json& e = member(member(source, "extensions"), "WOVEN_fabric"); !e.is_null()) woven = &e, wovenWhere = "WOVEN_fabric";
    else if (const json& x = member(extras, "woven"); !x.is_null()) woven = &x, wovenWhere = "extras.woven";
    if (woven) {
        try {
            m.woven = paramsFromJson(*woven);
        } catch (const std::exception& e) {
            fail(where + ", " + wovenWhere, e.what());
        }
    }
    return m;
}

void GltfMaterialReader::readExtensions(const json& extensions, Material& m, const std::string& name,
                                        SceneDescription& scene) {
    if (extensions.is_null()) return;
    const std::string where = "material '" + name + "'.extensions";
    if (!extensions.is_object()) fail(where, "must be a JSON object");

    if (const json& e = member(extensions, "KHR_materials_emissive_strength"); !e.is_null())
        m.emission *= number(e, "emissiveStrength", 1.0f, 0.0f, kMaxLightValue, where + ".KHR_materials_emissive_strength");

    if (const json& e = member(extensions, "KHR_materials_ior"); !e.is_null()) {
        m.ior = number(e, "ior", 1.5f, 0.0f, std::numeric_limits<float>::infinity(), where + ".KHR_materials_ior");
        if (m.ior > 0.0f && m.ior < 1.0f) fail(where + ".KHR_materials_ior.ior", "must be 0 or at least 1");
    }
    if (const json& e = member(extensions, "KHR_materials_specular"); !e.is_null()) {
        const std::string at = where + ".KHR_materials_specular";
        m.specular = number(e, "specularFactor", 1.0f, 0.0f, 1.0f, at);
        m.specularTexture = readTexture(member(e, "specularTexture"), false, at + ".specularTexture", scene);
        m.specularColor = color3(e, "specularColorFactor", glm::vec3(1.0f), at);
        m.specularColorTexture = readTexture(member(e, "specularColorTexture"), true, at + ".specularColorTexture", scene);
    }
    if (const json& e = member(extensions, "KHR_materials_sheen"); !e.is_null()) {
        const std::string at = where + ".KHR_materials_sheen";
        m.sheen.color = color3(e, "sheenColorFactor", glm::vec3(0.0f), at);
        m.sheen.colorTexture = readTexture(member(e, "sheenColorTexture"), true, at + ".sheenColorTexture", scene);
        m.sheen.roughness = number(e, "sheenRoughnessFactor", 0.0f, 0.0f, 1.0f, at);
        m.sheen.roughnessTexture = readTexture(member(e, "sheenRoughnessTexture"), false, at + ".sheenRoughnessTexture", scene);
    }
    if (const json& e = member(extensions, "KHR_materials_anisotropy"); !e.is_null()) {
        const std::string at = where + ".KHR_materials_anisotropy";
        m.anisotropy.strength = number(e, "anisotropyStrength", 0.0f, 0.0f, 1.0f, at);
        m.anisotropy.rotation = number(e, "anisotropyRotation", 0.0f, -1e6f, 1e6f, at);
        m.anisotropy.texture = readTexture(member(e, "anisotropyTexture"), false, at + ".anisotropyTexture", scene);
    }
    if (const json& e = member(extensions, "KHR_materials_clearcoat"); !e.is_null()) {
        const std::string at = where + ".KHR_materials_clearcoat";
        m.clearcoat.factor = number(e, "clearcoatFactor", 0.0f, 0.0f, 1.0f, at);
        m.clearcoat.texture = readTexture(member(e, "clearcoatTexture"), false, at + ".clearcoatTexture", scene);
        m.clearcoat.roughness = number(e, "clearcoatRoughnessFactor", 0.0f, 0.0f, 1.0f, at);
        m.clearcoat.roughnessTexture = readTexture(member(e, "clearcoatRoughnessTexture"), false, at + ".clearcoatRoughnessTexture", scene);
        m.clearcoat.normalTexture = readTexture(member(e, "clearcoatNormalTexture"), false, at + ".clearcoatNormalTexture", scene);
    }
    if (const json& e = member(extensions, "KHR_materials_transmission"); !e.is_null()) {
        const std::string at = where + ".KHR_materials_transmission";
        m.transmission.factor = number(e, "transmissionFactor", 0.0f, 0.0f, 1.0f, at);
        m.transmission.texture = readTexture(member(e, "transmissionTexture"), false, at + ".transmissionTexture", scene);
    }
    if (const json& e = member(extensions, "KHR_materials_diffuse_transmission"); !e.is_null()) {
        const std::string at = where + ".KHR_materials_diffuse_transmission";
        DiffuseTransmissionParams& d = m.diffuseTransmission;
        d.factor = number(e, "diffuseTransmissionFactor", 0.0f, 0.0f, 1.0f, at);
        d.texture = readTexture(member(e, "diffuseTransmissionTexture"), false, at + ".diffuseTransmissionTexture", scene);
        d.color = glm::vec3(unitColor(e, "diffuseTransmissionColorFactor", 3, at));
        d.colorTexture = readTexture(member(e, "diffuseTransmissionColorTexture"), true, at + ".diffuseTransmissionColorTexture", scene);
    }
    if (const json& e = member(extensions, "KHR_materials_volume"); !e.is_null()) {
        const std::string at = where + ".KHR_materials_volume";
        m.transmission.thickness = number(e, "thicknessFactor", 0.0f, 0.0f, std::numeric_limits<float>::infinity(), at);
        m.transmission.thicknessTexture = readTexture(member(e, "thicknessTexture"), false, at + ".thicknessTexture", scene);
        m.transmission.attenuationColor = color3(e, "attenuationColor", glm::vec3(1.0f), at);
        const json& distance = member(e, "attenuationDistance");
        if (!distance.is_null()) {
            if (!distance.is_number() || !(distance.get<double>() > 0.0)) fail(at + ".attenuationDistance", "must be a number > 0");
            m.transmission.attenuationDistance = distance.get<float>();
        }
    }
    if (const json& e = member(extensions, "KHR_materials_iridescence"); !e.is_null()) {
        const std::string at = where + ".KHR_materials_iridescence";
        const float infinity = std::numeric_limits<float>::infinity();
        m.iridescence.factor = number(e, "iridescenceFactor", 0.0f, 0.0f, 1.0f, at);
        m.iridescence.texture = readTexture(member(e, "iridescenceTexture"), false, at + ".iridescenceTexture", scene);
        m.iridescence.ior = number(e, "iridescenceIor", 1.3f, 1.0f, infinity, at);
        m.iridescence.thicknessMin = number(e, "iridescenceThicknessMinimum", 100.0f, 0.0f, infinity, at);
        m.iridescence.thicknessMax = number(e, "iridescenceThicknessMaximum", 400.0f, 0.0f, infinity, at);
        m.iridescence.thicknessTexture =
            readTexture(member(e, "iridescenceThicknessTexture"), false, at + ".iridescenceThicknessTexture", scene);
    }
    // Read for its value's sake: woven renders one IOR for every wavelength (a warning says so).
    if (const json& e = member(extensions, "KHR_materials_dispersion"); !e.is_null())
        number(e, "dispersion", 0.0f, 0.0f, std::numeric_limits<float>::infinity(), where + ".KHR_materials_dispersion");
    if (const json& e = member(extensions, "KHR_materials_pbrSpecularGlossiness"); !e.is_null())
        readSpecularGlossiness(e, m, where + ".KHR_materials_pbrSpecularGlossiness", scene);
    if (!member(extensions, "KHR_materials_unlit").is_null()) m.unlit = true;
}

// As glTF-Transform's metalRough() converts it: diffuse becomes the base colour of a dielectric
// whose F0 is the specular colour (an infinite IOR under KHR_materials_specular's colour) and
// whose roughness is 1 - glossiness, from a texture whose G is 1 - glossiness x A where the
// specular-glossiness texture is given. The specular-glossiness model's diffuse, scaled by
// 1 - max(specular), becomes woven's, scaled by 1 - F per channel: an approximation.
void GltfMaterialReader::readSpecularGlossiness(const json& e, Material& m, const std::string& at, SceneDescription& scene) {
    m.baseColor = unitColor(e, "diffuseFactor", 4, at);
    m.baseColorTexture = readTexture(member(e, "diffuseTexture"), true, at + ".diffuseTexture", scene);
    m.metallic = 0.0f;
    m.ior = 0.0f;
    m.specular = 1.0f;
    m.specularTexture = {};
    m.specularColor = glm::min(color3(e, "specularFactor", glm::vec3(1.0f), at), glm::vec3(1.0f));
    const float glossiness = number(e, "glossinessFactor", 1.0f, 0.0f, 1.0f, at);
    const TextureRef texture = readTexture(member(e, "specularGlossinessTexture"), true, at + ".specularGlossinessTexture", scene);
    m.specularColorTexture = texture;
    m.roughness = texture ? 1.0f : 1.0f - glossiness;
    m.metallicRoughnessTexture = {};
    if (!texture) return;
    const TextureImage& source = scene.textures[size_t(texture.image)];
    TextureImage rough{source.name + " (roughness from glossiness)", source.width, source.height, {}, {}};
    if (source.isFloat()) {
        for (const glm::vec4& t : source.floats) rough.floats.emplace_back(0.0f, 1.0f - glossiness * t.a, 0.0f, 1.0f);
    } else {
        for (const glm::u8vec4& t : source.bytes)
            rough.bytes.emplace_back(0, uint8_t(std::lround(255.0f - glossiness * float(t.a))), 0, 255);
    }
    scene.textures.push_back(std::move(rough));
    m.metallicRoughnessTexture = texture;
    m.metallicRoughnessTexture.image = int(scene.textures.size()) - 1;
    m.metallicRoughnessTexture.srgb = false;
}

TextureRef GltfMaterialReader::readTexture(const json& info, bool srgb, const std::string& where, SceneDescription& scene) {
    TextureRef ref;
    if (info.is_null()) return ref;
    if (!info.is_object()) fail(where, "must be a JSON object (a textureInfo)");
    const json& index = member(info, "index");
    if (!index.is_number_integer() || index.get<long long>() < 0) fail(where + ".index", "must be an integer >= 0");
    const json& textures = member(document_, "textures");
    if (!textures.is_array() || index.get<size_t>() >= textures.size())
        fail(where, "texture " + std::to_string(index.get<long long>()) + " does not exist");
    const json& texture = textures[index.get<size_t>()];
    // EXT_texture_webp names the WebP image; "source", if any, is the fallback for viewers without it.
    const json& webp = member(member(member(texture, "extensions"), "EXT_texture_webp"), "source");
    const json& source = webp.is_null() ? member(texture, "source") : webp;
    if (source.is_null()) {
        // Only an extension's image (KTX2, DDS) and no PNG/JPEG fallback.
        warn_(where + ": texture " + std::to_string(index.get<long long>()) +
              " has no PNG, JPEG or WebP image woven can read; the texture is ignored");
        return ref;
    }
    if (!source.is_number_integer() || source.get<long long>() < 0) fail(where, "texture source must be an integer >= 0");
    ref.image = imageTexture(source.get<int>(), where, scene);
    ref.srgb = srgb;

    ref.texCoord = int(number(info, "texCoord", 0.0f, 0.0f, 1e6f, where));
    ref.scale = number(info, member(info, "strength").is_null() ? "scale" : "strength", 1.0f,
                       -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity(), where);
    if (const json& t = member(member(info, "extensions"), "KHR_texture_transform"); !t.is_null()) {
        const std::string at = where + ".extensions.KHR_texture_transform";
        glm::vec2 offset(0.0f), scale(1.0f);
        if (const json& o = member(t, "offset"); !o.is_null()) {
            if (!o.is_array() || o.size() != 2 || !o[0].is_number() || !o[1].is_number()) fail(at + ".offset", "must be 2 numbers");
            offset = {o[0].get<float>(), o[1].get<float>()};
        }
        if (const json& s = member(t, "scale"); !s.is_null()) {
            if (!s.is_array() || s.size() != 2 || !s[0].is_number() || !s[1].is_number()) fail(at + ".scale", "must be 2 numbers");
            scale = {s[0].get<float>(), s[1].get<float>()};
        }
        const float rotation = number(t, "rotation", 0.0f, -1e6f, 1e6f, at);
        ref.uvTransform = textureTransform(offset, rotation, scale);
        if (!member(t, "texCoord").is_null()) ref.texCoord = int(number(t, "texCoord", 0.0f, 0.0f, 1e6f, at));
    }
    if (ref.texCoord > 1) {
        warn_(where + ": uses TEXCOORD_" + std::to_string(ref.texCoord) + ", which woven does not read; TEXCOORD_0 is used");
        ref.texCoord = 0;
    }

    if (const json& sampler = member(texture, "sampler"); !sampler.is_null()) {
        const json& samplers = member(document_, "samplers");
        if (!sampler.is_number_integer() || !samplers.is_array() || sampler.get<long long>() < 0 ||
            sampler.get<size_t>() >= samplers.size())
            fail(where, "sampler " + sampler.dump() + " does not exist");
        const json& s = samplers[sampler.get<size_t>()];
        const auto mode = [&](const char* key, int fallback) {
            const json& v = member(s, key);
            return v.is_number_integer() ? v.get<int>() : fallback;
        };
        ref.wrapS = wrapMode(mode("wrapS", 10497));
        ref.wrapT = wrapMode(mode("wrapT", 10497));
        ref.nearest = mode("magFilter", 9729) == 9728;
        const int minFilter = mode("minFilter", 9987);
        ref.mipmaps = minFilter != 9728 && minFilter != 9729;
    }
    return ref;
}

int GltfMaterialReader::imageTexture(int image, const std::string& where, SceneDescription& scene) {
    if (const auto it = textureOfImage_.find(image); it != textureOfImage_.end()) return it->second;
    const json& images = member(document_, "images");
    if (!images.is_array() || size_t(image) >= images.size()) fail(where, "image " + std::to_string(image) + " does not exist");
    const json& uri = member(images[size_t(image)], "uri");
    const bool external = uri.is_string() && uri.get<std::string>().rfind("data:", 0) != 0;
    const std::string label = external ? "image '" + uri.get<std::string>() + "'" : "image " + std::to_string(image);
    const auto bytes = images_.find(image);
    if (bytes == images_.end()) {
        const std::string dir = std::filesystem::path(path_).parent_path().string();
        const std::string file = "'" + (uri.is_string() ? uri.get<std::string>() : label) + "'";
        const std::string folder = " (looked in '" + (dir.empty() ? "." : dir) + "')";
        if (!absent_.count(image)) fail(where, "cannot read texture file " + file + folder);
        if (strict_) fail(where, "texture file " + file + " does not exist" + folder);
        // No texture is the neutral placeholder of every use: the factor alone where a texture
        // multiplies it (white), the geometry's normal for a normal map (flat), the tangent at full
        // strength for anisotropy. Later uses of the image are dropped without another warning.
        warn_(where + ": texture file " + file + " does not exist" + folder +
              "; drawn without it (--strict makes this an error)");
        return textureOfImage_[image] = -1;
    }
    try {
        scene.textures.push_back(decodeTexture(bytes->second.data(), bytes->second.size(), label));
    } catch (const ImageError& e) {
        fail(where, e.what());
    }
    return textureOfImage_[image] = int(scene.textures.size()) - 1;
}

}  // namespace woven
