#include "albedo_demodulation.h"

#include <algorithm>

#include <glm/common.hpp>
#include <tbb/parallel_for.h>

namespace woven {

Demodulated demodulate(const DenoiseBuffers& b) {
    const size_t n = b.pixels();
    Demodulated d{Planes3(n), Planes3(n), Planes3(n)};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& range) {
        for (size_t i = range.begin(); i != range.end(); ++i) {
            if (!b.usable(i)) {
                for (int c = 0; c < 3; ++c) d.divisor.c[c][i] = 1.0f;
                continue;
            }
            glm::vec3 divisor(1.0f);
            if (!b.albedo.empty()) {
                const glm::vec3 a = glm::max(b.albedo[i], glm::vec3(0.0f));
                if (std::max({a.x, a.y, a.z}) > kAlbedoFloor) divisor = a + kAlbedoFloor;
            }
            for (int c = 0; c < 3; ++c) {
                d.divisor.c[c][i] = divisor[c];
                d.irradiance.c[c][i] = b.color[i][c] / divisor[c];
                d.variance.c[c][i] = b.variance[i][c] / (divisor[c] * divisor[c]);
            }
        }
    });
    return d;
}

}  // namespace woven
