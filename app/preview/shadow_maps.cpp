#include "shadow_maps.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <numeric>

namespace woven {

namespace {

float luminance(const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

bool sameLights(const std::vector<PreviewLight>& a, const std::vector<PreviewLight>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(PreviewLight)) == 0);
}

void allocateDepth(GLenum target, GLuint texture, int size, int layers) {
    glBindTexture(target, texture);
    glTexImage3D(target, 0, GL_DEPTH_COMPONENT32F, size, size, std::max(layers, 1) * (target == GL_TEXTURE_CUBE_MAP_ARRAY ? 6 : 1),
                 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
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

bool ShadowMaps::supported() { return epoxy_gl_version() >= 40 || epoxy_has_gl_extension("GL_ARB_texture_cube_map_array"); }

ShadowMaps::ShadowMaps() {
    depthProgram_ = std::make_unique<ShaderProgram>(std::vector<std::string>{"shadow_depth.vert"},
                                                    std::vector<std::string>{"shadow_depth.frag"});
    glGenFramebuffers(1, &framebuffer_);
    glGenTextures(1, &cubeTexture_);
    glGenTextures(1, &sunTexture_);
}

ShadowMaps::~ShadowMaps() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &cubeTexture_);
    glDeleteTextures(1, &sunTexture_);
}

void ShadowMaps::update(const std::vector<const GpuMesh*>& casters, unsigned meshGeneration,
                        const PreviewLights& lights, const SceneBox& box) {
    if (meshGeneration == meshGeneration_ && sameLights(lights.lights, lights_)) return;
    meshGeneration_ = meshGeneration;
    lights_ = lights.lights;

    // The strongest lights by their irradiance at the scene's centre get the maps.
    const glm::vec3 centre = box.centre();
    const float radius = std::max(box.radius(), 1e-4f);
    const int n = int(lights_.size());
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    auto strength = [&](int i) {
        const PreviewLight& l = lights_[i];
        if (l.type == PreviewLight::Directional) return luminance(l.intensity);
        const glm::vec3 d = centre - l.position;
        return luminance(l.intensity) / std::max(glm::dot(d, d), radius * radius * 1e-4f);
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return strength(a) > strength(b); });
    shadowIndex_.assign(n, -1);
    shadowFar_.assign(n, 0.0f);
    std::vector<int> cubeLights, sunLights;
    for (int i : order) {
        if (lights_[i].type == PreviewLight::Directional) {
            if (int(sunLights.size()) < kMaxSuns) sunLights.push_back(i);
        } else if (int(cubeLights.size()) < kMaxCubes) {
            cubeLights.push_back(i);
        }
    }
    cubes_ = int(cubeLights.size());
    suns_ = int(sunLights.size());

    GLint previousFramebuffer = 0, viewport[4];
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glUseProgram(depthProgram_->id());

    allocateDepth(GL_TEXTURE_CUBE_MAP_ARRAY, cubeTexture_, kCubeSize, cubes_);
    for (int c = 0; c < cubes_; ++c) {
        const int i = cubeLights[c];
        shadowIndex_[i] = c;
        shadowFar_[i] = (glm::length(centre - lights_[i].position) + radius) * 1.01f;
        renderCube(c, lights_[i].position, shadowFar_[i], casters);
    }
    allocateDepth(GL_TEXTURE_2D_ARRAY, sunTexture_, kSunSize, suns_);
    sunMatrix_.assign(suns_, glm::mat4(1.0f));
    for (int s = 0; s < suns_; ++s) {
        const int i = sunLights[s];
        shadowIndex_[i] = s;
        // Orthographic over the bounding sphere, looking along the direction the light travels.
        const glm::vec3 dir = glm::normalize(lights_[i].position);
        const glm::vec3 up = std::abs(dir.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::mat4 view = glm::lookAt(centre - 2.0f * radius * dir, centre, up);
        sunMatrix_[s] = glm::ortho(-radius, radius, -radius, radius, 0.5f * radius, 3.5f * radius) * view;
        sunTexelWorld_[s] = 2.0f * radius / float(kSunSize);
        renderSun(s, sunMatrix_[s], casters);
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

void ShadowMaps::renderSun(int layer, const glm::mat4& viewProjection, const std::vector<const GpuMesh*>& casters) {
    glViewport(0, 0, kSunSize, kSunSize);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, sunTexture_, 0, layer);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUniform1f(depthProgram_->uniform("far"), 0.0f);
    glUniformMatrix4fv(depthProgram_->uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    for (const GpuMesh* mesh : casters) mesh->draw();
}

void ShadowMaps::bind(const ShaderProgram& program, int cubeUnit, int sunUnit) const {
    const int n = std::min<int>(int(shadowIndex_.size()), PreviewLights::kMaxLights);
    if (n > 0) {
        glUniform1iv(program.uniform("shadowIndex"), n, shadowIndex_.data());
        glUniform1fv(program.uniform("shadowFar"), n, shadowFar_.data());
    }
    if (suns_ > 0) {
        glUniformMatrix4fv(program.uniform("sunMatrix"), suns_, GL_FALSE, glm::value_ptr(sunMatrix_[0]));
        glUniform1fv(program.uniform("sunTexelWorld"), suns_, sunTexelWorld_);
    }
    glUniform1f(program.uniform("cubeSize"), float(kCubeSize));
    glActiveTexture(GL_TEXTURE0 + cubeUnit);
    glBindTexture(GL_TEXTURE_CUBE_MAP_ARRAY, cubeTexture_);
    glUniform1i(program.uniform("shadowCubes"), cubeUnit);
    glActiveTexture(GL_TEXTURE0 + sunUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, sunTexture_);
    glUniform1i(program.uniform("shadowSuns"), sunUnit);
}

}  // namespace woven
