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

// Bilinear, clamped at the map's edges: the bound texture's sampling for both kinds of map.
void setBilinearClamped(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

void allocateDepth(GLenum target, GLuint texture, int size, int layers) {
    glBindTexture(target, texture);
    glTexImage3D(target, 0, GL_DEPTH_COMPONENT32F, size, size, layers, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    // Hardware comparison with bilinear filtering: 2 x 2 percentage-closer filtering for free.
    glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    setBilinearClamped(target);
}

// What a transmitting caster passes, 8 bits a channel (a share in [0, 1]), bilinearly filtered;
// white where no such caster is.
void allocateColor(GLenum target, GLuint texture, int size, int layers) {
    glBindTexture(target, texture);
    glTexImage3D(target, 0, GL_RGBA8, size, size, layers, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    setBilinearClamped(target);
}

void deleteTextures(const std::initializer_list<GLuint>& textures) {
    for (GLuint t : textures) glDeleteTextures(1, &t);
}

bool nearCentre(const PreviewLight& l, const glm::vec3& centre, float radius) {
    return glm::length(l.position - centre) < kCubeReach * radius;
}

// The first n lights, strongest first by their irradiance at the scene's centre.
std::vector<int> byStrength(const PreviewLights& lights, int n, const glm::vec3& centre, float radius) {
    auto strength = [&](int i) {
        const PreviewLight& l = lights.lights[i];
        if (l.type == PreviewLight::Directional) return luminance(l.intensity);
        const glm::vec3 d = centre - l.position;
        return luminance(l.intensity) / std::max(glm::dot(d, d), radius * radius * 1e-4f);
    };
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return strength(a) > strength(b); });
    return order;
}

// A flat map's view of the scene's bounding sphere from a light, its texel's size and the
// light as the depth program takes it.
struct FlatView {
    glm::mat4 viewProjection;
    glm::vec2 texel{0.0f};
    glm::vec4 light;
};

FlatView flatView(const PreviewLight& l, const glm::vec3& centre, float radius) {
    FlatView view;
    view.light = glm::vec4(l.position, 1.0f);
    if (l.type == PreviewLight::Directional) {
        view.light.w = 0.0f;  // lightPosition is the direction travelled
        // Orthographic over the bounding sphere, looking along the direction the light travels.
        const glm::vec3 dir = glm::normalize(l.position);
        const glm::vec3 up = std::abs(dir.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        view.viewProjection = glm::ortho(-radius, radius, -radius, radius, 0.5f * radius, 3.5f * radius) *
                              glm::lookAt(centre - 2.0f * radius * dir, centre, up);
        view.texel.x = 2.0f * radius / float(ShadowMaps::kFlatSize);
    } else {
        // A perspective frustum from the light just holding the bounding sphere.
        const glm::vec3 toCentre = centre - l.position;
        const float distance = glm::length(toCentre);
        const float halfAngle = std::asin(std::min(1.0f, radius / distance)) * 1.05f;
        const glm::vec3 dir = toCentre / distance;
        const glm::vec3 up = std::abs(dir.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        view.viewProjection = glm::perspective(2.0f * halfAngle, 1.0f, std::max(distance - 1.05f * radius, distance * 1e-3f),
                                               distance + 1.05f * radius) *
                              glm::lookAt(l.position, centre, up);
        view.texel.y = 2.0f * std::tan(halfAngle) / float(ShadowMaps::kFlatSize);
    }
    return view;
}

// The framebuffer, viewport and clear colour the maps' rendering changes, to put back after it.
struct DrawTarget {
    GLint framebuffer = 0, viewport[4];
    GLfloat clearColor[4];
};

DrawTarget currentDrawTarget() {
    DrawTarget target;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &target.framebuffer);
    glGetIntegerv(GL_VIEWPORT, target.viewport);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, target.clearColor);
    return target;
}

void restore(const DrawTarget& target) {
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target.framebuffer));
    glViewport(target.viewport[0], target.viewport[1], target.viewport[2], target.viewport[3]);
    glClearColor(target.clearColor[0], target.clearColor[1], target.clearColor[2], target.clearColor[3]);
}

}  // namespace

