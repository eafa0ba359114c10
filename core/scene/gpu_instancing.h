#pragma once
// EXT_mesh_gpu_instancing: the copies of a node's mesh that one glTF node draws, each placed by
// its own translation, rotation and scale.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

namespace tinygltf {
class Model;
class Node;
}

namespace woven {

// The node's per-instance TRANSLATION, ROTATION (a quaternion, perhaps normalized integers) and
// SCALE as matrices in the node's space, or none when the node is not instanced. `instances`
// counts the file's instances so far, against kMaxInstances (mesh_instances.h). Throws
// SceneError naming `path` for attributes that are missing, malformed or not finite.
std::shared_ptr<std::vector<glm::mat4>> instanceMatrices(const tinygltf::Model& model, const tinygltf::Node& node,
                                                        const std::string& nodeName, size_t& instances, const std::string& path);

}  // namespace woven
