#pragma once
// A glTF mesh primitive's vertices as the loader takes them: its attributes checked against the
// vertex count, its triangles from any triangle mode, its morph targets at their default weights
// and its skin in the default pose. Every failure throws SceneError naming the file and mesh.
#include <glm/glm.hpp>

#include <cstddef>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "gltf_accessor.h"

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace woven {

class GltfPrimitiveReader {
public:
    GltfPrimitiveReader(const tinygltf::Model& model, const std::string& path);

    // Each joint's matrix in the default pose, from the nodes' world matrices.
    std::vector<glm::mat4> skinMatrices(int skinIndex, const std::vector<glm::mat4>& nodeWorld,
                                        const std::string& nodeName) const;
    // An attribute with one of `components` per element and vertexCount elements (size_t(-1):
    // any); empty when the primitive has none.
    AccessorData attribute(const std::map<std::string, int>& attributes, const std::string& semantic,
                           std::initializer_list<int> components, size_t vertexCount, const std::string& name) const;
    std::vector<glm::uvec3> triangles(const tinygltf::Primitive& primitive, size_t vertexCount,
                                      const std::string& name) const;

    // Object-space POSITION, NORMAL and TANGENT (xyz) with the morph targets' displacements at
    // their default weights.
    struct MorphedVertices {
        std::vector<glm::vec3> positions, normals, tangents;
    };
    MorphedVertices morph(const tinygltf::Primitive& primitive, const AccessorData& positions,
                          const AccessorData& normals, const AccessorData& tangents,
                          const std::vector<double>& weights, const std::string& name) const;
    // Per-vertex skinning matrices: the weighted sum of the joints' matrices over every
    // JOINTS_n / WEIGHTS_n pair.
    std::vector<glm::mat4> vertexSkin(const tinygltf::Primitive& primitive, const std::vector<glm::mat4>& joints,
                                      size_t n, const std::string& name) const;

private:
    [[noreturn]] void fail(const std::string& problem) const;

    const tinygltf::Model& model_;
    std::string path_;
};

}  // namespace woven
