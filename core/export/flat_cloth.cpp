#include "flat_cloth.h"

namespace woven {

Mesh flatCloth(glm::vec2 size, const std::string& name) {
    const glm::vec2 h = 0.5f * size;
    Mesh m;
    m.name = m.meshName = name;
    m.nodePath = {name};
    m.positions = {{-h.x, 0, h.y}, {h.x, 0, h.y}, {h.x, 0, -h.y}, {-h.x, 0, -h.y}};
    m.normals.assign(4, glm::vec3(0, 1, 0));
    m.uvs = {{0, 0}, {size.x, 0}, {size.x, size.y}, {0, size.y}};
    m.tangents.assign(4, glm::vec4(1, 0, 0, 1));  // +u; n x t = -z runs along +v
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.material = 0;
    return m;
}

}  // namespace woven