ShadowMaps::ShadowMaps() {
    depthProgram_ = std::make_unique<ShaderProgram>(std::vector<std::string>{"shadow_depth.vert"},
                                                    std::vector<std::string>{"shadow_depth.glsl", "shadow_depth.frag"});
    glGenFramebuffers(1, &framebuffer_);
    glGenFramebuffers(1, &transmittedFramebuffer_);
    for (MapSet* maps : {&cubes_, &flats_}) {
        glGenTextures(1, &maps->depth);
        glGenTextures(1, &maps->transmittedDepth);
        glGenTextures(1, &maps->transmittedColor);
    }
    // Filtering across a cube's face edges, so shadows show no seams there.
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
}

ShadowMaps::~ShadowMaps() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteFramebuffers(1, &transmittedFramebuffer_);
    for (const MapSet& maps : {cubes_, flats_}) deleteTextures({maps.depth, maps.transmittedDepth, maps.transmittedColor});
}

ShadowLookups ShadowMaps::lookups() const {
    if (shadowed_.empty()) return ShadowLookups::None;
    return transmittingKey_.empty() ? ShadowLookups::Opaque : ShadowLookups::Transmitted;
}

void ShadowMaps::update(const std::vector<const GpuMesh*>& casters, const TransmittingCasters& transmitting,
                        unsigned meshGeneration, const PreviewLights& lights, const SceneBox& box) {
    // The strongest lights by their irradiance at the scene's centre get the maps.
    const glm::vec3 centre = box.centre();
    const float radius = std::max(box.radius(), 1e-4f);
    const int n = std::min<int>(int(lights.lights.size()), PreviewLights::kMaxLights);
    std::vector<Shadowed> shadowed;
    int cubes = 0, flats = 0;
    for (int i : byStrength(lights, n, centre, radius)) {
        const PreviewLight& l = lights.lights[i];
        const bool cube = l.type != PreviewLight::Directional && nearCentre(l, centre, radius);
        if (cube ? cubes == kMaxCubes : flats == kMaxFlats) continue;
        (cube ? cubes : flats)++;
        shadowed.push_back({i, l.type, l.position});
    }
    if (meshGeneration == meshGeneration_ && shadowed == shadowed_ && int(cubeIndex_.size()) == n &&
        transmitting.key == transmittingKey_)
        return;
    meshGeneration_ = meshGeneration;
    shadowed_ = shadowed;
    transmittingKey_ = transmitting.key;
    cubeIndex_.assign(n, -1);
    flatIndex_.assign(n, -1);
    cubeFar_.assign(n, 0.0f);
    flatMatrix_.clear();
    flatTexel_.clear();
    if (shadowed_.empty()) return;

    const DrawTarget previous = currentDrawTarget();
    allocateMaps(cubes, flats);
    int cubeCount = 0;
    for (const Shadowed& s : shadowed_) {
        const PreviewLight& l = lights.lights[s.light];
        if (l.type != PreviewLight::Directional && nearCentre(l, centre, radius)) {
            cubeIndex_[s.light] = cubeCount;
            cubeFar_[s.light] = (glm::length(centre - l.position) + radius) * 1.01f;
            renderCube(cubeCount++, l.position, cubeFar_[s.light], casters, transmitting);
            continue;
        }
        const FlatView view = flatView(l, centre, radius);
        flatIndex_[s.light] = int(flatMatrix_.size());
        glViewport(0, 0, kFlatSize, kFlatSize);
        renderView(flats_, int(flatMatrix_.size()), view.viewProjection, view.light, 0.0f, casters, transmitting);
        flatMatrix_.push_back(view.viewProjection);
        flatTexel_.push_back(view.texel);
    }
    restore(previous);
}

