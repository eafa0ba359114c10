#include "gltf_primitive.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>

#include "scene_loader.h"

namespace woven {

GltfPrimitiveReader::GltfPrimitiveReader(const tinygltf::Model& model, const std::string& path) : model_(model), path_(path) {}

void GltfPrimitiveReader::fail(const std::string& problem) const { throw SceneError(path_ + ": " + problem); }

// Each joint's matrix in the default pose: its node's world matrix times its inverse bind
// matrix. A skinned mesh ignores its own node's transform (glTF 2.0, 3.7.3).
std::vector<glm::mat4> GltfPrimitiveReader::skinMatrices(int skinIndex, const std::vector<glm::mat4>& nodeWorld,
                                                         const std::string& nodeName) const {
    if (size_t(skinIndex) >= model_.skins.size()) fail("node '" + nodeName + "': skin " + std::to_string(skinIndex) + " does not exist");
    const tinygltf::Skin& skin = model_.skins[size_t(skinIndex)];
    AccessorData inverseBind;
    if (skin.inverseBindMatrices >= 0) {
        try {
            inverseBind = readAccessor(model_, skin.inverseBindMatrices);
        } catch (const AccessorError& e) {
            fail("skin " + std::to_string(skinIndex) + ": " + e.what());
        }
        if (inverseBind.components != 16 || inverseBind.count < skin.joints.size())
            fail("skin " + std::to_string(skinIndex) + ": inverseBindMatrices must hold one MAT4 per joint");
    }
    std::vector<glm::mat4> matrices;
    for (size_t j = 0; j < skin.joints.size(); ++j) {
        const int joint = skin.joints[j];
        if (joint < 0 || size_t(joint) >= nodeWorld.size())
            fail("skin " + std::to_string(skinIndex) + ": joint node " + std::to_string(joint) + " does not exist");
        glm::mat4 bind(1.0f);
        if (inverseBind.count)
            for (int k = 0; k < 16; ++k) bind[k / 4][k % 4] = float(inverseBind.at(j, k));
        matrices.push_back(nodeWorld[size_t(joint)] * bind);
    }
    return matrices;
}

AccessorData GltfPrimitiveReader::attribute(const std::map<std::string, int>& attributes, const std::string& semantic,
                                            std::initializer_list<int> components, size_t vertexCount,
                                            const std::string& name) const {
    const auto it = attributes.find(semantic);
    if (it == attributes.end()) return {};
    AccessorData data = readAccessor(model_, it->second);
    if (std::find(components.begin(), components.end(), data.components) == components.end())
        fail("mesh '" + name + "': " + semantic + " has " + std::to_string(data.components) + " components, expected " +
             std::to_string(*components.begin()) + (components.size() > 1 ? " or " + std::to_string(*(components.end() - 1)) : ""));
    if (vertexCount != size_t(-1) && data.count != vertexCount)
        fail("mesh '" + name + "': " + semantic + " has " + std::to_string(data.count) +
             " elements but POSITION has " + std::to_string(vertexCount));
    for (double v : data.values)
        if (!std::isfinite(v)) fail("mesh '" + name + "': " + semantic + " holds a NaN or infinite value");
    return data;
}

std::vector<glm::uvec3> GltfPrimitiveReader::triangles(const tinygltf::Primitive& primitive, size_t vertexCount,
                                                       const std::string& name) const {
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

GltfPrimitiveReader::MorphedVertices GltfPrimitiveReader::morph(const tinygltf::Primitive& primitive,
                                                                const AccessorData& positions, const AccessorData& normals,
                                                                const AccessorData& tangents, const std::vector<double>& weights,
                                                                const std::string& name) const {
    const size_t n = positions.count;
    MorphedVertices v;
    v.positions.resize(n);
    for (size_t i = 0; i < n; ++i) v.positions[i] = glm::vec3(positions.at(i, 0), positions.at(i, 1), positions.at(i, 2));
    if (normals.count) {
        v.normals.resize(n);
        for (size_t i = 0; i < n; ++i) v.normals[i] = glm::vec3(normals.at(i, 0), normals.at(i, 1), normals.at(i, 2));
    }
    if (tangents.count) {
        v.tangents.resize(n);
        for (size_t i = 0; i < n; ++i) v.tangents[i] = glm::vec3(tangents.at(i, 0), tangents.at(i, 1), tangents.at(i, 2));
    }
    for (size_t t = 0; t < primitive.targets.size(); ++t) {
        const float w = t < weights.size() ? float(weights[t]) : 0.0f;
        if (w == 0.0f) continue;
        const auto add = [&](const char* semantic, std::vector<glm::vec3>& out) {
            const AccessorData d = attribute(primitive.targets[t], semantic, {3}, n, name + " morph target " + std::to_string(t));
            if (out.empty()) return;
            for (size_t i = 0; i < d.count; ++i) out[i] += w * glm::vec3(d.at(i, 0), d.at(i, 1), d.at(i, 2));
        };
        add("POSITION", v.positions);
        add("NORMAL", v.normals);
        add("TANGENT", v.tangents);
    }
    return v;
}

// Per-vertex skinning matrices: the weighted sum of the joints' matrices over every
// JOINTS_n / WEIGHTS_n pair.
std::vector<glm::mat4> GltfPrimitiveReader::vertexSkin(const tinygltf::Primitive& primitive,
                                                       const std::vector<glm::mat4>& joints, size_t n,
                                                       const std::string& name) const {
    std::vector<glm::mat4> sum(n, glm::mat4(0.0f));
    std::vector<float> total(n, 0.0f);
    for (int set = 0;; ++set) {
        const std::string jointsName = "JOINTS_" + std::to_string(set), weightsName = "WEIGHTS_" + std::to_string(set);
        if (!primitive.attributes.count(jointsName) || !primitive.attributes.count(weightsName)) break;
        const AccessorData j = attribute(primitive.attributes, jointsName, {4}, n, name);
        const AccessorData w = attribute(primitive.attributes, weightsName, {4}, n, name);
        for (size_t i = 0; i < n; ++i)
            for (int k = 0; k < 4; ++k) {
                const float weight = float(w.at(i, k));
                if (weight == 0.0f) continue;
                const double joint = j.at(i, k);
                if (!(joint >= 0.0 && joint < double(joints.size())))
                    fail("mesh '" + name + "': " + jointsName + " names joint " + std::to_string(int64_t(joint)) +
                         " of a skin with " + std::to_string(joints.size()));
                sum[i] += weight * joints[size_t(joint)];
                total[i] += weight;
            }
    }
    for (size_t i = 0; i < n; ++i) {
        if (!(total[i] > 0.0f)) fail("mesh '" + name + "': skinned vertex " + std::to_string(i) + " has no joint weight");
        sum[i] /= total[i];
    }
    return sum;
}

}  // namespace woven
