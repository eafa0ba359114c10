#pragma once
// A small mesh and its Draco-compressed glTF file (KHR_draco_mesh_compression), written through
// draco::Encoder: for the compressed-glTF tests and the glTF fuzz target's seeds.
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace woven::test {

// A wavy 8 x 8 grid: positions, unit normals, UVs and two triangles per cell.
struct Grid {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;
    Grid();
};

// The grid as a .glb at `path` whose one primitive is Draco-compressed, sequentially so that
// points and faces keep their order; `corrupt` overwrites the bitstream's header. Throws
// std::runtime_error if Draco cannot encode it.
void writeDracoGrid(const std::string& path, const Grid& grid, bool corrupt = false);

}  // namespace woven::test
