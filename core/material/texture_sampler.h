#pragma once
// One use of a texture, bound to its image (which must outlive it): looks a TextureRef up at a surface point with its
// texture coordinate set, KHR_texture_transform, wrap modes and filter, and decodes sRGB colour
// to linear texel by texel before filtering, as a GPU does with an sRGB texture. The renderer
// filters bilinearly (or picks the nearest texel for a NEAREST magnification filter) and never
// uses mip levels: its pixel samples average the texture over the pixel.
#include "scene_description.h"
#include "tex_coords.h"

namespace woven {

class TextureSampler {
public:
    TextureSampler() = default;  // no texture: eval() returns `fallback`
    TextureSampler(const TextureRef& ref, const std::vector<TextureImage>& images);

    explicit operator bool() const { return image_ != nullptr; }
    // Linear RGBA at the point, or `fallback` when there is no texture: inline, since a
    // material asks for each of its inputs' textures at every hit, most of them absent.
    glm::vec4 eval(const TexCoords& tc, const glm::vec4& fallback = glm::vec4(1.0f)) const {
        return image_ ? lookup(tc) : fallback;
    }
    glm::vec2 uv(const TexCoords& tc) const;  // the transformed coordinates looked up
    float scale() const { return ref_.scale; }
    const TextureRef& ref() const { return ref_; }

private:
    glm::vec4 lookup(const TexCoords& tc) const;  // the image's filtered value at the point
    glm::vec4 texel(int x, int y) const;

    TextureRef ref_;
    const TextureImage* image_ = nullptr;
};

}  // namespace woven
