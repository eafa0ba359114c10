#include "gltf_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include "atomic_file.h"
#include "image_io.h"
#include "scene_camera.h"
#include "woven_params_json.h"

namespace woven {

namespace {

using json = nlohmann::json;

// The loader's rule (gltf_loader.cpp): candela and lux / 683 lm/W = W/sr and W/m^2.
constexpr float kLumensPerWatt = 683.0f;

constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t n = uint32_t(bytes[i]) << 16 | (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0U) |
                           (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0U);
        out += digits[(n >> 18) & 63];
        out += digits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }
json vec(const glm::vec4& v) { return {v.x, v.y, v.z, v.w}; }

bool isIdentity(const glm::mat3& m) { return m == glm::mat3(1.0f); }

class Writer {
public:
    Writer(const SceneDescription& scene, std::vector<std::string>& warnings) : scene_(scene), warnings_(warnings) {}

    // The document, its binary buffer still to be placed (GLB chunk or data URI).
    json document(const Camera& camera) {
        doc_["asset"] = {{"version", "2.0"}, {"generator", "woven export"}};
        json roots = json::array();
        for (int node : meshNodes()) roots.push_back(node);
        roots.push_back(cameraNode(camera));
        for (const PunctualLight& light : scene_.lights) roots.push_back(lightNode(light));
        doc_["scenes"] = json::array({{{"nodes", roots}}});
        doc_["scene"] = 0;
        if (!used_.empty()) doc_["extensionsUsed"] = std::vector<std::string>(used_.begin(), used_.end());
        if (!required_.empty()) doc_["extensionsRequired"] = std::vector<std::string>(required_.begin(), required_.end());
        return doc_;
    }
    const std::vector<unsigned char>& binary() const { return bin_; }

private:
    // --- the binary buffer -------------------------------------------------------------------

    int bufferView(const void* data, size_t size, int target) {
        while (bin_.size() % 4) bin_.push_back(0);
        json view = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", size}};
        if (target) view["target"] = target;
        const auto* bytes = static_cast<const unsigned char*>(data);
        bin_.insert(bin_.end(), bytes, bytes + size);
        doc_["bufferViews"].push_back(view);
        return int(doc_["bufferViews"].size()) - 1;
    }

    template <int N>
    int floatAccessor(const std::vector<glm::vec<N, float>>& values, const char* type, bool bounds = false,
                      int target = kArrayBuffer) {
        json a = {{"bufferView", bufferView(values.data(), values.size() * sizeof(values[0]), target)},
                  {"componentType", kFloat}, {"count", values.size()}, {"type", type}};
        if (bounds) {
            glm::vec<N, float> lo(INFINITY), hi(-INFINITY);
            for (const auto& v : values) lo = glm::min(lo, v), hi = glm::max(hi, v);
            for (int c = 0; c < N; ++c) a["min"].push_back(lo[c]), a["max"].push_back(hi[c]);
        }
        doc_["accessors"].push_back(a);
        return int(doc_["accessors"].size()) - 1;
    }

    int indexAccessor(const std::vector<glm::uvec3>& triangles, size_t vertices) {
        std::vector<uint32_t> flat;
        for (const glm::uvec3& t : triangles) flat.insert(flat.end(), {t.x, t.y, t.z});
        json a = {{"count", flat.size()}, {"type", "SCALAR"}};
        // 16 bits where they hold every index (65535 is the primitive restart value: not used).
        if (vertices < 65535) {
            const std::vector<uint16_t> narrow(flat.begin(), flat.end());
            a["bufferView"] = bufferView(narrow.data(), narrow.size() * 2, kElementArrayBuffer);
            a["componentType"] = kUnsignedShort;
        } else {
            a["bufferView"] = bufferView(flat.data(), flat.size() * 4, kElementArrayBuffer);
            a["componentType"] = kUnsignedInt;
        }
        doc_["accessors"].push_back(a);
        return int(doc_["accessors"].size()) - 1;
    }

    // --- meshes and their nodes --------------------------------------------------------------

