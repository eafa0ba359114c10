#include "gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "frame.h"
#include "gltf_accessor.h"
#include "image_io.h"
#include "mesh_attributes.h"
#include "scene_loader.h"
#include "woven_params_json.h"

namespace woven {

namespace {

// Extensions whose content we read, or whose absence of support changes nothing visible.
const std::set<std::string> kSupportedExtensions = {
    "KHR_mesh_quantization", "KHR_materials_emissive_strength", "KHR_lights_punctual", "WOVEN_fabric",
};
// Mesh compression we do not decode: named so the message can say what to do.
const std::set<std::string> kCompressionExtensions = {
    "KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_meshopt_compression",
};

// tinygltf hands every image's encoded bytes to this callback; decoding waits until we know
// how the image is used (sRGB colour or linear data) and whether it is used at all.
using EncodedImages = std::map<int, std::vector<unsigned char>>;
bool keepEncodedImage(tinygltf::Image*, const int index, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
    static_cast<EncodedImages*>(user)->operator[](index).assign(bytes, bytes + size);
    return true;
}

glm::mat4 localMatrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        float m[16];
        for (int i = 0; i < 16; ++i) m[i] = float(node.matrix[i]);
        return glm::make_mat4(m);  // both column-major
    }
    glm::mat4 t(1.0f), r(1.0f), s(1.0f);
    if (node.translation.size() == 3)
        t[3] = glm::vec4(float(node.translation[0]), float(node.translation[1]), float(node.translation[2]), 1.0f);
    if (node.rotation.size() == 4)
        r = glm::mat4_cast(glm::normalize(glm::quat(float(node.rotation[3]), float(node.rotation[0]),
                                                    float(node.rotation[1]), float(node.rotation[2]))));
    if (node.scale.size() == 3)
        s = glm::scale(glm::mat4(1.0f), glm::vec3(float(node.scale[0]), float(node.scale[1]), float(node.scale[2])));
    return t * r * s;
}

glm::vec3 color3(const std::vector<double>& v, glm::vec3 fallback) {
    return v.size() >= 3 ? glm::vec3(float(v[0]), float(v[1]), float(v[2])) : fallback;
}

std::string nameOr(const std::string& name, const char* kind, int index) {
    return name.empty() ? kind + std::to_string(index) : name;
}

bool allFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

class GltfLoader {
public:
    explicit GltfLoader(std::string path) : path_(std::move(path)) {}

