#include "drape_scene.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "atomic_file.h"
#include "woven_params_json.h"

namespace drape {

namespace {

tinygltf::Value toValue(const nlohmann::json& j) {
    if (j.is_object()) {
        tinygltf::Value::Object object;
        for (const auto& item : j.items()) object[item.key()] = toValue(item.value());
        return tinygltf::Value(std::move(object));
    }
    if (j.is_array()) {
        tinygltf::Value::Array array;
        for (const auto& item : j) array.push_back(toValue(item));
        return tinygltf::Value(std::move(array));
    }
    if (j.is_boolean()) return tinygltf::Value(j.get<bool>());
    if (j.is_number_integer()) return tinygltf::Value(j.get<int>());
    if (j.is_number()) return tinygltf::Value(j.get<double>());
    return tinygltf::Value(j.get<std::string>());
}

// Accumulates meshes, materials and nodes into one tinygltf::Model with a single buffer.
class ModelBuilder {
public:
    ModelBuilder() {
        model_.asset.version = "2.0";
        model_.asset.generator = "woven tools/drape";
        model_.buffers.emplace_back();
        model_.scenes.emplace_back();
        model_.defaultScene = 0;
    }

    int material(const std::string& name, const glm::vec3& baseColor, float roughness) {
        tinygltf::Material m;
        m.name = name;
        m.pbrMetallicRoughness.baseColorFactor = {baseColor.r, baseColor.g, baseColor.b, 1.0};
        m.pbrMetallicRoughness.metallicFactor = 0.0;
        m.pbrMetallicRoughness.roughnessFactor = roughness;
        m.doubleSided = true;
        model_.materials.push_back(m);
        return int(model_.materials.size()) - 1;
    }

    int wovenMaterial(const std::string& name, const woven::WovenParams& params) {
        const int index = material(name, params.weft_color, 0.6f);
        model_.materials[index].extensions["WOVEN_fabric"] = toValue(woven::paramsToJson(params));
        use("WOVEN_fabric");
        return index;
    }

    // One-sided: glTF emission is the radiance of the front face.
    int emissiveMaterial(const std::string& name, const glm::vec3& color, float strength) {
        const int index = material(name, glm::vec3(0.0f), 1.0f);
        tinygltf::Material& m = model_.materials[index];
        m.doubleSided = false;
        m.emissiveFactor = {color.r, color.g, color.b};
        tinygltf::Value::Object ext;
        ext["emissiveStrength"] = tinygltf::Value(double(strength));
        m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(ext);
        use("KHR_materials_emissive_strength");
        return index;
    }

    void meshNode(const std::string& name, const TriangleMesh& mesh, int material) {
        tinygltf::Primitive primitive;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        primitive.material = material;
        primitive.attributes["POSITION"] = vec3Accessor(mesh.positions, true);
        primitive.attributes["NORMAL"] = vec3Accessor(mesh.normals, false);
        if (!mesh.uvs.empty()) primitive.attributes["TEXCOORD_0"] = vec2Accessor(mesh.uvs);
        primitive.indices = indexAccessor(mesh.indices, uint32_t(mesh.positions.size()));
        tinygltf::Mesh gltfMesh;
        gltfMesh.name = name;
        gltfMesh.primitives.push_back(primitive);
        model_.meshes.push_back(gltfMesh);
        tinygltf::Node node;
        node.name = name;
        node.mesh = int(model_.meshes.size()) - 1;
        addNode(node);
    }

    void cameraNode(const glm::vec3& eye, const glm::vec3& target, float yfov, float aspect) {
        tinygltf::Camera camera;
        camera.type = "perspective";
        camera.name = "Camera";
        camera.perspective.yfov = yfov;
        camera.perspective.aspectRatio = aspect;
        camera.perspective.znear = 0.05;
        camera.perspective.zfar = 100.0;
        model_.cameras.push_back(camera);
        tinygltf::Node node;
        node.name = "Camera";
        node.camera = int(model_.cameras.size()) - 1;
        const glm::mat4 cameraToWorld = glm::inverse(glm::lookAt(eye, target, glm::vec3(0, 1, 0)));
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) node.matrix.push_back(cameraToWorld[c][r]);
        addNode(node);
    }

    void write(const std::string& path) {
        woven::writeFileAtomically(path, [&](const std::string& tmp) {
            tinygltf::TinyGLTF writer;
            if (!writer.WriteGltfSceneToFile(&model_, tmp, true, true, false, true))
                throw std::runtime_error("tinygltf could not write the file");
        });
    }

private:
    void use(const std::string& extension) {
        for (const auto& e : model_.extensionsUsed)
            if (e == extension) return;
        model_.extensionsUsed.push_back(extension);
    }

    void addNode(const tinygltf::Node& node) {
        model_.nodes.push_back(node);
        model_.scenes[0].nodes.push_back(int(model_.nodes.size()) - 1);
    }

