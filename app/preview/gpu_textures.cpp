#include "gpu_textures.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>

#include "gl_error.h"

namespace woven {

namespace {
GLint glWrap(TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
        case TextureWrap::Repeat: break;
    }
    return GL_REPEAT;
}
}  // namespace

std::string mapDefines(const std::vector<MapUse>& maps) {
    std::string defines;
    for (size_t i = 0; i < maps.size(); ++i) defines += "#define " + std::string(maps[i].define) + " " + std::to_string(i) + "\n";
    return defines + "#define MAP_COUNT " + std::to_string(maps.size()) + "\n";
}

GpuTextures::~GpuTextures() { reset(nullptr); }

void GpuTextures::reset(const std::vector<TextureImage>* images) {
    for (const auto& [key, id] : textures_) glDeleteTextures(1, &id);
    for (const auto& [key, id] : samplers_) glDeleteSamplers(1, &id);
    textures_.clear();
    samplers_.clear();
    images_ = images;
}

GLuint GpuTextures::texture(int image, bool srgb) {
    const auto key = std::make_pair(image, srgb);
    if (const auto it = textures_.find(key); it != textures_.end()) return it->second;
    if (!images_ || image < 0 || image >= int(images_->size()))
        throw GlError("texture " + std::to_string(image) + " does not exist");
    const TextureImage& t = (*images_)[size_t(image)];
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (t.isFloat()) {
        // Float data is stored as written; sRGB colour in a float file is decoded here.
        std::vector<glm::vec4> texels = t.floats;
        if (srgb)
            for (glm::vec4& v : texels)
                for (int c = 0; c < 3; ++c)
                    v[c] = v[c] <= 0.04045f ? v[c] / 12.92f : std::pow((v[c] + 0.055f) / 1.055f, 2.4f);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, t.width, t.height, 0, GL_RGBA, GL_FLOAT, texels.data());
    } else {
        glTexImage2D(GL_TEXTURE_2D, 0, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, t.width, t.height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, t.bytes.data());
    }
    glGenerateMipmap(GL_TEXTURE_2D);
    return textures_[key] = id;
}

GLuint GpuTextures::sampler(const TextureRef& ref) {
    const auto key = std::make_tuple(int(ref.wrapS), int(ref.wrapT), ref.nearest, ref.mipmaps);
    if (const auto it = samplers_.find(key); it != samplers_.end()) return it->second;
    GLuint id = 0;
    glGenSamplers(1, &id);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, glWrap(ref.wrapS));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, glWrap(ref.wrapT));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, ref.nearest ? GL_NEAREST : GL_LINEAR);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, ref.mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    return samplers_[key] = id;
}

void GpuTextures::bind(const TextureRef& ref, int unit) {
    // Active first: a texture made on first use is bound to the active unit while it uploads.
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, texture(ref.image, ref.srgb));
    glBindSampler(GLuint(unit), sampler(ref));
}

void GpuTextures::bindMaps(const ShaderProgram& program, const std::vector<MapUse>& maps, int firstUnit) {
    for (size_t i = 0; i < maps.size(); ++i) {
        const int unit = firstUnit + int(i);
        bind(*maps[i].ref, unit);
        const std::string index = "[" + std::to_string(i) + "]";
        glUniform1i(program.uniform(("maps" + index).c_str()), unit);
        glUniform1i(program.uniform(("mapTexCoord" + index).c_str()), maps[i].ref->texCoord);
        glUniformMatrix3fv(program.uniform(("mapTransform" + index).c_str()), 1, GL_FALSE,
                           glm::value_ptr(maps[i].ref->uvTransform));
    }
}

}  // namespace woven