    // One node per node path the loader recorded (the hierarchy of names, identity transforms:
    // the meshes are in world space), holding one glTF mesh per (node, mesh name) with a
    // primitive per woven Mesh; a node of an instanced mesh places its copies by
    // EXT_mesh_gpu_instancing. Returns the root nodes.
    std::vector<int> meshNodes() {
        std::map<std::vector<std::string>, int> nodeOf;
        std::vector<int> roots;
        std::map<std::tuple<int, std::string, const void*>, int> meshOf;
        for (const Mesh& mesh : scene_.meshes) {
            std::vector<std::string> path = mesh.nodePath.empty() ? std::vector<std::string>{mesh.name} : mesh.nodePath;
            int parent = -1;
            for (size_t depth = 1; depth <= path.size(); ++depth) {
                const std::vector<std::string> prefix(path.begin(), path.begin() + long(depth));
                auto it = nodeOf.find(prefix);
                if (it == nodeOf.end()) {
                    doc_["nodes"].push_back({{"name", prefix.back()}});
                    const int index = int(doc_["nodes"].size()) - 1;
                    it = nodeOf.emplace(prefix, index).first;
                    if (parent < 0) roots.push_back(index);
                    else doc_["nodes"][size_t(parent)]["children"].push_back(index);
                }
                parent = it->second;
            }
            const auto key = std::make_tuple(parent, mesh.meshName, static_cast<const void*>(mesh.instances.get()));
            auto m = meshOf.find(key);
            if (m == meshOf.end()) {
                json gltfMesh = {{"primitives", json::array()}};
                if (!mesh.meshName.empty()) gltfMesh["name"] = mesh.meshName;
                doc_["meshes"].push_back(gltfMesh);
                m = meshOf.emplace(key, int(doc_["meshes"].size()) - 1).first;
                doc_["nodes"][size_t(parent)]["mesh"] = m->second;
                if (mesh.instances)
                    doc_["nodes"][size_t(parent)]["extensions"]["EXT_mesh_gpu_instancing"] = instancing(*mesh.instances);
            }
            doc_["meshes"][size_t(m->second)]["primitives"].push_back(primitive(mesh));
        }
        return roots;
    }

