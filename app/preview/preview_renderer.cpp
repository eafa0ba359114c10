#include "preview_renderer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

#include "gl_error.h"
#include "orbit_camera.h"
#include "sheen_lobe.h"
#include "sky_visibility.h"
#include "display_transform.h"
#include "woven_params_json.h"

namespace woven {

namespace {

void uploadLights(const ShaderProgram& program, const PreviewLights& lights, const FaceAlbedos& bouncedCloth) {
    const int n = std::min<int>(int(lights.lights.size()), PreviewLights::kMaxLights);
    std::vector<glm::vec4> position(n), axis(n), intensity(n);
    for (int i = 0; i < n; ++i) {
        const PreviewLight& l = lights.lights[i];
        position[i] = glm::vec4(l.position, float(l.type));
        axis[i] = glm::vec4(l.axis, l.cosOuter);
        intensity[i] = glm::vec4(l.intensity, l.cosInner);
    }
    glUniform1i(program.uniform("lightCount"), n);
    if (n > 0) {
        glUniform4fv(program.uniform("lightPosition"), n, glm::value_ptr(position[0]));
        glUniform4fv(program.uniform("lightAxis"), n, glm::value_ptr(axis[0]));
        glUniform4fv(program.uniform("lightIntensity"), n, glm::value_ptr(intensity[0]));
    }
    glUniform3fv(program.uniform("ambientRadiance"), 1, glm::value_ptr(lights.ambient));
    glUniform3fv(program.uniform("bouncedClothFront"), 1, glm::value_ptr(bouncedCloth.front));
    glUniform3fv(program.uniform("bouncedClothBack"), 1, glm::value_ptr(bouncedCloth.back));
}

bool sameLights(const PreviewLights& a, const PreviewLights& b) {
    auto same = [](const PreviewLight& x, const PreviewLight& y) {
        return x.type == y.type && x.position == y.position && x.axis == y.axis && x.intensity == y.intensity &&
               x.cosOuter == y.cosOuter && x.cosInner == y.cosInner && x.area == y.area;
    };
    return a.ambient == b.ambient &&
           std::equal(a.lights.begin(), a.lights.end(), b.lights.begin(), b.lights.end(), same);
}

// Whether a material lets light through its surface, so that its shadow is coloured or partial:
// woven yarns that transmit, woven cloth with see-through gaps (a voile: core's rays pass them), or
// KHR_materials_diffuse_transmission on a glTF material.
bool letsLightThrough(const Material& m) {
    if (m.woven) return yarnsTransmit(*m.woven) || mayBeSeenThrough(*m.woven);
    return !m.unlit && m.diffuseTransmission.factor > 0.0f;
}

// Everything a transmittance program reads of a material that may change from frame to frame
// (the panel's sliders): its parameters, and for glTF its preamble (the maps) and factors.
std::string transmittanceKey(const Material& m) {
    if (m.woven) return paramsToJson(*m.woven).dump();
    std::string key = gltfProgramPreamble(m, ShadowLookups::None);
    for (const GltfUniform& u : gltfUniformTable()) {
        const glm::vec4 v = u.value(m);
        key.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    return key;
}

}  // namespace

PreviewRenderer::PreviewRenderer() {
    displayProgram_ = std::make_unique<ShaderProgram>(std::vector<std::string>{"fullscreen.vert"},
                                                      std::vector<std::string>{"display.frag"});
    environmentProgram_ = std::make_unique<ShaderProgram>(std::vector<std::string>{"fullscreen.vert"},
                                                          std::vector<std::string>{"environment.frag"});
    accumulateProgram_ = std::make_unique<ShaderProgram>(std::vector<std::string>{"fullscreen.vert"},
                                                         std::vector<std::string>{"accumulate.frag"});
    glGenVertexArrays(1, &emptyVao_);
    shadows_ = std::make_unique<ShadowMaps>();
    // Core's sheen albedo table, texel centres at its grid points so bilinear filtering matches.
    const int n = SheenLobe::kAlbedoTableSize;
    glGenTextures(1, &sheenAlbedoTable_);
    glBindTexture(GL_TEXTURE_2D, sheenAlbedoTable_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, n, n, 0, GL_RED, GL_FLOAT, SheenLobe::albedoTable().data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

PreviewRenderer::~PreviewRenderer() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &colour_);
    glDeleteFramebuffers(1, &meanFramebuffer_);
    glDeleteTextures(1, &mean_);
    glDeleteRenderbuffers(1, &depth_);
    glDeleteVertexArrays(1, &emptyVao_);
    glDeleteTextures(1, &sheenAlbedoTable_);
    glDeleteTextures(1, &environmentTexture_);
}

void PreviewRenderer::setMeshes(const SceneDescription& scene) {
    meshes_.clear();
    sceneMeshes_.clear();
    clothShares_.clear();
    bouncedLights_.reset();
    weaves_.clear();
    textures_.reset(&scene.textures);
    shadowCasters_.clear();
    ++meshGeneration_;
    bounds_ = sceneBounds(scene);
    glDeleteTextures(1, &environmentTexture_);
    environmentTexture_ = 0;
    if (const auto& image = scene.environment.image; image && image->width > 0 && image->height > 0) {
        glGenTextures(1, &environmentTexture_);
        glBindTexture(GL_TEXTURE_2D, environmentTexture_);
        std::vector<glm::vec3> radiance(image->pixels.size());
        for (size_t i = 0; i < radiance.size(); ++i) radiance[i] = glm::max(image->pixels[i], glm::vec3(0.0f));  // as core
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, image->width, image->height, 0, GL_RGB, GL_FLOAT, radiance.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    if (const size_t key = skyVisibilityKey(scene); sky_.empty() || key != skyKey_) {
        sky_ = skyVisibility(scene);
        skyKey_ = key;
    }
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& m = scene.meshes[i];
        if (m.triangles.empty()) continue;
        meshes_.push_back(std::make_unique<GpuMesh>(m, sky_[i]));
        sceneMeshes_.push_back(i);
        // Emitters cast no shadow here: an area light's samples sit on (or in) its own surface.
        const bool emitter = m.material >= 0 && m.material < int(scene.materials.size()) &&
                             scene.materials[m.material].emits();
        if (!emitter) shadowCasters_.push_back(meshes_.back().get());
    }
}

const ShaderProgram& PreviewRenderer::surfaceProgram(const Material& material, bool filterWeave, ShadowLookups shadows) {
    // The preamble names the program; a comment tells the two kinds apart.
    const std::string preamble = material.woven ? "// woven\n" + wovenProgramPreamble(material, filterWeave, shadows)
                                                : "// gltf\n" + gltfProgramPreamble(material, shadows);
    auto it = programs_.find(preamble);
    if (it == programs_.end())
        it = programs_.emplace(preamble, material.woven ? buildWovenProgram(preamble) : buildGltfProgram(preamble)).first;
    return *it->second;
}

const ShaderProgram& PreviewRenderer::shadowProgram(const Material& material) {
    // The weave filter's defines bring in the mean thread colours woven_shadow.frag averages.
    const std::string preamble = material.woven
                                     ? "// woven shadow\n" + wovenProgramPreamble(material, true, ShadowLookups::None)
                                     : "// gltf shadow\n" + gltfProgramPreamble(material, ShadowLookups::None);
    auto it = programs_.find(preamble);
    if (it == programs_.end())
        it = programs_
                 .emplace(preamble, material.woven ? buildWovenShadowProgram(preamble) : buildGltfShadowProgram(preamble))
                 .first;
    return *it->second;
}

void PreviewRenderer::updateShadows(const SceneDescription& scene, const PreviewLights& lights) {
    std::vector<const GpuMesh*> opaque;
    std::vector<std::pair<const GpuMesh*, int>> transmitting;  // with the material's index
    TransmittingCasters casters;
    for (const GpuMesh* mesh : shadowCasters_) {
        const int index = mesh->material();
        if (index >= 0 && index < int(scene.materials.size()) && letsLightThrough(scene.materials[index])) {
            casters.key += std::to_string(transmitting.size()) + ":" + std::to_string(index) + ":" +
                           transmittanceKey(scene.materials[index]) + "\n";
            transmitting.push_back({mesh, index});
        } else {
            opaque.push_back(mesh);
        }
    }
    casters.draw = [&](const glm::mat4& viewProjection, const glm::vec4& light, float far) {
        for (const auto& [mesh, index] : transmitting) {
            const Material& material = scene.materials[index];
            const ShaderProgram& program = shadowProgram(material);
            glUseProgram(program.id());
            glUniformMatrix4fv(program.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
            glUniform4fv(program.uniform("shadowLight"), 1, glm::value_ptr(light));
            glUniform1f(program.uniform("far"), far);
            uploadMaterial(program, material, index);
            mesh->draw();
        }
    };
    shadows_->update(opaque, casters, meshGeneration_, lights, bounds_);
}

void PreviewRenderer::updateBouncedLight(const SceneDescription& scene, const PreviewLights& lights, bool retrace) {
    if (bouncedLights_ && (!retrace || sameLights(*bouncedLights_, lights))) return;
    const BouncedLight bounced = bouncedLight(scene, lights);
    bouncedLights_ = lights;
    clothShares_ = bounced.clothShares;
    for (size_t k = 0; k < meshes_.size(); ++k) meshes_[k]->setBouncedLight(bounced.meshes[sceneMeshes_[k]]);
}

FaceAlbedos PreviewRenderer::bouncedClothAlbedos(const SceneDescription& scene) {
    FaceAlbedos albedos;
    for (size_t m = 0; m < clothShares_.size() && m < scene.materials.size(); ++m) {
        if (!(clothShares_[m] > 0.0f) || !scene.materials[m].woven) continue;
        const WovenParams& params = *scene.materials[m].woven;
        auto& [key, cached] = clothAlbedos_[int(m)];
        if (std::string json = paramsToJson(params).dump(); json != key) {
            cached = wovenAlbedos(params);
            key = std::move(json);
        }
        albedos.front += clothShares_[m] * cached.front;
        albedos.back += clothShares_[m] * cached.back;
    }
    return albedos;
}

void PreviewRenderer::ensureTarget(glm::ivec2 size) {
    if (size == size_) return;
    if (size.x < 1 || size.y < 1) throw GlError("preview size must be positive");
    // Past the implementation's largest image the framebuffer is only "incomplete": say the limit.
    GLint texture = 0, renderbuffer = 0, viewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    const int largest = std::min({texture, renderbuffer, viewport[0], viewport[1]});
    if (largest > 0 && (size.x > largest || size.y > largest))
        throw GlError("the preview is " + std::to_string(size.x) + " x " + std::to_string(size.y) +
                      " pixels: this OpenGL implementation draws at most " + std::to_string(largest) +
                      " a side (--width, --height; the Render button's frame, --final, has no such limit)");
    size_ = size;
    if (!framebuffer_) {
        glGenFramebuffers(1, &framebuffer_);
        glGenTextures(1, &colour_);
        glGenRenderbuffers(1, &depth_);
        glGenFramebuffers(1, &meanFramebuffer_);
        glGenTextures(1, &mean_);
    }
    glBindTexture(GL_TEXTURE_2D, mean_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, meanFramebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, mean_, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("the preview's float framebuffer is incomplete on this OpenGL implementation");
    glBindTexture(GL_TEXTURE_2D, colour_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, size.x, size.y, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, size.x, size.y);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw GlError("the preview's float framebuffer is incomplete on this OpenGL implementation");
}

void PreviewRenderer::render(const SceneDescription& scene, const PreviewLights& lights, const Camera& camera,
                             glm::ivec2 size, const PreviewOptions& options) {
    ShadowLookups shadows = ShadowLookups::None;
    if (options.shadows) {
        updateShadows(scene, lights);
        shadows = shadows_->lookups();
    }
    updateBouncedLight(scene, lights, options.traceBounce);
    const FaceAlbedos clothAlbedos = bouncedClothAlbedos(scene);
    ensureTarget(size);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, size.x, size.y);
    // Rays that miss everything see the environment: a constant one is the clear colour, an
    // image is drawn over it.
    const glm::vec3 background = environmentTexture_ ? glm::vec3(0.0f) : scene.environment.color;
    glClearColor(background.r, background.g, background.b, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (environmentTexture_) drawEnvironment(scene.environment, camera, size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    const glm::vec3 eye(camera.cameraToWorld[3]);
    const float distance = glm::length(bounds_.centre() - eye);
    const float radius = std::max(bounds_.radius(), 1e-4f);
    const float zFar = distance + radius * 1.01f;
    const float zNear = std::max(distance - radius * 1.01f, zFar * 1e-4f);
    const float aspect = camera.aspect > 0.0f ? camera.aspect : float(size.x) / float(size.y);
    // The refinement's sample point within each pixel: the image shifted by the opposite offset.
    const glm::vec2 shift = -2.0f * options.pixelOffset / glm::vec2(size);
    const glm::mat4 viewProjection = glm::translate(glm::mat4(1.0f), glm::vec3(shift, 0.0f)) *
                                     glm::perspective(camera.yfov, aspect, zNear, zFar) *
                                     glm::inverse(camera.cameraToWorld);

    const Material fallback;
    for (const auto& mesh : meshes_) {
        const int index = mesh->material();
        const bool valid = index >= 0 && index < int(scene.materials.size());
        drawMesh(*mesh, valid ? scene.materials[index] : fallback, valid ? index : -1, lights, clothAlbedos, camera,
                 viewProjection, options, shadows);
    }
    glDisable(GL_CULL_FACE);
    accumulate(options.refinement);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void PreviewRenderer::renderRefined(const SceneDescription& scene, const PreviewLights& lights, const Camera& camera,
                                    glm::ivec2 size, PreviewOptions options) {
    for (int frame = 0; frame < kRefinementFrames; ++frame) {
        options.refinement = frame;
        options.pixelOffset = refinementOffset(frame);
        render(scene, lights, camera, size, options);
    }
}

void PreviewRenderer::accumulate(int refinement) {
    glBindFramebuffer(GL_FRAMEBUFFER, meanFramebuffer_);
    glViewport(0, 0, size_.x, size_.y);
    glDisable(GL_DEPTH_TEST);
    // Frame 0 replaces the mean, whatever it held (a texture's first contents are undefined).
    if (refinement > 0) {
        glEnable(GL_BLEND);
        glBlendColor(0.0f, 0.0f, 0.0f, 1.0f / float(refinement + 1));
        glBlendFunc(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
    }
    glUseProgram(accumulateProgram_->id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, colour_);
    glUniform1i(accumulateProgram_->uniform("frame"), 0);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
}

void PreviewRenderer::drawEnvironment(const Environment& environment, const Camera& camera, glm::ivec2 size) {
    glDisable(GL_DEPTH_TEST);
    glUseProgram(environmentProgram_->id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, environmentTexture_);
    glUniform1i(environmentProgram_->uniform("environmentImage"), 0);
    glUniform3fv(environmentProgram_->uniform("environmentColor"), 1, glm::value_ptr(environment.color));
    glUniform1f(environmentProgram_->uniform("environmentRotation"), environment.rotation);
    const glm::mat3 rotation(camera.cameraToWorld);
    glUniformMatrix3fv(environmentProgram_->uniform("cameraRotation"), 1, GL_FALSE, glm::value_ptr(rotation));
    const float tanHalf = std::tan(0.5f * camera.yfov);
    const float aspect = camera.aspect > 0.0f ? camera.aspect : float(size.x) / float(size.y);
    glUniform2f(environmentProgram_->uniform("tanHalfFov"), tanHalf * aspect, tanHalf);
    glUniform2f(environmentProgram_->uniform("viewportSize"), float(size.x), float(size.y));
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

void PreviewRenderer::drawMesh(const GpuMesh& mesh, const Material& material, int materialIndex,
                               const PreviewLights& lights, const FaceAlbedos& bouncedCloth, const Camera& camera,
                               const glm::mat4& viewProjection, const PreviewOptions& options, ShadowLookups shadows) {
    const ShaderProgram& program = surfaceProgram(material, options.filterWeave, shadows);
    glUseProgram(program.id());
    glUniformMatrix4fv(program.uniform("viewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    glUniform3fv(program.uniform("cameraPosition"), 1, glm::value_ptr(glm::vec3(camera.cameraToWorld[3])));
    glUniform3fv(program.uniform("emission"), 1, glm::value_ptr(material.emission));
    uploadLights(program, lights, bouncedCloth);
    // A single-sided material shows its front alone, as glTF viewers draw it and camera rays see it
    // (RayKind in render_scene.h); counter-clockwise is the front, as in glTF.
    if (material.doubleSided) glDisable(GL_CULL_FACE);
    else glEnable(GL_CULL_FACE);
    uploadMaterial(program, material, materialIndex);
    glUniform1f(program.uniform("footprintBox"), refinementFootprint(options.refinement));
    glUniform1i(program.uniform("refinementFrame"), options.refinement);
    // After the weave's update, which binds on the active unit; the transmitted maps after the
    // material's textures (a woven material's kept surface has at most two, on units 8 and 9;
    // its far field's tables are on 14 and 15).
    const int transmittedUnit = material.woven ? 10 : 4 + int(gltfMaps(material).size());
    if (shadows != ShadowLookups::None) shadows_->bind(program, 1, 2, transmittedUnit);
    mesh.draw();
}

void PreviewRenderer::uploadMaterial(const ShaderProgram& program, const Material& material, int materialIndex) {
    if (material.woven) {
        auto& weave = weaves_[materialIndex];
        if (!weave) weave = std::make_unique<WeaveTextures>();
        weave->update(*material.woven);
        uploadWovenParams(program, *material.woven);
        weave->bind(program);
        uploadKeptSurface(program, material, textures_, 8);  // after the weave's units 0 to 7
    } else {
        glActiveTexture(GL_TEXTURE3);
        glBindTexture(GL_TEXTURE_2D, sheenAlbedoTable_);
        glUniform1i(program.uniform("sheenAlbedoTable"), 3);
        uploadGltfMaterial(program, material, textures_, 4);
    }
}

void PreviewRenderer::display(GLuint framebuffer, glm::ivec2 origin, glm::ivec2 size, const DisplayTransform& transform) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(origin.x, origin.y, size.x, size.y);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(displayProgram_->id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, mean_);
    glUniform1i(displayProgram_->uniform("radianceImage"), 0);
    glUniform1f(displayProgram_->uniform("exposureScale"), std::exp2(transform.exposure));
    glUniform1i(displayProgram_->uniform("toneMap"), int(transform.toneMap));
    glUniform2i(displayProgram_->uniform("origin"), origin.x, origin.y);
    glUniform2f(displayProgram_->uniform("viewportSize"), float(size.x), float(size.y));
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

Image PreviewRenderer::radiance() const {
    Image image;
    image.width = size_.x;
    image.height = size_.y;
    std::vector<glm::vec4> rgba(size_t(size_.x) * size_.y);
    glBindFramebuffer(GL_FRAMEBUFFER, meanFramebuffer_);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size_.x, size_.y, GL_RGBA, GL_FLOAT, rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    image.pixels.resize(rgba.size());
    for (int y = 0; y < size_.y; ++y)  // GL's row 0 is the bottom one
        for (int x = 0; x < size_.x; ++x) image.at(x, y) = glm::vec3(rgba[size_t(size_.y - 1 - y) * size_.x + x]);
    return image;
}

}  // namespace woven