    int view(const void* data, size_t bytes, int target) {
        std::vector<unsigned char>& buffer = model_.buffers[0].data;
        while (buffer.size() % 4) buffer.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buffer.size();
        view.byteLength = bytes;
        view.target = target;
        const auto* p = static_cast<const unsigned char*>(data);
        buffer.insert(buffer.end(), p, p + bytes);
        model_.bufferViews.push_back(view);
        return int(model_.bufferViews.size()) - 1;
    }

    int accessor(int bufferView, int componentType, int type, size_t count) {
        tinygltf::Accessor a;
        a.bufferView = bufferView;
        a.componentType = componentType;
        a.type = type;
        a.count = count;
        model_.accessors.push_back(a);
        return int(model_.accessors.size()) - 1;
    }

    int vec3Accessor(const std::vector<glm::vec3>& v, bool withBounds) {
        const int index = accessor(view(v.data(), v.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER),
                                   TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, v.size());
        if (withBounds) {  // required for POSITION
            glm::vec3 lo(v[0]), hi(v[0]);
            for (const glm::vec3& p : v) lo = glm::min(lo, p), hi = glm::max(hi, p);
            model_.accessors[index].minValues = {lo.x, lo.y, lo.z};
            model_.accessors[index].maxValues = {hi.x, hi.y, hi.z};
        }
        return index;
    }

    int vec2Accessor(const std::vector<glm::vec2>& v) {
        return accessor(view(v.data(), v.size() * sizeof(glm::vec2), TINYGLTF_TARGET_ARRAY_BUFFER),
                        TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, v.size());
    }

    int indexAccessor(const std::vector<uint32_t>& indices, uint32_t vertexCount) {
        if (vertexCount <= 65536) {  // 16-bit indices halve the index data
            std::vector<uint16_t> shortIndices(indices.begin(), indices.end());
            return accessor(view(shortIndices.data(), shortIndices.size() * 2, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, indices.size());
        }
        return accessor(view(indices.data(), indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
    }

    tinygltf::Model model_;
};

}  // namespace

void writeDrapeScene(const DrapeScene& scene, const std::string& path) {
    ModelBuilder b;
    b.meshNode("Cloth", scene.cloth, b.wovenMaterial("Cloth", scene.clothMaterial));
    b.meshNode("Object", scene.object, b.material("Object", {0.30f, 0.33f, 0.38f}, 0.35f));
    const glm::vec3 target(0.0f, 0.5f, 0.0f);
    b.cameraNode({0.0f, 1.35f, 2.3f}, target, 0.62f, 4.0f / 3.0f);
    if (scene.layout == Layout::Studio) {
        b.meshNode("Ground", quadMesh({-4, 0, -4}, {0, 0, 8}, {8, 0, 0}), b.material("Ground", glm::vec3(0.45f), 0.9f));
        const glm::vec3 lightCenter(-1.0f, 2.5f, 1.2f);
        b.meshNode("AreaLight", facingSquare(lightCenter, target - lightCenter, 0.8f),
                   b.emissiveMaterial("AreaLight", {1.0f, 0.95f, 0.88f}, 40.0f));
        return b.write(path);
    }
    // The room: floor, ceiling, back and side walls (fronts facing inwards), open towards the camera.
    const int wall = b.material("Wall", glm::vec3(0.7f), 0.9f);
    const float x0 = -2.0f, x1 = 2.0f, y1 = 2.6f, z0 = -1.6f, z1 = 3.2f;
    b.meshNode("Floor", quadMesh({x0, 0, z0}, {0, 0, z1 - z0}, {x1 - x0, 0, 0}), b.material("Ground", glm::vec3(0.45f), 0.9f));
    b.meshNode("Ceiling", quadMesh({x0, y1, z0}, {x1 - x0, 0, 0}, {0, 0, z1 - z0}), wall);
    b.meshNode("BackWall", quadMesh({x0, 0, z0}, {x1 - x0, 0, 0}, {0, y1, 0}), wall);
    b.meshNode("LeftWall", quadMesh({x0, 0, z0}, {0, y1, 0}, {0, 0, z1 - z0}), wall);
    b.meshNode("RightWall", quadMesh({x1, 0, z0}, {0, 0, z1 - z0}, {0, y1, 0}), wall);
    // A small lamp facing the back wall, and a shade between it and the cloth.
    const glm::vec3 lamp(0.9f, 1.9f, -1.2f);
    b.meshNode("Lamp", facingSquare(lamp, {0, 0, -1}, 0.15f), b.emissiveMaterial("Lamp", {1.0f, 0.92f, 0.8f}, 1500.0f));
    b.meshNode("Shade", facingSquare(lamp + glm::vec3(0, 0, 0.12f), {0, 0, 1}, 0.45f), b.material("Shade", glm::vec3(0.6f), 0.8f));
    b.write(path);
}

}  // namespace drape