    // EXT_mesh_gpu_instancing's TRANSLATION, ROTATION and SCALE of each instance's matrix. A matrix
    // that is no TRS (a shear, from a non-uniform scale above a rotation in the file's nodes) has
    // no such form: it is written as its nearest TRS, and said once.
    json instancing(const std::vector<glm::mat4>& matrices) {
        std::vector<glm::vec3> t(matrices.size()), s(matrices.size());
        std::vector<glm::vec4> r(matrices.size());
        bool sheared = false;
        for (size_t i = 0; i < matrices.size(); ++i) {
            const glm::mat4& m = matrices[i];
            const glm::mat3 linear(m);
            glm::vec3 scale(glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2]));
            if (glm::determinant(linear) < 0.0f) scale.x = -scale.x;  // a mirror as a negative scale
            const glm::mat3 rotation(linear[0] / scale.x, linear[1] / scale.y, linear[2] / scale.z);
            const glm::quat q = glm::normalize(glm::quat_cast(rotation));
            const glm::mat3 back = glm::mat3_cast(q) * glm::mat3(glm::scale(glm::mat4(1.0f), scale));
            for (int c = 0; c < 3; ++c) sheared |= glm::length(back[c] - linear[c]) > 1e-4f * glm::length(linear[c]);
            t[i] = glm::vec3(m[3]);
            r[i] = glm::vec4(q.x, q.y, q.z, q.w);
            s[i] = scale;
        }
        if (sheared && !warnedShear_) {
            warnedShear_ = true;
            warnings_.push_back("EXT_mesh_gpu_instancing: instances sheared by their nodes' transforms are written as "
                                "their nearest translation, rotation and scale");
        }
        used_.insert("EXT_mesh_gpu_instancing");
        // Required: a viewer without it would draw one copy at the node, and the rest nowhere.
        required_.insert("EXT_mesh_gpu_instancing");
        return {{"attributes", {{"TRANSLATION", floatAccessor(t, "VEC3", false, 0)}, {"ROTATION", floatAccessor(r, "VEC4", false, 0)},
                                {"SCALE", floatAccessor(s, "VEC3", false, 0)}}}};
    }

    json primitive(const Mesh& mesh) {
        json attributes = {{"POSITION", floatAccessor(mesh.positions, "VEC3", true)}};
        if (!mesh.normals.empty()) attributes["NORMAL"] = floatAccessor(mesh.normals, "VEC3");
        if (!mesh.tangents.empty() && !mesh.normals.empty() && usesTangents(mesh.material))
            attributes["TANGENT"] = floatAccessor(mesh.tangents, "VEC4");
        if (!mesh.uvs.empty()) attributes["TEXCOORD_0"] = floatAccessor(mesh.uvs, "VEC2");
        if (!mesh.uvs1.empty()) attributes["TEXCOORD_1"] = floatAccessor(mesh.uvs1, "VEC2");
        if (!mesh.colors.empty()) attributes["COLOR_0"] = floatAccessor(mesh.colors, "VEC4");
        return {{"attributes", attributes}, {"indices", indexAccessor(mesh.triangles, mesh.positions.size())},
                {"material", material(mesh.material)}, {"mode", 4}};
    }

    // --- materials and textures ---------------------------------------------------------------

    // Whether the material needs the mesh's tangents: a normal map, anisotropy, or a woven
    // material (its yarns run along them).
    bool usesTangents(int index) const {
        if (index < 0) return false;
        const Material& m = scene_.materials[size_t(index)];
        return m.normalTexture || m.clearcoat.normalTexture || m.anisotropy.strength > 0.0f || m.woven;
    }

    // The glTF material of scene material `index`; -1, woven's default material, gets one too,
    // since glTF's default (white metal) would look otherwise.
    int material(int index) {
        if (const auto it = materialOf_.find(index); it != materialOf_.end()) return it->second;
        Material fallback;
        fallback.name = "default";
        doc_["materials"].push_back(materialJson(index >= 0 ? scene_.materials[size_t(index)] : fallback));
        return materialOf_[index] = int(doc_["materials"].size()) - 1;
    }

    void extension(json& object, const char* name, json value) {
        object["extensions"][name] = std::move(value);
        used_.insert(name);
    }

    json materialJson(const Material& m) {
        json out = {{"name", m.name}};
        json pbr = {{"baseColorFactor", vec(m.baseColor)}, {"metallicFactor", m.metallic}, {"roughnessFactor", m.roughness}};
        texture(pbr, "baseColorTexture", m.baseColorTexture);
        texture(pbr, "metallicRoughnessTexture", m.metallicRoughnessTexture);
        out["pbrMetallicRoughness"] = pbr;
        texture(out, "normalTexture", m.normalTexture, "scale");
        texture(out, "occlusionTexture", m.occlusionTexture, "strength");
        texture(out, "emissiveTexture", m.emissiveTexture);
        // emissiveFactor is at most 1 in glTF; what is above goes to the strength.
        const float strongest = std::max({m.emission.r, m.emission.g, m.emission.b});
        if (strongest > 0.0f) {
            out["emissiveFactor"] = vec(strongest > 1.0f ? m.emission / strongest : m.emission);
            if (strongest > 1.0f) extension(out, "KHR_materials_emissive_strength", {{"emissiveStrength", strongest}});
        }
        if (m.alphaMode == AlphaMode::Mask) out["alphaMode"] = "MASK", out["alphaCutoff"] = m.alphaCutoff;
        if (m.alphaMode == AlphaMode::Blend) out["alphaMode"] = "BLEND";
        out["doubleSided"] = m.doubleSided;
        if (m.unlit) extension(out, "KHR_materials_unlit", json::object());
        if (m.ior != 1.5f) extension(out, "KHR_materials_ior", {{"ior", m.ior}});
        if (m.specular != 1.0f || m.specularColor != glm::vec3(1.0f) || m.specularTexture || m.specularColorTexture) {
            json e = {{"specularFactor", m.specular}, {"specularColorFactor", vec(m.specularColor)}};
            texture(e, "specularTexture", m.specularTexture);
            texture(e, "specularColorTexture", m.specularColorTexture);
            extension(out, "KHR_materials_specular", e);
        }
        if (m.sheen.color != glm::vec3(0.0f)) {
            json e = {{"sheenColorFactor", vec(m.sheen.color)}, {"sheenRoughnessFactor", m.sheen.roughness}};
            texture(e, "sheenColorTexture", m.sheen.colorTexture);
            texture(e, "sheenRoughnessTexture", m.sheen.roughnessTexture);
            extension(out, "KHR_materials_sheen", e);
        }
        if (m.anisotropy.strength > 0.0f) {
            json e = {{"anisotropyStrength", m.anisotropy.strength}, {"anisotropyRotation", m.anisotropy.rotation}};
            texture(e, "anisotropyTexture", m.anisotropy.texture);
            extension(out, "KHR_materials_anisotropy", e);
        }
        if (m.clearcoat.factor > 0.0f) {
            json e = {{"clearcoatFactor", m.clearcoat.factor}, {"clearcoatRoughnessFactor", m.clearcoat.roughness}};
            texture(e, "clearcoatTexture", m.clearcoat.texture);
            texture(e, "clearcoatRoughnessTexture", m.clearcoat.roughnessTexture);
            texture(e, "clearcoatNormalTexture", m.clearcoat.normalTexture, "scale");
            extension(out, "KHR_materials_clearcoat", e);
        }
        const TransmissionParams& t = m.transmission;
        if (t.factor > 0.0f) {
            json e = {{"transmissionFactor", t.factor}};
            texture(e, "transmissionTexture", t.texture);
            extension(out, "KHR_materials_transmission", e);
        }
        if (t.thickness > 0.0f || std::isfinite(t.attenuationDistance) || t.attenuationColor != glm::vec3(1.0f)) {
            json e = {{"thicknessFactor", t.thickness}, {"attenuationColor", vec(t.attenuationColor)}};
            if (std::isfinite(t.attenuationDistance)) e["attenuationDistance"] = t.attenuationDistance;
            texture(e, "thicknessTexture", t.thicknessTexture);
            extension(out, "KHR_materials_volume", e);
        }
        if (const DiffuseTransmissionParams& d = m.diffuseTransmission; d.factor > 0.0f) {
            json e = {{"diffuseTransmissionFactor", d.factor}, {"diffuseTransmissionColorFactor", vec(d.color)}};
            texture(e, "diffuseTransmissionTexture", d.texture);
            texture(e, "diffuseTransmissionColorTexture", d.colorTexture);
            extension(out, "KHR_materials_diffuse_transmission", e);
        }
        if (const IridescenceParams& i = m.iridescence; i.factor > 0.0f) {
            json e = {{"iridescenceFactor", i.factor}, {"iridescenceIor", i.ior},
                      {"iridescenceThicknessMinimum", i.thicknessMin}, {"iridescenceThicknessMaximum", i.thicknessMax}};
            texture(e, "iridescenceTexture", i.texture);
            texture(e, "iridescenceThicknessTexture", i.thicknessTexture);
            extension(out, "KHR_materials_iridescence", e);
        }
        if (m.woven) extension(out, "WOVEN_fabric", paramsToJson(*m.woven));
        return out;
    }

    // A textureInfo at object[key] for `ref` (nothing when it has no texture); `scaleKey` names
    // normalTexture's scale or occlusionTexture's strength.
    void texture(json& object, const char* key, const TextureRef& ref, const char* scaleKey = nullptr) {
        if (!ref) return;
        json info = {{"index", textureIndex(ref)}};
        if (ref.texCoord) info["texCoord"] = ref.texCoord;
        if (scaleKey && ref.scale != 1.0f) info[scaleKey] = ref.scale;
        if (!isIdentity(ref.uvTransform)) {
            // uv' = T R S uv (the loader's order): S and R from the 2 x 2 part, T its last column.
            const glm::mat3& m = ref.uvTransform;
            const float rotation = std::atan2(-m[0][1], m[0][0]);
            const float c = std::cos(rotation), s = std::sin(rotation);
            const glm::vec2 scale(m[0][0] * c - m[0][1] * s, m[1][0] * s + m[1][1] * c);
            json transform = {{"offset", {m[2][0], m[2][1]}}, {"scale", {scale.x, scale.y}}};
            if (rotation != 0.0f) transform["rotation"] = rotation;
            extension(info, "KHR_texture_transform", transform);
            // Without it the texture would be stretched over the whole mesh: a viewer that does not
            // scale textures must refuse the file rather than show it so.
            required_.insert("KHR_texture_transform");
        }
        object[key] = info;
    }

    int textureIndex(const TextureRef& ref) {
        const auto sampler = std::make_tuple(int(ref.wrapS), int(ref.wrapT), ref.nearest, ref.mipmaps);
        const auto key = std::make_pair(ref.image, sampler);
        if (const auto it = textureOf_.find(key); it != textureOf_.end()) return it->second;
        doc_["textures"].push_back({{"source", image(ref.image)}, {"sampler", samplerIndex(ref)}});
        return textureOf_[key] = int(doc_["textures"].size()) - 1;
    }

    int samplerIndex(const TextureRef& ref) {
        const auto wrap = [](TextureWrap w) {
            return w == TextureWrap::ClampToEdge ? 33071 : w == TextureWrap::MirroredRepeat ? 33648 : 10497;
        };
        const json sampler = {{"magFilter", ref.nearest ? 9728 : 9729},
                              {"minFilter", ref.mipmaps ? 9987 : (ref.nearest ? 9728 : 9729)},
                              {"wrapS", wrap(ref.wrapS)}, {"wrapT", wrap(ref.wrapT)}};
        for (size_t i = 0; i < doc_["samplers"].size(); ++i)
            if (doc_["samplers"][i] == sampler) return int(i);
        doc_["samplers"].push_back(sampler);
        return int(doc_["samplers"].size()) - 1;
    }

    int image(int index) {
        if (const auto it = imageOf_.find(index); it != imageOf_.end()) return it->second;
        TextureImage texture = scene_.textures.at(size_t(index));
        if (texture.isFloat()) {
            // 16-bit and float sources keep their stored values in [0, 1] (or above): the 8-bit
            // PNG holds them rounded, in the same encoding.
            warnings_.push_back("texture '" + texture.name + "' has more than 8 bits a channel; written with 8");
            for (const glm::vec4& v : texture.floats)
                texture.bytes.push_back(glm::u8vec4(glm::round(glm::clamp(v, 0.0f, 1.0f) * 255.0f)));
            texture.floats.clear();
        }
        const std::vector<unsigned char> png = encodeTexturePng(texture);
        doc_["images"].push_back({{"bufferView", bufferView(png.data(), png.size(), 0)}, {"mimeType", "image/png"}});
        return imageOf_[index] = int(doc_["images"].size()) - 1;
    }

    // --- camera and lights --------------------------------------------------------------------

    // A node at `position`, turned by `rotation` (glTF: a camera or light looks down its -z axis).
    json placedNode(const glm::vec3& position, const glm::quat& rotation) {
        const glm::quat q = glm::normalize(rotation);
        return {{"translation", vec(position)}, {"rotation", {q.x, q.y, q.z, q.w}}};
    }

    int cameraNode(const Camera& camera) {
        const SceneBox box = sceneBounds(scene_);
        json perspective = {{"yfov", camera.yfov}, {"znear", std::max(1e-4f, 1e-3f * box.radius())}};
        float aspect = camera.aspect;
        if (!(aspect > 0.0f) && scene_.render.width > 0 && scene_.render.height > 0)
            aspect = float(scene_.render.width) / float(scene_.render.height);
        if (aspect > 0.0f) perspective["aspectRatio"] = aspect;
        doc_["cameras"].push_back({{"type", "perspective"}, {"perspective", perspective}});
        // Rotation and position only: the loader drops scale from a camera's node.
        glm::mat3 axes(camera.cameraToWorld);
        for (int i = 0; i < 3; ++i) axes[i] = glm::normalize(axes[i]);
        json node = placedNode(glm::vec3(camera.cameraToWorld[3]), glm::quat_cast(axes));
        node["name"] = "Camera";
        node["camera"] = int(doc_["cameras"].size()) - 1;
        doc_["nodes"].push_back(node);
        return int(doc_["nodes"].size()) - 1;
    }

    int lightNode(const PunctualLight& light) {
        static const char* const types[] = {"point", "spot", "directional"};
        // woven's intensity is a colour: its largest channel becomes the intensity.
        const float strongest = std::max({light.intensity.r, light.intensity.g, light.intensity.b});
        json l = {{"type", types[int(light.type)]},
                  {"color", vec(strongest > 0.0f ? light.intensity / strongest : glm::vec3(1.0f))},
                  {"intensity", strongest * kLumensPerWatt}};
        if (light.type == PunctualLight::Type::Spot)
            l["spot"] = {{"innerConeAngle", light.innerConeAngle}, {"outerConeAngle", light.outerConeAngle}};
        json& lights = doc_["extensions"]["KHR_lights_punctual"]["lights"];
        lights.push_back(l);
        used_.insert("KHR_lights_punctual");
        const glm::quat rotation = glm::rotation(glm::vec3(0.0f, 0.0f, -1.0f), glm::normalize(light.direction));
        json node = placedNode(light.position, rotation);
        node["name"] = std::string(types[int(light.type)]) + " light " + std::to_string(lights.size() - 1);
        node["extensions"]["KHR_lights_punctual"] = {{"light", lights.size() - 1}};
        doc_["nodes"].push_back(node);
        return int(doc_["nodes"].size()) - 1;
    }

    const SceneDescription& scene_;
    std::vector<std::string>& warnings_;
    bool warnedShear_ = false;
    json doc_ = json::object();
    std::vector<unsigned char> bin_;
    std::set<std::string> used_, required_;
    std::map<int, int> materialOf_, imageOf_;
    std::map<std::pair<int, std::tuple<int, int, bool, bool>>, int> textureOf_;
};

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw GltfExportError("cannot create the file");
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out.flush()) throw GltfExportError("cannot write the file (disk full?)");
}

