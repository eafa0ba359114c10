// Cost of one BSDF query: the bare Ashikhmin-Shirley lobe against the full woven material
// (pattern lookup, yarn geometry, bump frame, noise, then the lobe), with the woven features
// off and on, and a 1024 x 1024-thread draft against the plain weave (1,1,1). The full/bare
// ratio is what the weave adds per shading point; and the same with yarns that transmit.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "ashikhmin_shirley.h"
#include "transmitting_yarn.h"
#include "woven_material.h"

using namespace woven;

namespace {

constexpr size_t kQueries = 4096;  // power of two: cycle with a mask

// Pre-generated inputs, so the timed loop measures the BSDF and not the random generator.
struct Queries {
    std::vector<glm::vec3> wo, wi;
    std::vector<glm::vec2> u;
    std::vector<float> uc;
    std::vector<glm::dvec2> uv;
    Queries() {
        std::mt19937 rng(1234);
        std::uniform_real_distribution<float> uni(0.0f, 1.0f);
        auto hemisphere = [&] {
            float z = uni(rng), phi = 6.2831853f * uni(rng), r = std::sqrt(1.0f - z * z);
            return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
        };
        for (size_t i = 0; i < kQueries; ++i) {
            wo.push_back(hemisphere());
            wi.push_back(hemisphere());
            u.emplace_back(uni(rng), uni(rng));
            uc.push_back(uni(rng));
            uv.emplace_back(20.0 * uni(rng), 20.0 * uni(rng));
        }
    }
};

const Queries& queries() {
    static const Queries q;
    return q;
}

WovenParams featuresOff() {
    WovenParams p;
    p.pattern = {9, 1, 3};
    p.cy = 0.0f;
    p.yarn_width = p.warp_width = 1.0f;
    p.noise = 0.0f;
    p.crimp = 0.0f;
    return p;
}

// The plain weave (1,1,1) with every feature off: the reference a draft is measured against.
WovenParams plainWeave() {
    WovenParams p = featuresOff();
    p.pattern = {1, 1, 1};
    return p;
}

// A draft of n x n threads with everything per thread: a random tile (fixed seed: no structure
// the caches could exploit), a colour and one of four yarn types per end and per pick, uneven
// spacing (0.5 to 1.5) when `spaced`. The queries span 1280 threads each way, more than the
// largest tile; n = 16 against n = 1024 shows the cost does not grow with the draft.
WovenParams draft(int n, bool spaced) {
    WovenParams p = featuresOff();
    std::mt19937 rng(99);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    p.tile.assign(size_t(n), std::string(size_t(n), '-'));
    for (std::string& row : p.tile)
        for (char& c : row) c = uni(rng) < 0.5f ? '|' : '-';
    for (int f = 0; f < 4; ++f) {
        YarnSpec yarn;
        yarn.value[kYarnEx] = 50.0f + 100.0f * f;
        yarn.value[kYarnWidth] = 0.7f + 0.1f * f;
        yarn.set[kYarnEx] = yarn.set[kYarnWidth] = true;
        p.yarns.push_back(yarn);
    }
    for (int t = 0; t < n; ++t) {
        p.warp_colors.emplace_back(uni(rng), uni(rng), uni(rng));
        p.weft_colors.emplace_back(uni(rng), uni(rng), uni(rng));
        p.warp_yarns.push_back(int(rng() % 4));
        p.weft_yarns.push_back(int(rng() % 4));
        if (spaced) {
            p.warp_spacing.push_back(0.5f + uni(rng));
            p.weft_spacing.push_back(0.5f + uni(rng));
        }
    }
    p.repeat = glm::vec2(64.0f);
    return p;
}

WovenParams featuresOn() {
    WovenParams p = featuresOff();
    p.cy = 0.75f;
    p.noise = 0.3f;
    p.crimp = 0.5f;
    p.yarn_width = p.warp_width = 0.8f;
    p.backing = 1;
    p.backing_color = glm::vec3(0.1f);
    return p;
}

const AshikhminShirley bareLobe(100.0f, 2.0f, 0.04f, glm::vec3(0.55f, 0.12f, 0.10f));

void BM_BareEval(benchmark::State& state) {
    const Queries& q = queries();
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(bareLobe.eval(q.wo[i], q.wi[i]));
        i = (i + 1) & (kQueries - 1);
    }
}

void BM_BareSample(benchmark::State& state) {
    const Queries& q = queries();
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(bareLobe.sample(q.wo[i], q.u[i], q.uc[i]));
        i = (i + 1) & (kQueries - 1);
    }
}

ShadingInput hitAt(const glm::dvec2& uv) {
    ShadingInput in;
    in.uv = uv;
    return in;
}