    SceneDescription load() {
        readModel();
        checkExtensions();
        scene_.source = path_;
        loadMaterials();
        for (int root : rootNodes()) visit(root, glm::mat4(1.0f), 0);
        return std::move(scene_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw SceneError(path_ + ": " + problem); }

    void warn(const std::string& message) {
        scene_.warnings.push_back(message);
        std::cerr << "warning: " << path_ << ": " << message << "\n";
    }

    // The JSON part of the file (the first chunk of a .glb), or null when it cannot be parsed.
    nlohmann::json jsonPart() const {
        std::ifstream in(path_, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (bytes.size() >= 20 && bytes.compare(0, 4, "glTF") == 0) {
            uint32_t length = 0;
            std::memcpy(&length, bytes.data() + 12, 4);
            bytes = bytes.substr(20, std::min<size_t>(length, bytes.size() - 20));
        }
        return nlohmann::json::parse(bytes, nullptr, false);
    }

    void readModel() {
        if (!std::filesystem::is_regular_file(path_)) fail("no such file");
        // Compressed files fail inside tinygltf with a confusing buffer error: name the cause first.
        const nlohmann::json document = jsonPart();
        if (document.is_object() && document.contains("extensionsRequired") && document["extensionsRequired"].is_array())
            for (const auto& name : document["extensionsRequired"])
                if (name.is_string() && kCompressionExtensions.count(name.get<std::string>()))
                    failCompressed(name.get<std::string>());
        tinygltf::TinyGLTF reader;
        reader.SetImageLoader(keepEncodedImage, &encodedImages_);
        reader.SetStoreOriginalJSONForExtrasAndExtensions(true);
        std::string err, warn;
        const bool binary = isBinaryGltf();
        const bool ok = binary ? reader.LoadBinaryFromFile(&model_, &err, &warn, path_)
                               : reader.LoadASCIIFromFile(&model_, &err, &warn, path_);
        if (!ok) {
            while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
            fail(std::string("cannot read ") + (binary ? "glTF binary" : "glTF") + ": " +
                 (err.empty() ? "unknown error" : err));
        }
    }

    bool isBinaryGltf() const {
        std::ifstream in(path_, std::ios::binary);
        char magic[4] = {};
        in.read(magic, 4);
        return in.gcount() == 4 && std::string(magic, 4) == "glTF";
    }

    [[noreturn]] void failCompressed(const std::string& extension) const {
        fail("uses " + extension + " mesh compression, which woven does not decode; save the file without mesh compression");
    }

    void checkExtensions() {
        for (const std::string& name : model_.extensionsRequired) {
            if (kSupportedExtensions.count(name)) continue;
            if (kCompressionExtensions.count(name)) failCompressed(name);
            fail("requires the extension " + name + ", which woven does not support");
        }
        for (const std::string& name : model_.extensionsUsed)
            if (!kSupportedExtensions.count(name) && !kCompressionExtensions.count(name))
                warn("ignores the optional extension " + name);
    }

    std::vector<int> rootNodes() const {
        const int sceneIndex = model_.defaultScene >= 0 ? model_.defaultScene : (model_.scenes.empty() ? -1 : 0);
        if (sceneIndex >= int(model_.scenes.size())) fail("default scene " + std::to_string(sceneIndex) + " does not exist");
        if (sceneIndex >= 0) return model_.scenes[sceneIndex].nodes;
        std::vector<bool> isChild(model_.nodes.size(), false);
        for (const tinygltf::Node& node : model_.nodes)
            for (int child : node.children)
                if (child >= 0 && size_t(child) < isChild.size()) isChild[child] = true;
        std::vector<int> roots;
        for (size_t i = 0; i < isChild.size(); ++i)
            if (!isChild[i]) roots.push_back(int(i));
        return roots;
    }

    // --- materials and textures -------------------------------------------------------------

    void loadMaterials() {
        for (size_t m = 0; m < model_.materials.size(); ++m) {
            const tinygltf::Material& source = model_.materials[m];
            Material material;
            material.name = nameOr(source.name, "material", int(m));
            const auto& pbr = source.pbrMetallicRoughness;
            material.baseColor = color3(pbr.baseColorFactor, glm::vec3(1.0f));
            material.roughness = float(pbr.roughnessFactor);
            material.metallic = float(pbr.metallicFactor);
            material.doubleSided = source.doubleSided;
            if (pbr.baseColorTexture.index >= 0)
                material.baseColorTexture = texture(pbr.baseColorTexture.index, material.name + " baseColorTexture");

            const nlohmann::json extensions = parseJson(source.extensions_json_string, material.name);
            const nlohmann::json extras = parseJson(source.extras_json_string, material.name);
            float strength = 1.0f;
            if (extensions.contains("KHR_materials_emissive_strength")) {
                const auto& e = extensions["KHR_materials_emissive_strength"];
                if (e.contains("emissiveStrength")) {
                    if (!e["emissiveStrength"].is_number() || e["emissiveStrength"].get<double>() < 0.0)
                        fail("material '" + material.name + "': emissiveStrength must be a number >= 0");
                    strength = e["emissiveStrength"].get<float>();
                }
            }
            material.emission = color3(source.emissiveFactor, glm::vec3(0.0f)) * strength;
            if (source.emissiveTexture.index >= 0 && material.emission != glm::vec3(0.0f)) {
                const Image& image = scene_.textures[texture(source.emissiveTexture.index, material.name + " emissiveTexture")];
                glm::dvec3 sum(0.0);
                for (const glm::vec3& p : image.pixels) sum += glm::dvec3(p);
                material.emission *= glm::vec3(sum / double(std::max<size_t>(image.pixels.size(), 1)));
                warn("material '" + material.name + "': emissive texture replaced by its average colour");
            }

            const nlohmann::json* woven = nullptr;
            std::string where;
            if (extensions.contains("WOVEN_fabric")) woven = &extensions["WOVEN_fabric"], where = "WOVEN_fabric";
            else if (extras.is_object() && extras.contains("woven")) woven = &extras["woven"], where = "extras.woven";
            if (woven) {
                try {
                    material.woven = paramsFromJson(*woven);
                } catch (const std::exception& e) {
                    fail("material '" + material.name + "', " + where + ": " + e.what());
                }
            }
            scene_.materials.push_back(std::move(material));
        }
    }

    nlohmann::json parseJson(const std::string& text, const std::string& materialName) const {
        if (text.empty()) return nlohmann::json::object();
        try {
            return nlohmann::json::parse(text);
        } catch (const std::exception& e) {
            fail("material '" + materialName + "': " + e.what());
        }
    }

    // Index into scene_.textures of glTF texture `index`, decoded as sRGB colour.
    int texture(int index, const std::string& use) {
        if (index < 0 || size_t(index) >= model_.textures.size())
            fail(use + ": texture " + std::to_string(index) + " does not exist");
        const int source = model_.textures[index].source;
        if (source < 0 || size_t(source) >= model_.images.size())
            fail(use + ": texture " + std::to_string(index) + " has no image woven can read");
        if (auto it = textureOfImage_.find(source); it != textureOfImage_.end()) return it->second;
        const tinygltf::Image& image = model_.images[source];
        const std::string label = image.uri.empty() ? "image " + std::to_string(source) : "image '" + image.uri + "'";
        const auto bytes = encodedImages_.find(source);
        if (bytes == encodedImages_.end()) {
            const std::string dir = std::filesystem::path(path_).parent_path().string();
            fail(use + ": cannot read texture file '" + image.uri + "' (looked in '" + (dir.empty() ? "." : dir) + "')");
        }
        try {
            scene_.textures.push_back(decodeImage(bytes->second.data(), bytes->second.size(), ChannelEncoding::Srgb, label));
        } catch (const ImageError& e) {
            fail(use + ": " + e.what());
        }
        return textureOfImage_[source] = int(scene_.textures.size()) - 1;
    }

    // --- the node hierarchy -----------------------------------------------------------------

    void visit(int nodeIndex, const glm::mat4& parent, size_t depth) {
        if (nodeIndex < 0 || size_t(nodeIndex) >= model_.nodes.size())
            fail("node " + std::to_string(nodeIndex) + " does not exist");
        if (depth > model_.nodes.size()) fail("the node hierarchy has a cycle (through node " + std::to_string(nodeIndex) + ")");
        const tinygltf::Node& node = model_.nodes[nodeIndex];
        const glm::mat4 world = parent * localMatrix(node);
        const std::string nodeName = nameOr(node.name, "node", nodeIndex);
        if (node.mesh >= 0) addMesh(node, world, nodeName);
        if (node.camera >= 0) addCamera(node, world, nodeName);
        if (const auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end())
            addLight(it->second.Get("light"), world, nodeName);
        for (int child : node.children) visit(child, world, depth + 1);
    }

    void addCamera(const tinygltf::Node& node, const glm::mat4& world, const std::string& nodeName) {
        if (scene_.hasCamera) return;
        if (size_t(node.camera) >= model_.cameras.size()) fail("node '" + nodeName + "': camera " + std::to_string(node.camera) + " does not exist");
        const tinygltf::Camera& camera = model_.cameras[node.camera];
        if (camera.type != "perspective") {
            warn("node '" + nodeName + "': " + camera.type + " camera ignored (only perspective cameras are used)");
            return;
        }
        if (!(camera.perspective.yfov > 0.0 && camera.perspective.yfov < M_PI))
            fail("camera '" + nameOr(camera.name, "camera", node.camera) + "': yfov must be in (0, pi)");
        // Scale in the node transform would scale the view frustum: keep rotation and position only.
        glm::mat4 cameraToWorld = world;
        for (int axis = 0; axis < 3; ++axis) cameraToWorld[axis] = glm::vec4(glm::normalize(glm::vec3(world[axis])), 0.0f);
        scene_.camera.cameraToWorld = cameraToWorld;
        scene_.camera.yfov = float(camera.perspective.yfov);
        scene_.camera.aspect = float(camera.perspective.aspectRatio);
        scene_.hasCamera = true;
    }

    void addLight(const tinygltf::Value& index, const glm::mat4& world, const std::string& nodeName) {
        const int lightIndex = index.IsInt() ? index.Get<int>() : (index.IsNumber() ? int(index.GetNumberAsDouble()) : -1);
        if (lightIndex < 0 || size_t(lightIndex) >= model_.lights.size())
            fail("node '" + nodeName + "': KHR_lights_punctual light " + std::to_string(lightIndex) + " does not exist");
        const tinygltf::Light& source = model_.lights[lightIndex];
        PunctualLight light;
        if (source.type == "point") light.type = PunctualLight::Type::Point;
        else if (source.type == "spot") light.type = PunctualLight::Type::Spot;
        else if (source.type == "directional") light.type = PunctualLight::Type::Directional;
        else fail("light '" + nameOr(source.name, "light", lightIndex) + "': unknown type '" + source.type + "'");
        light.position = glm::vec3(world[3]);
        light.direction = glm::normalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f));
        light.intensity = color3(source.color, glm::vec3(1.0f)) * float(source.intensity);
        light.innerConeAngle = float(source.spot.innerConeAngle);
        light.outerConeAngle = float(source.spot.outerConeAngle);
        if (!allFinite(light.direction) || !allFinite(light.position) || !allFinite(light.intensity))
            fail("node '" + nodeName + "': light has a degenerate transform or a non-finite intensity");
        scene_.lights.push_back(light);
    }

