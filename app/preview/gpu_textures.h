#pragma once
// A scene's texture images on the GPU, as the preview samples them: one GL texture per image
// and decoding (sRGB colour is an SRGB8_ALPHA8 texture, so the GPU decodes before filtering, as
// core's TextureSampler does), with mip levels, made on first use; and one sampler object per
// wrap and filter state.
#include <epoxy/gl.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "scene_description.h"
#include "shader_program.h"

namespace woven {

// One texture a surface shader samples through maps[] (shaders/texture_maps.glsl): its GLSL
// define and the reference.
struct MapUse {
    const char* define;
    const TextureRef* ref;
};
// "#define MAP_<NAME> i" for each map, i its index in `maps`, and MAP_COUNT.
std::string mapDefines(const std::vector<MapUse>& maps);

class GpuTextures {
public:
    GpuTextures() = default;
    ~GpuTextures();
    GpuTextures(const GpuTextures&) = delete;
    GpuTextures& operator=(const GpuTextures&) = delete;

    // Forgets every texture; the next bind() uploads from `images`, which must outlive this.
    void reset(const std::vector<TextureImage>* images);
    // Binds the texture and sampler of `ref` to texture unit `unit`. Throws GlError for an
    // image that does not exist.
    void bind(const TextureRef& ref, int unit);
    // Binds map i to unit firstUnit + i and sets its maps[i], mapTexCoord[i] and mapTransform[i].
    void bindMaps(const ShaderProgram& program, const std::vector<MapUse>& maps, int firstUnit);

private:
    GLuint texture(int image, bool srgb);
    GLuint sampler(const TextureRef& ref);

    const std::vector<TextureImage>* images_ = nullptr;
    std::map<std::pair<int, bool>, GLuint> textures_;
    std::map<std::tuple<int, int, bool, bool>, GLuint> samplers_;
};

}  // namespace woven