void BM_WovenShadeEval(benchmark::State& state, const WovenParams& params) {
    const WovenMaterial material(params);
    const Queries& q = queries();
    size_t i = 0;
    for (auto _ : state) {
        auto s = material.shade(hitAt(q.uv[i]));
        if (s) benchmark::DoNotOptimize(s->bsdf.eval(q.wo[i], q.wi[i]));
        benchmark::DoNotOptimize(s);
        i = (i + 1) & (kQueries - 1);
    }
}

// shade() alone: the weave lookup, yarn geometry and frame a shading point costs, without the lobe.
void BM_WovenShade(benchmark::State& state, const WovenParams& params) {
    const WovenMaterial material(params);
    const Queries& q = queries();
    size_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(material.shade(hitAt(q.uv[i])));
        i = (i + 1) & (kQueries - 1);
    }
}

void BM_WovenShadeSample(benchmark::State& state, const WovenParams& params) {
    const WovenMaterial material(params);
    const Queries& q = queries();
    size_t i = 0;
    for (auto _ : state) {
        auto s = material.shade(hitAt(q.uv[i]));
        if (s) benchmark::DoNotOptimize(s->bsdf.sample(q.wo[i], q.u[i], q.uc[i]));
        benchmark::DoNotOptimize(s);
        i = (i + 1) & (kQueries - 1);
    }
}

// A material whose yarns transmit (docs/MODEL_TRANSMISSION.md): shade() also looks up the other
// face's yarn, and the point's BSDF evaluates reflection and transmission, wi on either side.
void BM_WovenTransmittingShadeEval(benchmark::State& state, WovenParams params) {
    params.transmission = 0.5f;
    const WovenMaterial material(params);
    const Queries& q = queries();
    size_t i = 0;
    for (auto _ : state) {
        auto s = material.shade(hitAt(q.uv[i]));
        const glm::vec3 wi = (i & 1) ? q.wi[i] : -q.wi[i];
        if (s && s->transmission) benchmark::DoNotOptimize(transmittingYarn(s->bsdf, *s->transmission).eval(q.wo[i], wi));
        benchmark::DoNotOptimize(s);
        i = (i + 1) & (kQueries - 1);
    }
}

// The weave filter's BSDF (shadeFiltered + eval) over a footprint of `elements` weave elements:
// from one element on the far field alone (a mixture of 8 cross-section lobes per yarn, fewer for
// flat yarns), below it blended with the exact lobe.
void BM_WovenFilteredShadeEval(benchmark::State& state, const WovenParams& params, double elements) {
    const WovenMaterial material(params);
    const Queries& q = queries();
    size_t i = 0;
    for (auto _ : state) {
        ShadingInput in = hitAt(q.uv[i]);
        in.duvdx = glm::dvec2(2.0 * elements / params.repeat.x, 0.0);  // the filter takes half the pixel
        in.duvdy = glm::dvec2(0.0, 2.0 * elements / params.repeat.y);
        auto s = material.shadeFiltered(in);
        if (s) benchmark::DoNotOptimize(s->eval(q.wo[i], q.wi[i]));
        benchmark::DoNotOptimize(s);
        i = (i + 1) & (kQueries - 1);
    }
}

}  // namespace

BENCHMARK(BM_BareEval);
BENCHMARK(BM_BareSample);
BENCHMARK_CAPTURE(BM_WovenShade, plain_111, plainWeave());
BENCHMARK_CAPTURE(BM_WovenShade, draft_16_even, draft(16, false));
BENCHMARK_CAPTURE(BM_WovenShade, draft_1024_even, draft(1024, false));
BENCHMARK_CAPTURE(BM_WovenShade, draft_16_spaced, draft(16, true));
BENCHMARK_CAPTURE(BM_WovenShade, draft_1024_spaced, draft(1024, true));
BENCHMARK_CAPTURE(BM_WovenShadeEval, plain_111, plainWeave());
BENCHMARK_CAPTURE(BM_WovenShadeEval, draft_1024_even, draft(1024, false));
BENCHMARK_CAPTURE(BM_WovenShadeEval, draft_1024_spaced, draft(1024, true));
BENCHMARK_CAPTURE(BM_WovenShadeEval, features_off, featuresOff());
BENCHMARK_CAPTURE(BM_WovenShadeSample, features_off, featuresOff());
BENCHMARK_CAPTURE(BM_WovenShadeEval, features_on, featuresOn());
BENCHMARK_CAPTURE(BM_WovenShadeSample, features_on, featuresOn());
BENCHMARK_CAPTURE(BM_WovenTransmittingShadeEval, features_on, featuresOn());
BENCHMARK_CAPTURE(BM_WovenFilteredShadeEval, far_flat, featuresOff(), 4.0);
BENCHMARK_CAPTURE(BM_WovenFilteredShadeEval, far_cy_075, featuresOn(), 4.0);
BENCHMARK_CAPTURE(BM_WovenFilteredShadeEval, blend_cy_075, featuresOn(), 0.5);
