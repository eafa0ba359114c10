#include "scene_validation.h"

#include "coordinate_limits.h"
#include "mesh_instances.h"
#include "scene_loader.h"

namespace woven {

void validateScene(const SceneDescription& s) {
    const auto fail = [&](const std::string& what) { throw SceneError(s.source + ": " + what); };
    size_t triangles = 0;
    for (const Mesh& mesh : s.meshes) {
        const std::string name = "mesh '" + mesh.name + "': ";
        const size_t n = mesh.positions.size();
        for (size_t v = 0; v < n; ++v)
            if (const std::string problem = coordinateProblem(mesh.positions[v]); !problem.empty())
                fail(name + "vertex " + std::to_string(v) + " at " + problem);
        for (size_t t = 0; t < mesh.triangles.size(); ++t) {
            const glm::uvec3 tri = mesh.triangles[t];
            if (tri.x >= n || tri.y >= n || tri.z >= n)
                fail(name + "triangle " + std::to_string(t) + " refers to a vertex past the " + std::to_string(n) + " it has");
        }
        if (!mesh.normals.empty() && mesh.normals.size() != n) fail(name + "normal count differs from vertex count");
        if (!mesh.uvs.empty() && mesh.uvs.size() != n) fail(name + "uv count differs from vertex count");
        if (!mesh.uvs1.empty() && mesh.uvs1.size() != n) fail(name + "TEXCOORD_1 count differs from vertex count");
        if (!mesh.colors.empty() && mesh.colors.size() != n) fail(name + "colour count differs from vertex count");
        if (!mesh.tangents.empty() && mesh.tangents.size() != n) fail(name + "tangent count differs from vertex count");
        if (mesh.material < -1 || mesh.material >= int(s.materials.size()))
            fail(name + "material " + std::to_string(mesh.material) + " does not exist");
        if (mesh.instances) {
            if (mesh.instances->size() > kMaxInstances)
                fail(name + std::to_string(mesh.instances->size()) + " instances, past woven's limit of " +
                     std::to_string(kMaxInstances) + " (docs/LIMITS.md)");
            const MeshBox box = ownBox(mesh);
            for (size_t i = 0; i < mesh.instances->size(); ++i)
                if (const std::string problem = placementProblem((*mesh.instances)[i], box); !problem.empty())
                    fail(name + "instance " + std::to_string(i) + ": " + problem);
        }
        triangles += mesh.triangles.size();
    }
    if (triangles == 0) fail("no triangles to render");
}

}  // namespace woven