std::string glb(const json& document, const std::vector<unsigned char>& binary) {
    std::string text = document.dump();
    while (text.size() % 4) text += ' ';
    std::string bin(binary.begin(), binary.end());
    while (bin.size() % 4) bin += '\0';
    const auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const uint32_t length = uint32_t(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size()));
    std::string out = "glTF" + u32(2) + u32(length) + u32(uint32_t(text.size())) + "JSON" + text;
    if (!bin.empty()) out += u32(uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
    return out;
}

}  // namespace

void writeGltf(const std::string& path, const SceneDescription& scene, const Camera& camera, std::vector<std::string>& warnings) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    const bool binary = extension == ".glb";
    if (!binary && extension != ".gltf") throw GltfExportError(path + ": the file name must end in .glb or .gltf");
    Writer writer(scene, warnings);
    json document = writer.document(camera);
    std::string bytes;
    if (!writer.binary().empty()) {
        document["buffers"] = json::array({{{"byteLength", writer.binary().size()}}});
        if (!binary) document["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(writer.binary());
    }
    bytes = binary ? glb(document, writer.binary()) : document.dump(1) + "\n";
    try {
        writeFileAtomically(path, [&](const std::string& tmp) { writeBytes(tmp, bytes); });
    } catch (const FileWriteError& e) {
        throw GltfExportError(e.what());
    }
}

}  // namespace woven
