#include "denoise_buffers.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace woven {

namespace {
bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

bool DenoiseBuffers::usable(size_t pixel) const {
    const glm::vec3& v = variance[pixel];
    return finite(color[pixel]) && finite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f &&
           (albedo.empty() || finite(albedo[pixel])) && (normal.empty() || finite(normal[pixel])) &&
           (direct.empty() || finite(direct[pixel])) && (directVariance.empty() || finite(directVariance[pixel])) &&
           (depth.empty() || !std::isnan(depth[pixel]));
}

void checkDenoiseBuffers(const DenoiseBuffers& b) {
    if (b.width <= 0 || b.height <= 0) throw std::invalid_argument("denoise: the frame has no pixels");
    const size_t n = b.pixels();
    auto check = [n](size_t size, const char* name, bool optional) {
        if ((optional && size == 0) || size == n) return;
        throw std::invalid_argument(std::string("denoise: the ") + name + " buffer has " + std::to_string(size) +
                                    " pixels, the frame " + std::to_string(n));
    };
    check(b.color.size(), "colour", false);
    check(b.variance.size(), "variance", false);
    check(b.albedo.size(), "albedo", true);
    check(b.normal.size(), "normal", true);
    check(b.depth.size(), "depth", true);
    check(b.direct.size(), "direct-light", true);
    check(b.directVariance.size(), "direct-light variance", true);
}

}  // namespace woven
