#pragma once
// Which light a path vertex's light sample takes, by what each could send to that vertex: a
// bounding volume hierarchy over the finite lights' LightBounds, walked from the root choosing
// each child by its importance (pbrt-v4's BVHLightSampler, after Conty Estevez and Kulla 2018,
// as Cycles 3.5's light tree does). In a room of many lamps the near ones get the samples,
// where PowerLightSampler spreads them by power alone (docs/RESULTS.md). Infinite lights (the
// environment, directional lights) are outside the tree and chosen by power against its total.
#include <cstdint>
#include <optional>
#include <vector>

#include "light.h"
#include "light_bounds.h"
#include "piecewise_constant.h"

namespace woven {

// Where a light sample is taken from: a point and, on a surface, its shading normal (zero
// elsewhere).
struct LightSampleContext {
    glm::vec3 p{0.0f}, n{0.0f};
};

class BvhLightSampler {
public:
    // The lights with their scene bounds set (infinite lights' power depends on them).
    explicit BvhLightSampler(const std::vector<Light>& lights);

    // A light's index for u in [0, 1) and its probability from ctx; -1 (and 0) when no light
    // can reach ctx.
    int sample(const LightSampleContext& ctx, float u, float* pmf) const;
    // The probability that sample() gives `index` from ctx: 0 for an index outside the lights.
    float pmf(const LightSampleContext& ctx, int index) const;

private:
    struct Node {
        LightImportance importance;
        // An inner node's second child (its first follows it), or a leaf's light.
        int childOrLight = 0;
        bool leaf = false;
    };
    // Appends the subtree of lights [begin, end) of `bvhLights` and returns its bounds; each
    // leaf's light gets the bits of the way down to it, the first step in bit 0.
    LightBounds build(std::vector<std::pair<int, LightBounds>>& bvhLights, size_t begin, size_t end, uint64_t bits, int depth);

    std::vector<Node> nodes_;
    // Per light in the tree: its path down it (bit d set: the second child at depth d); per
    // infinite light: its place in infinite_.
    std::vector<uint64_t> trail_;
    std::vector<int8_t> where_;     // per light: kInTree, kInfinite or kNever
    std::vector<int> infinite_;     // the infinite lights' indices
    std::optional<PiecewiseConstant1D> infiniteChoice_;  // among them, by power
    float pInfinite_ = 0.0f;        // the chance of an infinite light: their share of the power
};

}  // namespace woven
