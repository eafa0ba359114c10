#include "u3m_export.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "atomic_file.h"
#include "final_preview.h"
#include "frame_io.h"
#include "image_io.h"
#include "lobe_fit.h"
#include "srgb.h"
#include "u3m_physics.h"
#include "u3ma_archive.h"
#include "uv_scale.h"
#include "weave_pattern.h"
#include "woven_params_json.h"

namespace woven {

namespace fs = std::filesystem;

namespace {

// The scene's woven material that the export is of, by name or as the only one a mesh uses.
int chooseMaterial(const SceneDescription& scene, const std::string& name) {
    std::vector<int> woven;
    for (const Mesh& mesh : scene.meshes)
        if (mesh.material >= 0 && scene.materials[size_t(mesh.material)].woven &&
            std::find(woven.begin(), woven.end(), mesh.material) == woven.end())
            woven.push_back(mesh.material);
    std::string names;
    for (int m : woven) names += (names.empty() ? "'" : ", '") + scene.materials[size_t(m)].name + "'";
    if (woven.empty())
        throw U3mError(scene.source + ": no part of the scene is woven, so there is no fabric to export (make parts woven with "
                                      "--woven TARGET=JSON or a scene file's \"materials\")");
    if (name.empty()) {
        if (woven.size() > 1) throw U3mError(scene.source + ": a U3M holds one fabric and the scene has " + std::to_string(woven.size()) +
                                             " woven materials (" + names + "): choose one with --material NAME");
        return woven.front();
    }
    for (int m : woven)
        if (scene.materials[size_t(m)].name == name) return m;
    throw U3mError(scene.source + ": --material '" + name + "' is no woven material of the scene; its woven materials: " + names);
}

}  // namespace

TextileKeys textileOf(const Material& m) {
    return m.textile.value_or(TextileKeys{std::nullopt, std::nullopt, std::nullopt, fibres().front().density, ""});
}

FabricMeasures measureSceneMaterial(const SceneDescription& scene, int material) {
    const Material& m = scene.materials[size_t(material)];
    const TextileKeys textile = textileOf(m);
    glm::dvec2 threadsPerCm(0.0);
    if (textile.threadsPerCm) {
        threadsPerCm = *textile.threadsPerCm;
    } else {
        std::vector<size_t> meshes;
        for (size_t i = 0; i < scene.meshes.size(); ++i)
            if (scene.meshes[i].material == material) meshes.push_back(i);
        try {
            threadsPerCm = glm::dvec2(m.woven->repeat) / (100.0 * worldLengthPerUv(scene, meshes));
        } catch (const std::invalid_argument& e) {
            throw U3mError(scene.source + ": material '" + m.name + "': its real size is unknown (" + e.what() +
                           "): give its thread counts (ends_per_cm and picks_per_cm)");
        }
    }
    if (!(threadsPerCm.x > 0.0 && threadsPerCm.y > 0.0 && std::isfinite(threadsPerCm.x) && std::isfinite(threadsPerCm.y)))
        throw U3mError(scene.source + ": material '" + m.name + "': its real size is unknown: give its thread counts");
    return measureFabric(*m.woven, threadsPerCm, textile.warpTex, textile.weftTex, textile.fibreDensity);
}

namespace {

// One channel of a map as a grey PNG (R = G = B, opaque), which U3M's scalar maps take, and the
// channel's mean, the constant that stands for the map.
struct GreyMap {
    TextureImage image;
    double mean = 0.0;
};
GreyMap greyMap(const TextureImage& from, const std::function<float(glm::u8vec4)>& value) {
    GreyMap grey;
    grey.image.width = from.width, grey.image.height = from.height;
    grey.image.bytes.reserve(from.bytes.size());
    double sum = 0.0;
    for (const glm::u8vec4& t : from.bytes) {
        const float v = std::clamp(value(t), 0.0f, 1.0f);
        sum += v;
        const auto b = uint8_t(std::lround(v * 255.0f));
        grey.image.bytes.emplace_back(b, b, b, 255);
    }
    grey.mean = from.bytes.empty() ? 0.0 : sum / double(from.bytes.size());
    return grey;
}

float unit(uint8_t v) { return float(v) / 255.0f; }
float signedUnit(uint8_t v) { return 2.0f * unit(v) - 1.0f; }

// The files of one face and its `visualisation`, the maps over `mm` each.
struct FaceWriter {
    std::string folder;  // "NAME_textures/"
    glm::dvec2 mm;
    std::vector<ArchiveEntry>& files;

