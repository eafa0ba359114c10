#include "shadow_maps.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace woven {

namespace {

// Lights nearer the centre than this many bounding radii get cube maps.
constexpr float kCubeReach = 2.0f;

void allocateDepth(GLenum target, GLuint texture, int size, int layers) {
    glBindTexture(target, texture);
    glTexImage3D(target, 0, GL_DEPTH_COMPONENT32F, size, size, layers, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    // Hardware comparison with bilinear filtering: 2 x 2 percentage-closer filtering for free.
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

}  // namespace

ShadowMaps::ShadowMaps() {
    depthProgram_ = std::make_unique<ShaderProgram>(std::vector<std::string>{"shadow_depth.vert"},
                                                    std::vector<std::string>{"shadow_depth.frag"});
    glGenFramebuffers(1, &framebuffer_);
    glGenTextures(1, &cubeTexture_);
    glGenTextures(1, &flatTexture_);
    // Filtering across a cube's face edges, so shadows show no seams there.
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

ShadowMaps::~ShadowMaps() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &cubeTexture_);
    glDeleteTextures(1, &flatTexture_);
}

void ShadowMaps::update(const std::vector<const GpuMesh*>& casters, unsigned meshGeneration,
                        const PreviewLights& lights, const SceneBox& box) {
    // The strongest lights by their irradiance at the scene's centre get the maps.
    const glm::vec3 centre = box.centre();
    const float radius = std::max(box.radius(), 1e-4f);
    const int n = std::min<int>(int(lights.lights.size()), PreviewLights::kMaxLights);
    auto nearCentre = [&](const PreviewLight& l) { return glm::length(l.position - centre) < kCubeReach * radius; };
    auto strength = [&](int i) {
        const PreviewLight& l = lights.lights[i];
        if (l.type == PreviewLight::Directional) return luminance(l.intensity);
        const glm::vec3 d = centre - l.position;
        return luminance(l.intensity) / std::max(glm::dot(d, d), radius * radius * 1e-4f);
    };
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return strength(a) > strength(b); });
    std::vector<Shadowed> shadowed;
    int cubes = 0, flats = 0;
    for (int i : order) {
        const PreviewLight& l = lights.lights[i];
        const bool cube = l.type != PreviewLight::Directional && nearCentre(l);
        if (cube ? cubes == kMaxCubes : flats == kMaxFlats) continue;
        (cube ? cubes : flats)++;
        shadowed.push_back({i, l.type, l.position});
    }
    if (meshGeneration == meshGeneration_ && shadowed == shadowed_ && int(cubeIndex_.size()) == n) return;
    meshGeneration_ = meshGeneration;
    shadowed_ = shadowed;
    cubeIndex_.assign(n, -1);
    flatIndex_.assign(n, -1);
    cubeFar_.assign(n, 0.0f);
    flatMatrix_.clear();
    flatTexel_.clear();
    if (shadowed_.empty()) return;

    GLint previousFramebuffer = 0, viewport[4];
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glUseProgram(depthProgram_->id());
    allocateDepth(GL_TEXTURE_CUBE_MAP_ARRAY, cubeTexture_, kCubeSize, 6 * std::max(cubes, 1));
    allocateDepth(GL_TEXTURE_2D_ARRAY, flatTexture_, kFlatSize, std::max(flats, 1));

    int cubeCount = 0;
    for (const Shadowed& s : shadowed_) {
        const PreviewLight& l = lights.lights[s.light];
        if (l.type != PreviewLight::Directional && nearCentre(l)) {
            cubeIndex_[s.light] = cubeCount;
            cubeFar_[s.light] = (glm::length(centre - l.position) + radius) * 1.01f;
            renderCube(cubeCount++, l.position, cubeFar_[s.light], casters);
            continue;
        }
        glm::mat4 viewProjection;
        glm::vec2 texel(0.0f);
        if (l.type == PreviewLight::Directional) {
            // Orthographic over the bounding sphere, looking along the direction the light travels.
            const glm::vec3 dir = glm::normalize(l.position);
            const glm::vec3 up = std::abs(dir.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            viewProjection = glm::ortho(-radius, radius, -radius, radius, 0.5f * radius, 3.5f * radius) *
                             glm::lookAt(centre - 2.0f * radius * dir, centre, up);
            texel.x = 2.0f * radius / float(kFlatSize);
        } else {
            // A perspective frustum from the light just holding the bounding sphere.
            const glm::vec3 toCentre = centre - l.position;
            const float distance = glm::length(toCentre);
            const float halfAngle = std::asin(std::min(1.0f, radius / distance)) * 1.05f;
            const glm::vec3 dir = toCentre / distance;
            const glm::vec3 up = std::abs(dir.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
            viewProjection = glm::perspective(2.0f * halfAngle, 1.0f, std::max(distance - 1.05f * radius, distance * 1e-3f),
                                              distance + 1.05f * radius) *
                             glm::lookAt(l.position, centre, up);
            texel.y = 2.0f * std::tan(halfAngle) / float(kFlatSize);
        }
        flatIndex_[s.light] = int(flatMatrix_.size());
        renderFlat(int(flatMatrix_.size()), viewProjection, casters);
        flatMatrix_.push_back(viewProjection);
        flatTexel_.push_back(texel);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFramebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
}

void ShadowMaps::renderCube(int layer, const glm::vec3& position, float far, const std::vector<const GpuMesh*>& casters) {
    // GL's cube face order and orientations (+x, -x, +y, -y, +z, -z).
    static const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, far * 1e-4f, far);
    glViewport(0, 0, kCubeSize, kCubeSize);
    glUniform3fv(depthProgram_->uniform("lightPosition"), 1, glm::value_ptr(position));
    glUniform1f(depthProgram_->uniform("far"), far);
    for (int face = 0; face < 6; ++face) {
        glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, cubeTexture_, 0, 6 * layer + face);
        glClear(GL_DEPTH_BUFFER_BIT);
        const glm::mat4 viewProjection = projection * glm::lookAt(position, position + axes[face], ups[face]);
        glUniformMatrix4fv(depthProgram_->uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
        for (const GpuMesh* mesh : casters) mesh->draw();
    }
}

void ShadowMaps::renderFlat(int layer, const glm::mat4& viewProjection, const std::vector<const GpuMesh*>& casters) {
    glViewport(0, 0, kFlatSize, kFlatSize);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, flatTexture_, 0, layer);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniform1f(depthProgram_->uniform("far"), 0.0f);
    glUniformMatrix4fv(depthProgram_->uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    for (const GpuMesh* mesh : casters) mesh->draw();
}

void ShadowMaps::bind(const ShaderProgram& program, int cubeUnit, int flatUnit) const {
    const int n = int(cubeIndex_.size());
    if (n > 0) {
        glUniform1iv(program.uniform("shadowCube"), n, cubeIndex_.data());
        glUniform1iv(program.uniform("shadowFlat"), n, flatIndex_.data());
        glUniform1fv(program.uniform("shadowFar"), n, cubeFar_.data());
    }
    if (!flatMatrix_.empty()) {
        glUniformMatrix4fv(program.uniform("flatMatrix"), GLsizei(flatMatrix_.size()), GL_FALSE, glm::value_ptr(flatMatrix_[0]));
        glUniform2fv(program.uniform("flatTexel"), GLsizei(flatTexel_.size()), glm::value_ptr(flatTexel_[0]));
    }
    glUniform1f(program.uniform("cubeSize"), float(kCubeSize));
    glActiveTexture(GL_TEXTURE0 + cubeUnit);
    glBindTexture(GL_TEXTURE_CUBE_MAP_ARRAY, cubeTexture_);
    glUniform1i(program.uniform("shadowCubes"), cubeUnit);
    glActiveTexture(GL_TEXTURE0 + flatUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, flatTexture_);
    glUniform1i(program.uniform("shadowFlats"), flatUnit);
}

}  // namespace woven
