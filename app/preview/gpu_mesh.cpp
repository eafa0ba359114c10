#include "gpu_mesh.h"

#include <cstddef>
#include <vector>

namespace woven {

namespace {
struct Vertex {
    glm::vec3 position, normal;
    glm::vec2 uv, uv1;
    glm::vec4 color, tangent;
    glm::vec2 skyVisibility;
};

void attribute(GLuint location, int size, size_t offset, size_t stride = sizeof(Vertex)) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, GLsizei(stride), reinterpret_cast<void*>(offset));
}

// The instance matrices from instance `first` on, a column per location.
void instanceMatrices(GLsizei first) {
    for (GLuint c = 0; c < 4; ++c)
        glVertexAttribPointer(GpuMesh::kInstanceMatrixLocation + c, 4, GL_FLOAT, GL_FALSE, sizeof(glm::mat4),
                              reinterpret_cast<void*>(size_t(first) * sizeof(glm::mat4) + c * sizeof(glm::vec4)));
}
}  // namespace

GpuMesh::GpuMesh(const Mesh& mesh, const std::vector<glm::vec2>& skyVisibility) : material_(mesh.material) {
    std::vector<Vertex> vertices(mesh.positions.size());
    for (size_t i = 0; i < vertices.size(); ++i) {
        vertices[i].position = mesh.positions[i];
        vertices[i].normal = mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[i];
        vertices[i].uv = mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i];
        vertices[i].uv1 = mesh.uvs1.empty() ? glm::vec2(0.0f) : mesh.uvs1[i];
        vertices[i].color = mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[i];
        vertices[i].tangent = mesh.tangents.empty() ? glm::vec4(0.0f) : mesh.tangents[i];
        vertices[i].skyVisibility = skyVisibility[i];
    }
    indexCount_ = GLsizei(mesh.triangles.size() * 3);
    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(1, &vertexBuffer_);
    glBindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
    glGenBuffers(1, &indexBuffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.triangles.size() * sizeof(glm::uvec3)),
                 mesh.triangles.data(), GL_STATIC_DRAW);
    attribute(0, 3, offsetof(Vertex, position));
    attribute(1, 3, offsetof(Vertex, normal));
    attribute(2, 2, offsetof(Vertex, uv));
    attribute(3, 2, offsetof(Vertex, uv1));
    attribute(4, 4, offsetof(Vertex, color));
    attribute(5, 4, offsetof(Vertex, tangent));
    attribute(kSkyVisibilityLocation, 2, offsetof(Vertex, skyVisibility));
    glGenBuffers(1, &bouncedBuffer_);
    setBouncedLight(std::vector<BouncedVertex>(vertices.size()));
    glBindBuffer(GL_ARRAY_BUFFER, bouncedBuffer_);
    attribute(kBouncedLightLocation, 3, offsetof(BouncedVertex, radiance[0]), sizeof(BouncedVertex));
    attribute(kBouncedLightLocation + 1, 3, offsetof(BouncedVertex, radiance[1]), sizeof(BouncedVertex));
    attribute(kBouncedLightLocation + 2, 4, offsetof(BouncedVertex, offCloth[0]), sizeof(BouncedVertex));
    attribute(kBouncedLightLocation + 3, 4, offsetof(BouncedVertex, offCloth[1]), sizeof(BouncedVertex));
    glEnableVertexAttribArray(kLightsSeenLocation);
    glVertexAttribIPointer(kLightsSeenLocation, kVertexShadowLights / 4, GL_UNSIGNED_INT, sizeof(BouncedVertex),
                           reinterpret_cast<void*>(offsetof(BouncedVertex, lightsSeen)));
    if (mesh.instances) {
        std::vector<glm::mat4> matrices;
        matrices.reserve(mesh.instances->size());
        for (const glm::mat4& m : *mesh.instances)
            if (glm::determinant(glm::mat3(m)) >= 0.0f) matrices.push_back(m);
        kept_ = GLsizei(matrices.size());
        for (const glm::mat4& m : *mesh.instances)
            if (glm::determinant(glm::mat3(m)) < 0.0f) matrices.push_back(m);
        mirrored_ = GLsizei(matrices.size()) - kept_;
        glGenBuffers(1, &instanceBuffer_);
        glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(matrices.size() * sizeof(glm::mat4)), matrices.data(), GL_STATIC_DRAW);
        for (GLuint c = 0; c < 4; ++c) {
            glEnableVertexAttribArray(kInstanceMatrixLocation + c);
            glVertexAttribDivisor(kInstanceMatrixLocation + c, 1);
        }
        instanceMatrices(0);
    }
    glBindVertexArray(0);
}

void GpuMesh::setBouncedLight(const std::vector<BouncedVertex>& bounced) {
    glBindBuffer(GL_ARRAY_BUFFER, bouncedBuffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(bounced.size() * sizeof(BouncedVertex)), bounced.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

GpuMesh::~GpuMesh() {
    glDeleteBuffers(1, &bouncedBuffer_);
    glDeleteBuffers(1, &instanceBuffer_);
    glDeleteBuffers(1, &indexBuffer_);
    glDeleteBuffers(1, &vertexBuffer_);
    glDeleteVertexArrays(1, &vao_);
}

void GpuMesh::draw() const {
    glBindVertexArray(vao_);
    if (!instanceBuffer_) {
        // A disabled attribute reads the context's current value, which the VAO does not keep.
        for (GLuint c = 0; c < 4; ++c)
            glVertexAttrib4f(kInstanceMatrixLocation + c, c == 0, c == 1, c == 2, c == 3);
        glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    } else {
        if (kept_) glDrawElementsInstanced(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr, kept_);
        if (mirrored_) {
            glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_);
            instanceMatrices(kept_);
            glFrontFace(GL_CW);
            glDrawElementsInstanced(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr, mirrored_);
            glFrontFace(GL_CCW);
            instanceMatrices(0);
        }
    }
    glBindVertexArray(0);
}

}  // namespace woven