void ShadowMaps::allocateMaps(int cubes, int flats) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);  // the transmitted colour where no caster lets light through
    const int cubeLayers = 6 * std::max(cubes, 1), flatLayers = std::max(flats, 1);
    allocateDepth(GL_TEXTURE_CUBE_MAP_ARRAY, cubes_.depth, kCubeSize, cubeLayers);
    allocateDepth(GL_TEXTURE_2D_ARRAY, flats_.depth, kFlatSize, flatLayers);
    if (!transmittingKey_.empty()) {
        allocateDepth(GL_TEXTURE_CUBE_MAP_ARRAY, cubes_.transmittedDepth, kCubeSize, cubeLayers);
        allocateColor(GL_TEXTURE_CUBE_MAP_ARRAY, cubes_.transmittedColor, kCubeSize, cubeLayers);
        allocateDepth(GL_TEXTURE_2D_ARRAY, flats_.transmittedDepth, kFlatSize, flatLayers);
        allocateColor(GL_TEXTURE_2D_ARRAY, flats_.transmittedColor, kFlatSize, flatLayers);
    }
}

void ShadowMaps::renderCube(int cube, const glm::vec3& position, float far, const std::vector<const GpuMesh*>& casters,
                            const TransmittingCasters& transmitting) {
    // GL's cube face order and orientations (+x, -x, +y, -y, +z, -z).
    static const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const glm::vec3 ups[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    const glm::mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, far * 1e-4f, far);
    glViewport(0, 0, kCubeSize, kCubeSize);
    for (int face = 0; face < 6; ++face)
        renderView(cubes_, 6 * cube + face, projection * glm::lookAt(position, position + axes[face], ups[face]),
                   glm::vec4(position, 1.0f), far, casters, transmitting);
}

void ShadowMaps::renderView(const MapSet& maps, int layer, const glm::mat4& viewProjection, const glm::vec4& light,
                            float far, const std::vector<const GpuMesh*>& casters,
                            const TransmittingCasters& transmitting) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, maps.depth, 0, layer);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(depthProgram_->id());
    glUniform4fv(depthProgram_->uniform("shadowLight"), 1, glm::value_ptr(light));
    glUniform1f(depthProgram_->uniform("far"), far);
    glUniformMatrix4fv(depthProgram_->uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    for (const GpuMesh* mesh : casters) mesh->draw();
    if (transmittingKey_.empty()) return;
    // The transmitting casters on their own: the nearest one's depth and colour, whatever opaque
    // caster lies in front of it (the opaque map then shadows the point anyway).
    glBindFramebuffer(GL_FRAMEBUFFER, transmittedFramebuffer_);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, maps.transmittedDepth, 0, layer);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, maps.transmittedColor, 0, layer);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    transmitting.draw(viewProjection, light, far);
}

void ShadowMaps::bind(const ShaderProgram& program, int cubeUnit, int flatUnit, int transmittedUnit) const {
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
    const struct {
        const char* sampler;
        GLenum target;
        GLuint texture;
        int unit;
    } maps[] = {{"shadowCubes", GL_TEXTURE_CUBE_MAP_ARRAY, cubes_.depth, cubeUnit},
                {"shadowFlats", GL_TEXTURE_2D_ARRAY, flats_.depth, flatUnit},
                {"transmittedCubes", GL_TEXTURE_CUBE_MAP_ARRAY, cubes_.transmittedDepth, transmittedUnit},
                {"transmittedCubeColors", GL_TEXTURE_CUBE_MAP_ARRAY, cubes_.transmittedColor, transmittedUnit + 1},
                {"transmittedFlats", GL_TEXTURE_2D_ARRAY, flats_.transmittedDepth, transmittedUnit + 2},
                {"transmittedFlatColors", GL_TEXTURE_2D_ARRAY, flats_.transmittedColor, transmittedUnit + 3}};
    for (int i = 0, count = transmittingKey_.empty() ? 2 : 6; i < count; ++i) {
        const auto& map = maps[i];
        glActiveTexture(GL_TEXTURE0 + map.unit);
        glBindTexture(map.target, map.texture);
        glUniform1i(program.uniform(map.sampler), map.unit);
    }
}

}  // namespace woven
