#include "texture_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "image_io.h"

namespace woven {

namespace {

// sRGB decoding of 8-bit codes: a table, since pow() per texel would dominate lookups.
const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int v = 0; v < 256; ++v) t[size_t(v)] = srgbToLinear(v / 255.0f);
        return t;
    }();
    return table;
}

// The texel index for integer coordinate i on an axis of n texels.
int wrapIndex(long long i, int n, TextureWrap wrap) {
    switch (wrap) {
        case TextureWrap::ClampToEdge: return int(std::clamp<long long>(i, 0, n - 1));
        case TextureWrap::MirroredRepeat: {
            const long long period = 2LL * n;
            long long r = i % period;
            if (r < 0) r += period;
            return int(r < n ? r : period - 1 - r);
        }
        case TextureWrap::Repeat: break;
    }
    long long r = i % n;
    return int(r < 0 ? r + n : r);
}

// floor() of a texel coordinate, kept within long long for any finite uv.
long long floorIndex(float x) { return (long long)(std::floor(std::clamp(x, -1e15f, 1e15f))); }

}  // namespace

TextureSampler::TextureSampler(const TextureRef& ref, const std::vector<TextureImage>& images) : ref_(ref) {
    if (!ref) return;
    if (ref.image >= int(images.size())) throw std::out_of_range("texture " + std::to_string(ref.image) + " does not exist");
    const TextureImage& image = images[size_t(ref.image)];
    if (image.width > 0 && image.height > 0) image_ = &image;
}

glm::vec2 TextureSampler::uv(const TexCoords& tc) const {
    const glm::vec2 uv = tc.uv[ref_.texCoord == 1 ? 1 : 0];
    return glm::vec2(ref_.uvTransform * glm::vec3(uv, 1.0f));
}

glm::vec4 TextureSampler::texel(int x, int y) const {
    const size_t i = size_t(y) * size_t(image_->width) + size_t(x);
    if (image_->isFloat()) {
        glm::vec4 t = image_->floats[i];
        if (ref_.srgb)
            for (int c = 0; c < 3; ++c) t[c] = srgbToLinear(t[c]);
        return t;
    }
    const glm::u8vec4 b = image_->bytes[i];
    if (ref_.srgb) {
        const auto& table = srgbTable();
        return {table[b.r], table[b.g], table[b.b], b.a / 255.0f};
    }
    return glm::vec4(b) / 255.0f;
}

glm::vec4 TextureSampler::lookup(const TexCoords& tc) const {
    const glm::vec2 p = uv(tc);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return texel(0, 0);
    // glTF puts uv (0, 0) at the image's top-left corner, as TextureImage's row 0 is the top.
    const int w = image_->width, h = image_->height;
    const float x = p.x * w, y = p.y * h;
    if (ref_.nearest)
        return texel(wrapIndex(floorIndex(x), w, ref_.wrapS), wrapIndex(floorIndex(y), h, ref_.wrapT));
    const long long x0 = floorIndex(x - 0.5f), y0 = floorIndex(y - 0.5f);
    const float tx = (x - 0.5f) - float(x0), ty = (y - 0.5f) - float(y0);
    const int xa = wrapIndex(x0, w, ref_.wrapS), xb = wrapIndex(x0 + 1, w, ref_.wrapS);
    const int ya = wrapIndex(y0, h, ref_.wrapT), yb = wrapIndex(y0 + 1, h, ref_.wrapT);
    return (1.0f - ty) * ((1.0f - tx) * texel(xa, ya) + tx * texel(xb, ya)) +
           ty * ((1.0f - tx) * texel(xa, yb) + tx * texel(xb, yb));
}

}  // namespace woven