    // --- meshes -----------------------------------------------------------------------------

    void addMesh(const tinygltf::Node& node, const glm::mat4& world, const std::string& nodeName) {
        if (size_t(node.mesh) >= model_.meshes.size()) fail("node '" + nodeName + "': mesh " + std::to_string(node.mesh) + " does not exist");
        const tinygltf::Mesh& mesh = model_.meshes[node.mesh];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string name = nodeName + "/" + nameOr(mesh.name, "mesh", node.mesh) + "/" + std::to_string(p);
            try {
                addPrimitive(mesh.primitives[p], world, name);
            } catch (const AccessorError& e) {
                fail("mesh '" + name + "': " + e.what());
            }
        }
    }

    AccessorData attribute(const tinygltf::Primitive& primitive, const char* semantic, int components,
                           size_t vertexCount, const std::string& name) {
        const auto it = primitive.attributes.find(semantic);
        if (it == primitive.attributes.end()) return {};
        AccessorData data = readAccessor(model_, it->second);
        if (data.components != components)
            fail("mesh '" + name + "': " + semantic + " has " + std::to_string(data.components) +
                 " components, expected " + std::to_string(components));
        if (vertexCount != size_t(-1) && data.count != vertexCount)
            fail("mesh '" + name + "': " + semantic + " has " + std::to_string(data.count) +
                 " elements but POSITION has " + std::to_string(vertexCount));
        for (double v : data.values)
            if (!std::isfinite(v)) fail("mesh '" + name + "': " + semantic + " holds a NaN or infinite value");
        return data;
    }

    std::vector<glm::uvec3> triangles(const tinygltf::Primitive& primitive, size_t vertexCount, const std::string& name) {
        std::vector<uint32_t> index;
        if (primitive.indices >= 0) {
            const AccessorData data = readAccessor(model_, primitive.indices);
            if (data.components != 1) fail("mesh '" + name + "': indices must be scalars");
            index.reserve(data.count);
            for (double v : data.values) {
                if (!(v >= 0.0 && v < double(vertexCount)))
                    fail("mesh '" + name + "': index " + std::to_string(int64_t(v)) + " is out of range (" +
                         std::to_string(vertexCount) + " vertices)");
                index.push_back(uint32_t(v));
            }
        } else {
            index.resize(vertexCount);
            for (size_t i = 0; i < vertexCount; ++i) index[i] = uint32_t(i);
        }
        std::vector<glm::uvec3> result;
        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            for (size_t i = 0; i + 2 < index.size(); i += 3) result.emplace_back(index[i], index[i + 1], index[i + 2]);
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            // glTF 3.7.2.1: every other triangle swaps its first two vertices to keep the winding.
            for (size_t i = 0; i + 2 < index.size(); ++i)
                result.push_back(i % 2 == 0 ? glm::uvec3(index[i], index[i + 1], index[i + 2])
                                            : glm::uvec3(index[i + 1], index[i], index[i + 2]));
        } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
            for (size_t i = 1; i + 1 < index.size(); ++i) result.emplace_back(index[i], index[i + 1], index[0]);
        }
        return result;
    }

    void addPrimitive(const tinygltf::Primitive& primitive, const glm::mat4& world, const std::string& name) {
        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            warn("mesh '" + name + "': point or line primitive skipped (mode " + std::to_string(mode) + ")");
            return;
        }
        if (!primitive.attributes.count("POSITION")) fail("mesh '" + name + "' has no POSITION attribute");
        if (primitive.material >= int(model_.materials.size()))
            fail("mesh '" + name + "': material " + std::to_string(primitive.material) + " does not exist");

        const AccessorData positions = attribute(primitive, "POSITION", 3, size_t(-1), name);
        const size_t n = positions.count;
        const AccessorData normals = attribute(primitive, "NORMAL", 3, n, name);
        const AccessorData uvs = attribute(primitive, "TEXCOORD_0", 2, n, name);
        const AccessorData tangents = attribute(primitive, "TANGENT", 4, n, name);

        Mesh mesh;
        mesh.name = name;
        mesh.material = primitive.material;
        mesh.triangles = triangles(primitive, n, name);
        const glm::mat3 linear(world);
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
        const float handedness = glm::determinant(linear) < 0.0f ? -1.0f : 1.0f;
        mesh.positions.resize(n);
        for (size_t v = 0; v < n; ++v) {
            mesh.positions[v] = glm::vec3(world * glm::vec4(positions.at(v, 0), positions.at(v, 1), positions.at(v, 2), 1.0f));
            if (!allFinite(mesh.positions[v]))
                fail("mesh '" + name + "': vertex " + std::to_string(v) + " has a non-finite world position");
        }
        if (uvs.count) {
            mesh.uvs.resize(n);
            for (size_t v = 0; v < n; ++v) mesh.uvs[v] = glm::vec2(uvs.at(v, 0), uvs.at(v, 1));
        }
        // A mirroring transform turns counter-clockwise into clockwise: swap to keep the front.
        if (handedness < 0.0f)
            for (glm::uvec3& t : mesh.triangles) std::swap(t.y, t.z);

        if (const size_t dropped = removeDegenerateTriangles(mesh))
            warn("mesh '" + name + "': dropped " + std::to_string(dropped) + " degenerate triangle(s)");
        if (mesh.triangles.empty()) {
            warn("mesh '" + name + "': no triangles left, skipped");
            return;
        }

        bool normalsUsable = normals.count > 0;
        if (normalsUsable) {
            mesh.normals.resize(n);
            for (size_t v = 0; v < n && normalsUsable; ++v) {
                const glm::vec3 normal = normalMatrix * glm::vec3(normals.at(v, 0), normals.at(v, 1), normals.at(v, 2));
                const float length = glm::length(normal);
                normalsUsable = length > 0.0f && std::isfinite(length);
                mesh.normals[v] = normal / length;
            }
            if (!normalsUsable) warn("mesh '" + name + "': zero-length normals, normals recomputed from the triangles");
        }
        if (!normalsUsable) computeVertexNormals(mesh);

        if (tangents.count && normalsUsable) {
            mesh.tangents.resize(n);
            for (size_t v = 0; v < n; ++v) {
                const glm::vec3 t = linear * glm::vec3(tangents.at(v, 0), tangents.at(v, 1), tangents.at(v, 2));
                const glm::vec3 axis = Frame::fromNormalAndAxis(mesh.normals[v], t).x;
                mesh.tangents[v] = glm::vec4(axis, (tangents.at(v, 3) < 0.0 ? -1.0f : 1.0f) * handedness);
            }
        } else if (!mesh.uvs.empty()) {
            computeTangents(mesh);
        }
        scene_.meshes.push_back(std::move(mesh));
    }

    std::string path_;
    tinygltf::Model model_;
    EncodedImages encodedImages_;
    std::map<int, int> textureOfImage_;
    SceneDescription scene_;
};

}  // namespace

SceneDescription loadGltf(const std::string& path) { return GltfLoader(path).load(); }

}  // namespace woven