    nlohmann::json image(const std::string& file, const TextureImage& t) {
        files.push_back({folder + file, encodeTexturePng(t)});
        return {{"path", folder + file},
                {"width", mm.x},
                {"height", mm.y},
                {"dpi", {{"x", t.width / (mm.x / 25.4)}, {"y", t.height / (mm.y / 25.4)}}},
                {"repeat", {{"mode", "normal"}, {"rotation", 0.0}}}};
    }
    nlohmann::json scalar(const std::string& file, const GreyMap& grey, double factor = 1.0) {
        return {{"constant", grey.mean * factor}, {"texture", {{"factor", factor}, {"offset", 0.0}, {"image", image(file, grey.image)}}}};
    }

    nlohmann::json face(const std::string& side, const BakedMaterial& b) {
        const Material& m = b.material;
        const std::vector<TextureImage>& maps = b.textures;
        const TextureImage& base = maps[BakedMaterial::kBaseColor];
        // Base colour: sRGB as baked; the constant is its mean taken in linear light.
        glm::dvec3 linear(0.0);
        for (const glm::u8vec4& t : base.bytes) linear += glm::dvec3(srgbToLinear(unit(t.r)), srgbToLinear(unit(t.g)), srgbToLinear(unit(t.b)));
        linear /= double(std::max<size_t>(1, base.bytes.size()));
        TextureImage opaque = base;
        for (glm::u8vec4& t : opaque.bytes) t.a = 255;
        nlohmann::json v;
        v["shader"] = "principled";
        v["basecolor"] = {{"constant", {{"r", linearToSrgb(float(linear.r))}, {"g", linearToSrgb(float(linear.g))}, {"b", linearToSrgb(float(linear.b))}}},
                          {"texture", {{"mode", "multiply"}, {"factor", {{"r", 1.0}, {"g", 1.0}, {"b", 1.0}}}, {"image", image(side + "_basecolor.png", opaque)}}}};
        v["alpha"] = scalar(side + "_alpha.png", greyMap(base, [](glm::u8vec4 t) { return unit(t.a); }));
        v["normal"] = {{"constant", {{"x", 0.0}, {"y", 0.0}, {"z", 1.0}}},
                       {"texture", {{"scale", 1.0}, {"image", image(side + "_normal.png", maps[BakedMaterial::kNormal])}}}};
        v["roughness"] = scalar(side + "_roughness.png",
                                greyMap(maps[BakedMaterial::kMetallicRoughness], [](glm::u8vec4 t) { return unit(t.g); }));
        v["metalness"] = {{"constant", 0.0}, {"texture", nullptr}};
        if (m.anisotropy.texture) {
            const TextureImage& a = maps[BakedMaterial::kAnisotropy];
            v["anisotropy_value"] = scalar(side + "_anisotropy_value.png", greyMap(a, [](glm::u8vec4 t) { return unit(t.b); }));
            // glTF's direction (x along the tangent, y along the bitangent, as the normal map's)
            // as U3M's rotation, a fraction of a turn; an axis, so half a turn apart is the same.
            const auto turn = [](glm::u8vec4 t) {
                const float r = std::atan2(signedUnit(t.g), signedUnit(t.r)) / float(2.0 * M_PI);
                return r < 0.0f ? r + 1.0f : r;
            };
            v["anisotropy_rotation"] = scalar(side + "_anisotropy_rotation.png", greyMap(a, turn));
        } else {
            v["anisotropy_value"] = {{"constant", 0.0}, {"texture", nullptr}};
            v["anisotropy_rotation"] = {{"constant", 0.0}, {"texture", nullptr}};
        }
        // The dielectric reflection at normal incidence, on U3M's scale of 0 to 8 %.
        const double f0 = std::pow((m.ior - 1.0) / (m.ior + 1.0), 2.0) * m.specular;
        v["specular_value"] = {{"constant", f0 / 0.08}, {"texture", nullptr}};
        v["specular_tint"] = {{"constant", 0.0}, {"texture", nullptr}};
        v["ior"] = {{"constant", m.ior}, {"texture", nullptr}};
        v["sheen_value"] = {{"constant", std::max({m.sheen.color.r, m.sheen.color.g, m.sheen.color.b})}, {"texture", nullptr}};
        v["sheen_tint"] = {{"constant", 0.0}, {"texture", nullptr}};
        if (m.diffuseTransmission.colorTexture) {
            v["transmission"] = scalar(side + "_transmission.png",
                                       greyMap(maps[BakedMaterial::kDiffuseTransmission],
                                               [](glm::u8vec4 t) {
                                                   return float(luminance(glm::vec3(srgbToLinear(unit(t.r)), srgbToLinear(unit(t.g)), srgbToLinear(unit(t.b)))));
                                               }),
                                       m.diffuseTransmission.factor);
        } else {
            v["transmission"] = {{"constant", 0.0}, {"texture", nullptr}};
        }
        for (const char* key : {"clearcoat_value", "clearcoat_roughness", "displacement", "subsurface_radius", "subsurface_value"})
            v[key] = {{"constant", 0.0}, {"texture", nullptr}};
        v["clearcoat_normal"] = {{"constant", {{"x", 0.0}, {"y", 0.0}, {"z", 1.0}}}, {"texture", nullptr}};
        v["subsurface_color"] = {{"constant", {{"r", 0.0}, {"g", 0.0}, {"b", 0.0}}}, {"texture", nullptr}};
        v["preview"] = nullptr;
        return v;
    }
};

std::string uuid4() {
    std::random_device device;
    std::mt19937_64 random((uint64_t(device()) << 32) ^ device());
    const uint64_t hi = (random() & ~uint64_t(0xf000)) | 0x4000, lo = (random() & ~(uint64_t(3) << 62)) | (uint64_t(2) << 62);
    char s[40];
    std::snprintf(s, sizeof s, "%08x-%04x-%04x-%04x-%012llx", unsigned(hi >> 32), unsigned((hi >> 16) & 0xffff), unsigned(hi & 0xffff),
                  unsigned(lo >> 48), (unsigned long long)(lo & 0xffffffffffffULL));
    return s;
}

std::string isoTime(std::time_t t) {
    std::tm u{};
    gmtime_r(&t, &u);
    char s[32];
    std::strftime(s, sizeof s, "%Y-%m-%dT%H:%M:%SZ", &u);
    return s;
}

// A file name of the output's stem that U3M's path rules take: [0-9A-Za-z._-], not ending in '.'.
std::string safeStem(const std::string& path) {
    std::string s;
    for (char c : fs::path(path).stem().string()) s += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    return s.empty() ? "fabric" : s;
}

// The woven parameters as custom.woven keeps them: the material's JSON at its real thread count
// (not the mesh's repeat) with its yarn counts' widths and its fibre.
nlohmann::json wovenSection(const Material& m, const glm::dvec2& threadsPerCm) {
    nlohmann::json j = paramsToJson(*m.woven);
    j.erase("repeat");
    j["ends_per_cm"] = threadsPerCm.x;
    j["picks_per_cm"] = threadsPerCm.y;
    if (m.textile && !m.textile->fibre.empty()) j["fibre"] = m.textile->fibre;
    return j;
}

void writeFile(const std::string& path, const std::vector<unsigned char>& bytes) {
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream f(tmp, std::ios::binary);
        f.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        if (!f) throw FileWriteError(tmp + ": could not be written");
    });
}

