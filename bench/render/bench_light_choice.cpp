// What choosing a light costs per light sample: PowerLightSampler (BDPT's, and the path tracer's
// before the light BVH) against BvhLightSampler, on the Lambert box's lamp (2 triangles) and on
// the 64-lamp room's ceiling (128 triangles), from random points of the room with normals. One
// thread; the best of 5 runs of 2^21 choices each.
#include <chrono>
#include <cstdio>
#include <vector>

#include "bvh_light_sampler.h"
#include "light_sampler.h"
#include "sampling.h"

namespace {

using namespace woven;

std::vector<Light> lampTriangles(int lampsPerSide, float spacing, float side, float y) {
    std::vector<Light> lights;
    Rng rng(23);
    for (int i = 0; i < lampsPerSide; ++i)
        for (int j = 0; j < lampsPerSide; ++j) {
            const float x = (i - 0.5f * (lampsPerSide - 1)) * spacing, z = (j - 0.5f * (lampsPerSide - 1)) * spacing;
            const glm::vec3 a(x - side / 2, y, z - side / 2), b(x + side / 2, y, z - side / 2), c(x + side / 2, y, z + side / 2),
                d(x - side / 2, y, z + side / 2);
            const glm::vec3 L(std::pow(10.0f, 1.0f + 3.0f * rng.uniform()));
            lights.push_back(Light::triangle(a, b, c, L, false));  // facing down
            lights.push_back(Light::triangle(a, c, d, L, false));
        }
    return lights;
}

template <class Choose>
double nanosecondsPerChoice(const std::vector<LightSampleContext>& contexts, Choose&& choose) {
    double best = 1e30;
    for (int run = 0; run < 5; ++run) {
        int chosen = 0;
        const auto start = std::chrono::steady_clock::now();
        for (size_t k = 0; k < contexts.size(); ++k) {
            float pmf = 0.0f;
            chosen += choose(contexts[k], (float(k) + 0.5f) / float(contexts.size()), &pmf) >= 0;
        }
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (chosen == 0) std::printf("(nothing chosen)\n");
        best = std::min(best, s * 1e9 / double(contexts.size()));
    }
    return best;
}

}  // namespace

int main() {
    std::vector<LightSampleContext> contexts(size_t(1) << 21);
    Rng rng(5);
    for (LightSampleContext& c : contexts) {
        c.p = {8.0f * rng.uniform() - 4.0f, 2.9f * rng.uniform(), 8.0f * rng.uniform() - 4.0f};
        c.n = sampleUniformSphere({rng.uniform(), rng.uniform()});
    }
    struct Case {
        const char* name;
        std::vector<Light> lights;
    };
    const Case cases[] = {{"box lamp, 2 triangles", lampTriangles(1, 0.0f, 0.5f, 2.98f)},
                          {"64 lamps, 128 triangles", lampTriangles(8, 1.0f, 0.1f, 2.98f)}};
    std::printf("| lights | power choice ns | light BVH ns (pmf ns) |\n|---|---:|---:|\n");
    for (const Case& c : cases) {
        const PowerLightSampler power(c.lights);
        const BvhLightSampler tree(c.lights);
        const double p = nanosecondsPerChoice(contexts, [&](const LightSampleContext&, float u, float* pmf) {
            return power.sample(u, pmf);
        });
        const double t = nanosecondsPerChoice(contexts, [&](const LightSampleContext& ctx, float u, float* pmf) {
            return tree.sample(ctx, u, pmf);
        });
        const double q = nanosecondsPerChoice(contexts, [&](const LightSampleContext& ctx, float u, float* pmf) {
            *pmf = tree.pmf(ctx, int(u * float(c.lights.size())));
            return 0;
        });
        std::printf("| %s | %.1f | %.1f (%.1f) |\n", c.name, p, t, q);
    }
    return 0;
}
