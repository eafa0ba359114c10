#pragma once
// One scene mesh in GPU buffers: interleaved position, normal, both uv sets, colour, tangent
// (zeros where the mesh has none, white for colour: the shader then falls back to the geometric
// normal and one weave element) and the sky's share on each side (sky_visibility.h); in a buffer
// of their own, the light bounced to each side (bounced_light.h), zero until setBouncedLight(). An
// instanced mesh (Mesh::instances) also keeps its copies'
// matrices, one per instance (mesh.vert's instanceMatrix), and is drawn by one instanced draw per
// handedness; any other has the identity there, which places each vertex exactly where it is.
#include <epoxy/gl.h>

#include <vector>

#include "bounced_light.h"
#include "scene_description.h"

namespace woven {

class GpuMesh {
public:
    // skyVisibility: one per vertex, as skyVisibility() gives them.
    GpuMesh(const Mesh& mesh, const std::vector<glm::vec2>& skyVisibility);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    // One per vertex (the mesh's positions), as bouncedLight() gives them.
    void setBouncedLight(const std::vector<BouncedVertex>& bounced);

    void draw() const;
    int material() const { return material_; }

    // The attribute locations mesh.vert and shadow_depth.vert read the instance's matrix from.
    static constexpr GLuint kInstanceMatrixLocation = 6;  // to 9
    static constexpr GLuint kSkyVisibilityLocation = 10;
    static constexpr GLuint kBouncedLightLocation = 11;  // to 14: BouncedVertex's four vectors
    static constexpr GLuint kLightsSeenLocation = 15;    // BouncedVertex::lightsSeen

private:
    GLuint vao_ = 0, vertexBuffer_ = 0, indexBuffer_ = 0, instanceBuffer_ = 0, bouncedBuffer_ = 0;
    GLsizei indexCount_ = 0;
    // Instanced: the copies that keep the winding first, then the mirrored ones, whose front is
    // clockwise on screen (the glTF rule for a negative determinant).
    GLsizei kept_ = 0, mirrored_ = 0;
    int material_ = -1;
};

}  // namespace woven