void checkOutput(const std::string& path) {
    try {
        checkWritable(path);  // and so its folder, where the .u3m's textures go
    } catch (const FileWriteError& e) {
        throw U3mError(e.what());
    }
}

}  // namespace

WovenParams backFace(const WovenParams& front) {
    WovenParams back = front;
    const WeavePattern reversed = WeavePattern::fromParams(front).reversed();
    std::istringstream rows(reversed.draw(reversed.width(), reversed.height()));
    back.tile.clear();
    for (std::string row; std::getline(rows, row);) back.tile.push_back(row);
    return back;
}

U3mExport exportU3m(const SceneDescription& scene, const std::string& path, const U3mOptions& options) {
    const std::string extension = lowerExtension(path);
    if (extension != ".u3ma" && extension != ".u3m") throw U3mError(path + ": a U3M file's name ends in .u3ma (the archive) or .u3m (a file and its textures' folder)");
    const bool archive = extension == ".u3ma";
    const int index = chooseMaterial(scene, options.material);
    const Material& material = scene.materials[size_t(index)];
    const WovenParams& params = *material.woven;
    U3mExport out;
    out.material = material.name;
    out.measures = measureSceneMaterial(scene, index);
    const glm::dvec2 threadsPerCm = out.measures.threadsPerCm;
    checkOutput(path);  // also refuses a folder by that name
    BakedMaterial front, back;
    try {
        front = bakeWoven(params, options.bake);
        back = bakeWoven(backFace(params), options.bake);
    } catch (const std::invalid_argument& e) {
        throw U3mError(scene.source + ": material '" + material.name + "': " + e.what());
    }
    out.notes = front.notes;
    out.mapMm = glm::dvec2(front.threads) * double(options.bake.repeats) * 10.0 / threadsPerCm;

    const std::string stem = safeStem(path);
    std::vector<ArchiveEntry> files;
    FaceWriter faces{stem + "_textures/", out.mapMm, files};
    nlohmann::json frontJson = faces.face("front", front), backJson = faces.face("back", back);
    if (options.previewSize > 0) {
        const TextureImage preview = renderFinalPreview(scene, options.previewSize, options.previewSpp);
        const std::string file = faces.folder + "preview.png";
        files.push_back({file, encodeTexturePng(preview)});
        // A render has no size on the cloth; the preview claims 10 cm across, its dpi to match.
        const double mm = 100.0;
        frontJson["preview"] = {{"path", file}, {"width", mm}, {"height", mm * preview.height / preview.width},
                                {"dpi", {{"x", preview.width / (mm / 25.4)}, {"y", preview.width / (mm / 25.4)}}}};
    }
    const std::time_t now = std::time(nullptr);
    out.document = {
        {"schema", "1.1"},
        {"material",
         {{"id", uuid4()},
          {"name", material.name.empty() ? stem : material.name},
          {"description", "a woven fabric exported by woven: " + describe(out.measures)},
          {"created", isoTime(now)},
          {"modified", isoTime(now)},
          {"front", frontJson},
          {"back", backJson},
          {"side", nullptr},
          {"physics", u3mPhysics(params, out.measures, textileOf(material))},
          {"metadata", nullptr}}},
        {"custom", {{"woven", {{"version", 1}, {"material", wovenSection(material, threadsPerCm)}}}}},
    };
    const std::string text = out.document.dump(2);
    ArchiveEntry u3m{stem + ".u3m", std::vector<unsigned char>(text.begin(), text.end())};
    try {
        if (archive) {
            files.insert(files.begin(), u3m);
            writeFile(path, packU3ma(files, now));
        } else {
            const fs::path folder = fs::path(path).parent_path();
            fs::create_directories(folder / faces.folder);
            files.push_back({fs::path(path).filename().string(), u3m.bytes});  // the .u3m last: a finished file set
            for (const ArchiveEntry& e : files) writeFile((folder / e.name).string(), e.bytes);
        }
    } catch (const std::exception& e) {
        throw U3mError(path + ": " + e.what());
    }
    return out;
}

}  // namespace woven
