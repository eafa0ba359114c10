#pragma once
// One scene mesh in GPU buffers: interleaved position, normal, both uv sets, colour and tangent
// (zeros where the mesh has none, white for colour: the shader then falls back to the geometric
// normal and one weave element).
#include <epoxy/gl.h>

#include "scene_description.h"

namespace woven {

class GpuMesh {
public:
    explicit GpuMesh(const Mesh& mesh);
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    void draw() const;
    int material() const { return material_; }

private:
    GLuint vao_ = 0, vertexBuffer_ = 0, indexBuffer_ = 0;
    GLsizei indexCount_ = 0;
    int material_ = -1;
};

}  // namespace woven
