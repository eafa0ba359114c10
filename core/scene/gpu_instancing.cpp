#include "gpu_instancing.h"

#include <tiny_gltf.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "gltf_accessor.h"
#include "mesh_instances.h"
#include "scene_loader.h"

namespace woven {

std::shared_ptr<std::vector<glm::mat4>> instanceMatrices(const tinygltf::Model& model, const tinygltf::Node& node,
                                                        const std::string& nodeName, size_t& instances, const std::string& path) {
    const auto fail = [&](const std::string& problem) { throw SceneError(path + ": " + problem); };
    const auto it = node.extensions.find("EXT_mesh_gpu_instancing");
    if (it == node.extensions.end()) return nullptr;
    const std::string where = "node '" + nodeName + "': EXT_mesh_gpu_instancing";
    const tinygltf::Value& attributes = it->second.Get("attributes");
    if (!attributes.IsObject()) fail(where + " has no attributes object");
    AccessorData trs[3];
    const char* semantics[3] = {"TRANSLATION", "ROTATION", "SCALE"};
    size_t count = size_t(-1);
    for (int a = 0; a < 3; ++a) {
        const tinygltf::Value& index = attributes.Get(semantics[a]);
        if (!index.IsInt() && !index.IsNumber()) continue;  // absent: identity
        const int accessor = index.IsInt() ? index.Get<int>() : int(index.GetNumberAsDouble());
        // Before reading it: the accessor's count is what the limit bounds.
        if (accessor >= 0 && size_t(accessor) < model.accessors.size() &&
            model.accessors[size_t(accessor)].count > kMaxInstances - instances)
            fail(where + " " + semantics[a] + ": " + std::to_string(model.accessors[size_t(accessor)].count) +
                 " instances bring the file's past woven's limit of " + std::to_string(kMaxInstances) +
                 " (docs/LIMITS.md)");
        try {
            trs[a] = readAccessor(model, accessor);
        } catch (const AccessorError& e) {
            fail(where + " " + semantics[a] + ": " + e.what());
        }
        if (trs[a].components != (a == 1 ? 4 : 3))
            fail(where + " " + semantics[a] + " must be a " + (a == 1 ? "VEC4" : "VEC3") + " accessor");
        if (count != size_t(-1) && trs[a].count != count)
            fail(where + ": TRANSLATION, ROTATION and SCALE must have one element per instance each (" +
                 std::to_string(count) + " and " + std::to_string(trs[a].count) + ")");
        count = trs[a].count;
        for (double v : trs[a].values)
            if (!std::isfinite(v)) fail(where + " " + semantics[a] + " holds a NaN or infinite value");
    }
    if (count == size_t(-1)) fail(where + " names none of TRANSLATION, ROTATION and SCALE");
    instances += count;
    auto matrices = std::make_shared<std::vector<glm::mat4>>(count);
    for (size_t i = 0; i < count; ++i) {
        glm::vec3 t(0.0f), s(1.0f);
        glm::quat r(1.0f, 0.0f, 0.0f, 0.0f);
        if (trs[0].count) t = glm::vec3(trs[0].at(i, 0), trs[0].at(i, 1), trs[0].at(i, 2));
        if (trs[1].count) {
            r = glm::quat(float(trs[1].at(i, 3)), float(trs[1].at(i, 0)), float(trs[1].at(i, 1)), float(trs[1].at(i, 2)));
            if (!(glm::length(r) > 0.0f)) fail(where + " ROTATION " + std::to_string(i) + " is a zero quaternion");
            r = glm::normalize(r);
        }
        if (trs[2].count) s = glm::vec3(trs[2].at(i, 0), trs[2].at(i, 1), trs[2].at(i, 2));
        (*matrices)[i] = glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
    }
    return matrices;
}

}  // namespace woven
