#pragma once
// The random numbers of one camera sample, by dimension (sample_dimensions.h): a pure function of
// (seed, pixel, sample index, dimension), so disjoint sample ranges rendered anywhere merge into
// exactly the render of their union. A value type (a variant, no allocation per sample).
#include <cstdint>
#include <string>
#include <variant>

#include "sampling.h"
#include "sobol_sampler.h"

namespace woven {

// Independent PCG numbers (Rng), drawn in the order the integrators ask for them whatever the
// dimension: for comparison and for tests that need independent samples.
class IndependentSampler {
public:
    IndependentSampler(uint64_t seed, uint64_t pixel, uint64_t sampleIndex) : rng_(seed, pixel, sampleIndex) {}
    float get1D(uint32_t) { return rng_.uniform(); }
    glm::vec2 get2D(uint32_t) { return rng_.uniform2(); }

private:
    Rng rng_;
};

enum class SamplerKind { Independent, Sobol };
// --sampler's names, in SamplerKind's order.
inline constexpr const char* kSamplerNames[] = {"independent", "sobol"};

// Throws std::invalid_argument naming the known ones.
SamplerKind samplerKind(const std::string& name);
inline const char* samplerName(SamplerKind kind) { return kSamplerNames[int(kind)]; }

class Sampler {
public:
    Sampler(SamplerKind kind, uint64_t seed, uint64_t pixel, uint64_t sampleIndex)
        : sampler_(kind == SamplerKind::Sobol ? Variant(SobolSampler(seed, pixel, sampleIndex))
                                              : Variant(IndependentSampler(seed, pixel, sampleIndex))) {}

    float get1D(uint32_t dimension) {
        return std::visit([&](auto& s) { return s.get1D(dimension); }, sampler_);
    }
    glm::vec2 get2D(uint32_t dimension) {
        return std::visit([&](auto& s) { return s.get2D(dimension); }, sampler_);
    }

private:
    using Variant = std::variant<IndependentSampler, SobolSampler>;
    Variant sampler_;
};

}  // namespace woven
