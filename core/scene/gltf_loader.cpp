#include "gltf_loader.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "frame.h"
#include "coordinate_limits.h"
#include "glb_container.h"
#include "gpu_instancing.h"
#include "gltf_file_access.h"
#include "decoded_limits.h"
#include "draco_decoding.h"
#include "gltf_accessor.h"
#include "file_reading.h"
#include "gltf_material_reader.h"
#include "gltf_primitive.h"
#include "untrusted_json.h"
#include "image_io.h"
#include "light_limits.h"
#include "mesh_attributes.h"
#include "mesh_instances.h"
#include "meshopt_decoding.h"
#include "scene_loader.h"
#include "woven_params_json.h"

namespace woven {

namespace {

// Extensions whose content we read, or whose absence of support changes nothing visible.
const std::set<std::string> kSupportedExtensions = {
    "KHR_mesh_quantization", "KHR_materials_emissive_strength", "KHR_lights_punctual", "KHR_texture_transform",
    "KHR_materials_sheen", "KHR_materials_specular", "KHR_materials_ior", "KHR_materials_transmission",
    "KHR_materials_volume", "KHR_materials_clearcoat", "KHR_materials_unlit", "KHR_materials_anisotropy", "WOVEN_fabric",
    "KHR_draco_mesh_compression", "EXT_meshopt_compression", "EXT_texture_webp", "EXT_mesh_gpu_instancing",
    "KHR_materials_iridescence", "KHR_materials_pbrSpecularGlossiness", "KHR_materials_dispersion",
    "KHR_materials_diffuse_transmission",
};
// Supported with an approximation that the user is told about once.
const std::map<std::string, std::string> kApproximatedExtensions = {
    {"KHR_materials_volume", "rendered thin-walled: the attenuation applies, refraction does not"},
    {"KHR_materials_pbrSpecularGlossiness", "approximated by metallic-roughness as glTF-Transform converts it "
                                            "(F0 = specular, roughness = 1 - glossiness)"},
    {"KHR_materials_dispersion", "rendered without dispersion (one IOR for every wavelength)"},
};
// Mesh compression we do not decode: named so the message can say what to do. (The KHR
// successor of EXT_meshopt_compression has a codec version Debian's meshoptimizer lacks.)
const std::set<std::string> kCompressionExtensions = {"KHR_meshopt_compression"};

// Where keepEncodedImage keeps the bytes, and the model tinygltf is filling, whose buffers it
// checks an image's buffer view against: tinygltf hands over &buffer[byteOffset] and byteLength
// unchecked (a view past its buffer was read out of bounds; found by fuzz/fuzz_gltf).
struct ImageSink {
    EncodedImages* images;
    const tinygltf::Model* model;
};

// tinygltf hands every image's encoded bytes to this callback; decoding waits until we know
// how the image is used (sRGB colour or linear data) and whether it is used at all.
bool keepEncodedImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                      const unsigned char* bytes, int size, void* user) {
    const ImageSink& sink = *static_cast<const ImageSink*>(user);
    if (image->bufferView >= 0) {  // tinygltf has checked the view's and its buffer's index
        const tinygltf::BufferView& view = sink.model->bufferViews[size_t(image->bufferView)];
        const size_t bufferBytes = sink.model->buffers[size_t(view.buffer)].data.size();
        if (view.byteOffset > bufferBytes || view.byteLength > bufferBytes - view.byteOffset || size < 0) {
            *err += "image " + std::to_string(index) + ": bufferView " + std::to_string(image->bufferView) +
                    " (byteOffset " + std::to_string(view.byteOffset) + ", byteLength " + std::to_string(view.byteLength) +
                    ") lies outside buffer " + std::to_string(view.buffer) + " (" + std::to_string(bufferBytes) + " bytes)";
            return false;
        }
    }
    (*sink.images)[index].assign(bytes, bytes + size);
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

// KHR_lights_punctual gives candela (point, spot) and lux (directional); woven's lights are
// radiometric (W/sr, W/m^2). Blender's importer divides by 683 lm/W (its default "Standard"
// lighting mode), and so does woven, so a file lights the same in both.
constexpr float kLumensPerWatt = 683.0f;

// A camera's aspectRatio (width / height) outside [kMinCameraAspect, 1 / kMinCameraAspect] is
// no picture anyone means: a line of pixels.
constexpr double kMinCameraAspect = 1.0 / 64.0;

bool allFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

class GltfLoader {
public:
    GltfLoader(std::string path, const LoadOptions& options) : path_(std::move(path)), options_(options) {}

    SceneDescription load() {
        readModel();
        checkExtensions();
        scene_.source = path_;
        GltfMaterialReader(path_, document_, encodedImages_, absentImages(), options_.strict,
                           [this](const std::string& m) { warn(m); })
            .read(scene_);
        computeNodeMatrices();
        for (int root : rootNodes()) visit(root, {});
        warnDropped(degenerate_, "degenerate");
        warnDropped(duplicate_, "duplicate");
        return std::move(scene_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { throw SceneError(path_ + ": " + problem); }

    void warn(const std::string& message) {
        scene_.warnings.push_back(message);
        std::cerr << "warning: " << path_ << ": " << message << "\n";
    }

    void readModel() {
        std::vector<unsigned char> file;
        try {
            file = readRegularFile(path_, kMaxGltfFileBytes);
        } catch (const FileReadError& e) {
            throw SceneError(e.what());
        }
        scene_.inputFiles.push_back(path_);
        checkGlbChunks(file, path_);
        // Compressed files fail inside tinygltf with a confusing buffer error: name the cause first.
        document_ = gltfJson(file, path_);
        // Compressed files hold what tinygltf refuses: stand-ins (replaced when decoding) first.
        const bool meshoptStubbed = stubMeshoptFallbackBuffers(document_);
        const bool dracoStoodIn = standInDracoIndexViews(document_);
        if (meshoptStubbed || dracoStoodIn) file = withJson(file, document_);
        const nlohmann::json& document = document_;
        if (document.is_object() && document.contains("extensionsRequired") && document["extensionsRequired"].is_array())
            for (const auto& name : document["extensionsRequired"])
                if (name.is_string() && kCompressionExtensions.count(name.get<std::string>()))
                    failCompressed(name.get<std::string>());
        tinygltf::TinyGLTF reader;
        files_.serve(reader);
        reader.SetImageLoader(keepEncodedImage, &imageSink_);
        reader.SetStoreOriginalJSONForExtrasAndExtensions(true);
        std::string err, warn;
        const bool binary = file.size() >= 4 && std::memcmp(file.data(), "glTF", 4) == 0;
        const std::string folder = std::filesystem::path(path_).parent_path().string();
        if (!binary && file.size() > std::numeric_limits<unsigned>::max()) fail("the glTF file is too large to parse");
        const bool ok = binary ? reader.LoadBinaryFromMemory(&model_, &err, &warn, file.data(), unsigned(file.size()), folder)
                               : reader.LoadASCIIFromString(&model_, &err, &warn, reinterpret_cast<const char*>(file.data()),
                                                            unsigned(file.size()), folder);
        if (!ok) {
            while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
            fail(std::string("cannot read ") + (binary ? "glTF binary" : "glTF") + ": " +
                 (err.empty() ? "unknown error" : jsonProblem(err)));
        }
        try {
            size_t decodedBytes = 0;
            decodeMeshoptViews(model_, decodedBytes);
            decodeDracoPrimitives(model_, decodedBytes);
        } catch (const DecodingError& e) {
            fail(e.what());
        }
    }

    // The images tinygltf could not read because their file is not there: in none of the places
    // it looked (the glTF file's folder, then the current one), and not outside the folder, which
    // stays an error without --allow-any-path whether or not the file exists.
    AbsentImages absentImages() const {
        namespace fs = std::filesystem;
        AbsentImages absent;
        const fs::path folder = fs::path(path_).parent_path();
        for (size_t i = 0; i < model_.images.size(); ++i) {
            const std::string& uri = model_.images[i].uri;  // tinygltf keeps it for a file it could not load
            if (uri.empty() || encodedImages_.count(int(i))) continue;
            const std::string file = uriFilePath(uri);
            std::error_code inFolder, inCurrent;
            if (!fs::exists(folder / file, inFolder) && !inFolder && !fs::exists(file, inCurrent) && !inCurrent &&
                files_.refusal((folder / file).string()).empty())
                absent.insert(int(i));
        }
        return absent;
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
        for (const std::string& name : model_.extensionsUsed) {
            if (!kSupportedExtensions.count(name) && !kCompressionExtensions.count(name))
                warn("ignores the optional extension " + name);
            if (const auto it = kApproximatedExtensions.find(name); it != kApproximatedExtensions.end())
                warn(name + ": " + it->second);
        }
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

    // --- the node hierarchy -----------------------------------------------------------------

    // The world matrix of every node, also of nodes outside the default scene (a skin's joints
    // may be there). A node with two parents or a cycle is an error.
    void computeNodeMatrices() {
        const size_t n = model_.nodes.size();
        std::vector<int> parent(n, -1);
        for (size_t i = 0; i < n; ++i)
            for (int child : model_.nodes[i].children) {
                if (child < 0 || size_t(child) >= n) fail("node " + std::to_string(child) + " does not exist");
                if (parent[size_t(child)] >= 0) fail("node " + std::to_string(child) + " is the child of two nodes");
                parent[size_t(child)] = int(i);
            }
        nodeWorld_.assign(n, glm::mat4(1.0f));
        std::vector<char> done(n, 0);
        for (size_t i = 0; i < n; ++i) {
            // Walk up to a finished ancestor, then down again.
            std::vector<size_t> chain;
            for (int k = int(i); k >= 0 && !done[size_t(k)]; k = parent[size_t(k)]) {
                if (chain.size() > n) fail("the node hierarchy has a cycle (through node " + std::to_string(k) + ")");
                chain.push_back(size_t(k));
            }
            for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
                const int p = parent[*it];
                nodeWorld_[*it] = (p >= 0 ? nodeWorld_[size_t(p)] : glm::mat4(1.0f)) * localMatrix(model_.nodes[*it]);
                done[*it] = 1;
            }
        }
    }

    // `path`: the names of the nodes above this one, root first.
    void visit(int nodeIndex, std::vector<std::string> path) {
        if (nodeIndex < 0 || size_t(nodeIndex) >= model_.nodes.size())
            fail("node " + std::to_string(nodeIndex) + " does not exist");
        if (path.size() > model_.nodes.size()) fail("the node hierarchy has a cycle (through node " + std::to_string(nodeIndex) + ")");
        const tinygltf::Node& node = model_.nodes[nodeIndex];
        const glm::mat4& world = nodeWorld_[size_t(nodeIndex)];
        const std::string nodeName = nameOr(node.name, "node", nodeIndex);
        path.push_back(nodeName);
        if (node.mesh >= 0) addMesh(node, world, path);
        if (node.camera >= 0) addCamera(node, world, nodeName);
        if (const auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end())
            addLight(it->second.Get("light"), world, nodeName);
        for (int child : node.children) visit(child, path);
    }

    // Every perspective camera goes into scene_.cameras (--camera chooses); the first is the scene's.
    void addCamera(const tinygltf::Node& node, const glm::mat4& world, const std::string& nodeName) {
        if (size_t(node.camera) >= model_.cameras.size()) fail("node '" + nodeName + "': camera " + std::to_string(node.camera) + " does not exist");
        const tinygltf::Camera& camera = model_.cameras[node.camera];
        if (camera.type != "perspective") {
            warn("node '" + nodeName + "': " + camera.type + " camera ignored (only perspective cameras are used)");
            return;
        }
        if (!(camera.perspective.yfov > 0.0 && camera.perspective.yfov < M_PI))
            fail("camera '" + nameOr(camera.name, "camera", node.camera) + "': yfov must be in (0, pi)");
        // aspectRatio is optional (tinygltf reads a missing one as 0: the image decides).
        const double aspect = camera.perspective.aspectRatio;
        if (!(aspect == 0.0 || (aspect >= kMinCameraAspect && aspect <= 1.0 / kMinCameraAspect)))
            fail("camera '" + nameOr(camera.name, "camera", node.camera) + "': aspectRatio " + std::to_string(aspect) +
                 " is not a width / height between " + std::to_string(kMinCameraAspect) + " and " +
                 std::to_string(1.0 / kMinCameraAspect));
        // Scale in the node transform would scale the view frustum: keep rotation and position
        // only. A zero scale or a non-finite matrix leaves no frame to look through (NaN rays).
        glm::mat4 cameraToWorld = world;
        for (int axis = 0; axis < 3; ++axis) cameraToWorld[axis] = glm::vec4(glm::normalize(glm::vec3(world[axis])), 0.0f);
        const bool degenerate = !allFinite(glm::vec3(cameraToWorld[0])) || !allFinite(glm::vec3(cameraToWorld[1])) ||
                                !allFinite(glm::vec3(cameraToWorld[2])) || !allFinite(glm::vec3(cameraToWorld[3])) ||
                                !(std::abs(glm::determinant(glm::mat3(cameraToWorld))) > 1e-3f);
        if (degenerate)
            fail("node '" + nodeName + "': the camera's transform is degenerate (a zero scale, parallel axes or a "
                 "non-finite value): it has no view to render");
        NamedCamera named{nameOr(camera.name, "camera", node.camera), nodeName, {}};
        if (const std::string problem = coordinateProblem(glm::vec3(cameraToWorld[3])); !problem.empty())
            fail("node '" + nodeName + "': camera '" + named.name + "' at " + problem);
        named.camera.cameraToWorld = cameraToWorld;
        named.camera.yfov = float(camera.perspective.yfov);
        named.camera.aspect = float(aspect);
        if (!scene_.hasCamera) scene_.camera = named.camera;
        scene_.hasCamera = true;
        scene_.cameras.push_back(std::move(named));
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
        light.name = nameOr(source.name, "light", lightIndex);
        light.position = glm::vec3(world[3]);
        light.direction = glm::normalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f));
        const std::string lightName = "light '" + light.name + "'";
        light.intensity = color3(source.color, glm::vec3(1.0f)) * float(source.intensity / kLumensPerWatt);
        if (const std::string problem = lightValueProblem(light.intensity); !problem.empty())
            fail(lightName + ": intensity " + std::to_string(source.intensity) + " times its colour, divided by " +
                 std::to_string(int(kLumensPerWatt)) + " lm/W, " + problem);
        if (light.type == PunctualLight::Type::Spot) {
            light.innerConeAngle = float(source.spot.innerConeAngle);
            light.outerConeAngle = float(source.spot.outerConeAngle);
            if (!(light.innerConeAngle >= 0.0f && light.innerConeAngle < light.outerConeAngle &&
                  light.outerConeAngle <= float(M_PI / 2)))
                fail(lightName + ": the cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2");
        }
        if (!allFinite(light.direction) || !allFinite(light.position))
            fail("node '" + nodeName + "': " + lightName + " has a degenerate transform (a zero scale or a non-finite value)");
        // A directional light has no position that rays start from.
        if (light.type != PunctualLight::Type::Directional)
            if (const std::string problem = coordinateProblem(light.position); !problem.empty())
                fail("node '" + nodeName + "': " + lightName + " at " + problem);
        scene_.lights.push_back(light);
    }

    // --- meshes -----------------------------------------------------------------------------

    void addMesh(const tinygltf::Node& node, const glm::mat4& world, const std::vector<std::string>& nodePath) {
        const std::string& nodeName = nodePath.back();
        if (size_t(node.mesh) >= model_.meshes.size()) fail("node '" + nodeName + "': mesh " + std::to_string(node.mesh) + " does not exist");
        const tinygltf::Mesh& mesh = model_.meshes[node.mesh];
        const size_t first = scene_.meshes.size();
        // A node's weights override its mesh's; missing ones are 0.
        const std::vector<double>& weights = node.weights.empty() ? mesh.weights : node.weights;
        const std::vector<glm::mat4> joints = node.skin >= 0 ? GltfPrimitiveReader(model_, path_).skinMatrices(node.skin, nodeWorld_, nodeName) : std::vector<glm::mat4>{};
        std::shared_ptr<std::vector<glm::mat4>> instances = instanceMatrices(model_, node, nodeName, instances_, path_);
        // An instanced mesh stays in its own space and each instance places it: world x TRS, or
        // the TRS alone after a skin, which ignores the node (and, being linear, commutes with it).
        if (instances && joints.empty())
            for (glm::mat4& m : *instances) m = world * m;
        const glm::mat4 transform = instances ? glm::mat4(1.0f) : world;
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string name = nodeName + "/" + nameOr(mesh.name, "mesh", node.mesh) + "/" + std::to_string(p);
            try {
                addPrimitive(mesh.primitives[p], joints, transform, weights, name);
            } catch (const AccessorError& e) {
                fail("mesh '" + name + "': " + e.what());
            }
        }
        for (size_t m = first; m < scene_.meshes.size(); ++m) {
            scene_.meshes[m].meshName = nameOr(mesh.name, "mesh", node.mesh);
            scene_.meshes[m].nodePath = nodePath;
        }
        if (instances) placeInstances(std::move(instances), first, nodeName);
    }

    // Gives the node's primitives (scene_.meshes from `first`) their instances. One with a zero
    // scale (glTF's way to hide a copy) draws nothing and has no inverse for Embree: dropped, in
    // one warning for the node. One placed past the coordinate limit is refused, as a vertex is.
    void placeInstances(std::shared_ptr<std::vector<glm::mat4>> instances, size_t first, const std::string& nodeName) {
        MeshBox box;
        for (size_t m = first; m < scene_.meshes.size(); ++m) {
            const MeshBox own = ownBox(scene_.meshes[m]);
            box.add(own.lo);
            box.add(own.hi);
        }
        size_t kept = 0, flat = 0;
        for (size_t i = 0; i < instances->size(); ++i) {
            const glm::mat4& m = (*instances)[i];
            if (const std::string problem = placementProblem(m, box); !problem.empty()) {
                const bool finite = allFinite(glm::vec3(m[0])) && allFinite(glm::vec3(m[1])) &&
                                    allFinite(glm::vec3(m[2])) && allFinite(glm::vec3(m[3]));
                if (!finite || invertible(m))
                    fail("node '" + nodeName + "': EXT_mesh_gpu_instancing instance " + std::to_string(i) + ": " + problem);
                ++flat;
                continue;
            }
            (*instances)[kept++] = m;
        }
        instances->resize(kept);
        if (flat)
            warn("node '" + nodeName + "': " + std::to_string(flat) + " of its " + std::to_string(flat + kept) +
                 " EXT_mesh_gpu_instancing instances have a zero scale (or flattened axes) and are not drawn");
        if (const size_t repeated = dropCopies(*instances, box))
            warn("node '" + nodeName + "': " + std::to_string(repeated) + " of its EXT_mesh_gpu_instancing instances repeat "
                 "another's placement (the same triangles in the same place, within a millionth of their size) and are "
                 "drawn once");
        kept = instances->size();
        if (kept == 0) {
            scene_.meshes.resize(first);
            return;
        }
        const std::shared_ptr<const std::vector<glm::mat4>> shared = std::move(instances);
        for (size_t m = first; m < scene_.meshes.size(); ++m) scene_.meshes[m].instances = shared;
    }

    void addPrimitive(const tinygltf::Primitive& primitive, const std::vector<glm::mat4>& joints, const glm::mat4& world,
                      const std::vector<double>& weights, const std::string& name) {
        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            warn("mesh '" + name + "': point or line primitive skipped (mode " + std::to_string(mode) + ")");
            return;
        }
        if (!primitive.attributes.count("POSITION")) fail("mesh '" + name + "' has no POSITION attribute");
        if (primitive.material >= int(model_.materials.size()))
            fail("mesh '" + name + "': material " + std::to_string(primitive.material) + " does not exist");

        const GltfPrimitiveReader reader(model_, path_);
        const AccessorData positions = reader.attribute(primitive.attributes, "POSITION", {3}, size_t(-1), name);
        const size_t n = positions.count;
        const AccessorData normals = reader.attribute(primitive.attributes, "NORMAL", {3}, n, name);
        const AccessorData uvs = reader.attribute(primitive.attributes, "TEXCOORD_0", {2}, n, name);
        const AccessorData uvs1 = reader.attribute(primitive.attributes, "TEXCOORD_1", {2}, n, name);
        const AccessorData colors = reader.attribute(primitive.attributes, "COLOR_0", {3, 4}, n, name);
        const AccessorData tangents = reader.attribute(primitive.attributes, "TANGENT", {4}, n, name);
        const GltfPrimitiveReader::MorphedVertices object = reader.morph(primitive, positions, normals, tangents, weights, name);
        const std::vector<glm::mat4> skin = joints.empty() ? std::vector<glm::mat4>{} : reader.vertexSkin(primitive, joints, n, name);
        const auto transformOf = [&](size_t v) -> const glm::mat4& { return skin.empty() ? world : skin[v]; };

        Mesh mesh;
        mesh.name = name;
        mesh.material = primitive.material;
        mesh.triangles = reader.triangles(primitive, n, name);
        // The winding follows the transform of the first vertex: a mirroring skin or node turns
        // counter-clockwise into clockwise, so swap to keep the front.
        const float handedness = n && glm::determinant(glm::mat3(transformOf(0))) < 0.0f ? -1.0f : 1.0f;
        mesh.positions.resize(n);
        for (size_t v = 0; v < n; ++v) {
            mesh.positions[v] = glm::vec3(transformOf(v) * glm::vec4(object.positions[v], 1.0f));
            if (const std::string problem = coordinateProblem(mesh.positions[v]); !problem.empty())
                fail("mesh '" + name + "': vertex " + std::to_string(v) + "'s world position " + problem);
        }
        if (uvs.count) {
            mesh.uvs.resize(n);
            for (size_t v = 0; v < n; ++v) mesh.uvs[v] = glm::vec2(uvs.at(v, 0), uvs.at(v, 1));
        }
        if (uvs1.count) {
            mesh.uvs1.resize(n);
            for (size_t v = 0; v < n; ++v) mesh.uvs1[v] = glm::vec2(uvs1.at(v, 0), uvs1.at(v, 1));
        }
        if (colors.count) {
            mesh.colors.resize(n);
            for (size_t v = 0; v < n; ++v)
                mesh.colors[v] = glm::vec4(colors.at(v, 0), colors.at(v, 1), colors.at(v, 2), colors.components == 4 ? colors.at(v, 3) : 1.0);
        }
        if (handedness < 0.0f)
            for (glm::uvec3& t : mesh.triangles) std::swap(t.y, t.z);

        degenerate_.add(removeDegenerateTriangles(mesh), name);
        duplicate_.add(removeDuplicateTriangles(mesh), name);
        if (mesh.triangles.empty()) {
            warn("mesh '" + name + "': no triangles left, skipped");
            return;
        }

        bool normalsUsable = !object.normals.empty();
        if (normalsUsable) {
            mesh.normals.resize(n);
            for (size_t v = 0; v < n && normalsUsable; ++v) {
                const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transformOf(v))));
                const glm::vec3 normal = normalMatrix * object.normals[v];
                const float length = glm::length(normal);
                normalsUsable = length > 0.0f && std::isfinite(length);
                mesh.normals[v] = normal / length;
            }
            if (!normalsUsable) warn("mesh '" + name + "': zero-length normals, normals recomputed from the triangles");
        }
        if (!normalsUsable) computeVertexNormals(mesh);

        // Tangents serve the normal map, along its texture coordinates; woven cloth follows TEXCOORD_0.
        const int tangentSet = primitive.material >= 0 ? tangentTexCoord(scene_.materials[size_t(primitive.material)]) : 0;
        if (!object.tangents.empty() && normalsUsable) {
            mesh.tangents.resize(n);
            for (size_t v = 0; v < n; ++v) {
                const glm::vec3 t = glm::mat3(transformOf(v)) * object.tangents[v];
                const glm::vec3 axis = Frame::fromNormalAndAxis(mesh.normals[v], t).x;
                mesh.tangents[v] = glm::vec4(axis, (tangents.at(v, 3) < 0.0 ? -1.0f : 1.0f) * handedness);
            }
        } else if (!(tangentSet == 0 ? mesh.uvs : mesh.uvs1).empty()) {
            computeTangents(mesh, tangentSet);
        }
        scene_.meshes.push_back(std::move(mesh));
    }

    // One warning for the file: exporters leave a degenerate triangle at the poles of every UV
    // sphere, and a line per primitive buried every other warning.
    struct DroppedTriangles {
        size_t triangles = 0;
        std::vector<std::string> primitives;
        void add(size_t dropped, const std::string& primitive) {
            if (dropped == 0) return;
            triangles += dropped;
            primitives.push_back(primitive);
        }
    };
    void warnDropped(const DroppedTriangles& dropped, const std::string& kind) {
        const std::vector<std::string>& in = dropped.primitives;
        if (in.empty()) return;
        constexpr size_t kNamed = 3;
        std::string names;
        for (size_t i = 0; i < std::min(in.size(), kNamed); ++i) names += (i ? ", '" : "'") + in[i] + "'";
        if (in.size() > kNamed) names += ", ...";
        const size_t n = dropped.triangles;
        warn("dropped " + std::to_string(n) + " " + kind + " triangle" + (n == 1 ? "" : "s") + " in " +
             std::to_string(in.size()) + " primitive" + (in.size() == 1 ? "" : "s") + " (" + names + ")");
    }

    static int tangentTexCoord(const Material& m) {
        for (const TextureRef* t : {&m.normalTexture, &m.clearcoat.normalTexture, &m.anisotropy.texture})
            if (*t) return t->texCoord;
        return 0;
    }

    std::string path_;
    LoadOptions options_;
    nlohmann::json document_;
    tinygltf::Model model_;
    EncodedImages encodedImages_;
    ImageSink imageSink_{&encodedImages_, &model_};
    std::vector<glm::mat4> nodeWorld_;
    size_t instances_ = 0;  // so far, against kMaxInstances
    DroppedTriangles degenerate_, duplicate_;
    SceneDescription scene_;
    GltfFileAccess files_{path_, options_.anyPath, scene_.inputFiles};
};

}  // namespace

SceneDescription loadGltf(const std::string& path, const LoadOptions& options) { return GltfLoader(path, options).load(); }

}  // namespace woven
