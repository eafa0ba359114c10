#include "bvh_light_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "math_constants.h"

namespace woven {

namespace {
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

enum : int8_t { kNever = 0, kInTree = 1, kInfinite = 2 };

// Below this depth splits are by SAH; deeper ones halve the lights, so that every path down the
// tree fits trail_'s 64 bits (2^27 lights need 27 more levels).
constexpr int kMaxSahDepth = 32;
constexpr int kBuckets = 12;

// The cost of a group in pbrt-v4's surface area orientation heuristic: its power, times the
// solid angle its emission cone spans (M_omega), times its box's area, over how elongated the
// parent is along the split axis.
float cost(const LightBounds& b, const Bounds& parent, int axis) {
    const float thetaO = std::acos(std::clamp(b.cone.cosTheta, -1.0f, 1.0f));
    const float thetaE = std::acos(std::clamp(b.cosThetaE, -1.0f, 1.0f));
    const float thetaW = std::min(thetaO + thetaE, kPi);
    const float sinThetaO = std::sqrt(std::max(0.0f, 1.0f - b.cone.cosTheta * b.cone.cosTheta));
    const float mOmega = 2.0f * kPi * (1.0f - b.cone.cosTheta) +
                         kPi / 2.0f * (2.0f * thetaW * sinThetaO - std::cos(thetaO - 2.0f * thetaW) -
                                       2.0f * thetaO * sinThetaO + b.cone.cosTheta);
    const glm::vec3 extent = parent.hi - parent.lo;
    const float kr = extent[axis] > 0.0f ? std::max(extent.x, std::max(extent.y, extent.z)) / extent[axis] : 1.0f;
    const glm::vec3 d = b.bounds.hi - b.bounds.lo;
    const float area = 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
    return b.phi * mOmega * kr * area;
}

// Child 0 or 1 of an inner node by the children's importances, and its probability.
float childProbability(float importance0, float importance1, int child) {
    return (child == 0 ? importance0 : importance1) / (importance0 + importance1);
}

}  // namespace

BvhLightSampler::BvhLightSampler(const std::vector<Light>& lights)
    : trail_(lights.size(), 0), where_(lights.size(), kNever) {
    std::vector<std::pair<int, LightBounds>> bvhLights;
    std::vector<float> infinitePower;
    double finitePower = 0.0, totalInfinitePower = 0.0;
    for (size_t i = 0; i < lights.size(); ++i) {
        if (lights[i].isInfinite()) {
            trail_[i] = infinite_.size();  // its place among the infinite lights
            where_[i] = kInfinite;
            infinite_.push_back(int(i));
            infinitePower.push_back(std::max(luminance(lights[i].power()), 0.0f));
            totalInfinitePower += infinitePower.back();
        } else if (const std::optional<LightBounds> b = boundsOf(lights[i])) {
            where_[i] = kInTree;
            bvhLights.emplace_back(int(i), *b);
            finitePower += b->phi;
        }
    }
    if (!infinite_.empty()) {
        infiniteChoice_.emplace(infinitePower);
        // By power, as PowerLightSampler divides it between them and the rest.
        pInfinite_ = bvhLights.empty() ? 1.0f
                     : totalInfinitePower > 0.0 ? float(totalInfinitePower / (totalInfinitePower + finitePower))
                                                : 0.0f;
    }
    if (!bvhLights.empty()) build(bvhLights, 0, bvhLights.size(), 0, 0);
}

LightBounds BvhLightSampler::build(std::vector<std::pair<int, LightBounds>>& bvhLights, size_t begin, size_t end,
                                   uint64_t bits, int depth) {
    if (end - begin == 1) {
        const auto& [light, bounds] = bvhLights[begin];
        nodes_.push_back({LightImportance(bounds), light, true});
        trail_[size_t(light)] = bits;
        return bounds;
    }
    Bounds all, centroids;
    for (size_t i = begin; i < end; ++i) {
        const Bounds& b = bvhLights[i].second.bounds;
        all = {glm::min(all.lo, b.lo), glm::max(all.hi, b.hi)};
        centroids = {glm::min(centroids.lo, b.centre()), glm::max(centroids.hi, b.centre())};
    }
    // The split of least cost among kBuckets - 1 planes on each axis (pbrt-v4's buildBVH).
    float bestCost = std::numeric_limits<float>::infinity();
    int bestAxis = -1, bestBucket = -1;
    const auto bucketOf = [&](const LightBounds& b, int axis) {
        const float extent = centroids.hi[axis] - centroids.lo[axis];
        return std::min(kBuckets - 1, int(kBuckets * (b.bounds.centre()[axis] - centroids.lo[axis]) / extent));
    };
    for (int axis = 0; axis < 3 && depth < kMaxSahDepth; ++axis) {
        if (!(centroids.hi[axis] > centroids.lo[axis])) continue;
        std::array<LightBounds, kBuckets> buckets{};
        for (size_t i = begin; i < end; ++i) {
            LightBounds& bucket = buckets[size_t(bucketOf(bvhLights[i].second, axis))];
            bucket = unionOf(bucket, bvhLights[i].second);
        }
        for (int split = 0; split < kBuckets - 1; ++split) {
            LightBounds below, above;
            for (int k = 0; k <= split; ++k) below = unionOf(below, buckets[size_t(k)]);
            for (int k = split + 1; k < kBuckets; ++k) above = unionOf(above, buckets[size_t(k)]);
            if (below.phi == 0.0f || above.phi == 0.0f) continue;
            const float c = cost(below, all, axis) + cost(above, all, axis);
            if (c > 0.0f && c < bestCost) {
                bestCost = c;
                bestAxis = axis;
                bestBucket = split;
            }
        }
    }
    size_t middle = (begin + end) / 2;
    if (bestAxis >= 0) {
        const auto first = bvhLights.begin() + std::ptrdiff_t(begin), last = bvhLights.begin() + std::ptrdiff_t(end);
        const size_t split = size_t(std::partition(first, last, [&](const auto& l) {
                                        return bucketOf(l.second, bestAxis) <= bestBucket;
                                    }) - bvhLights.begin());
        if (split != begin && split != end) middle = split;
    }
    const size_t node = nodes_.size();
    nodes_.emplace_back();
    const LightBounds first = build(bvhLights, begin, middle, bits, depth + 1);
    nodes_[node].childOrLight = int(nodes_.size());
    const LightBounds second = build(bvhLights, middle, end, bits | uint64_t(1) << depth, depth + 1);
    const LightBounds both = unionOf(first, second);
    nodes_[node].importance = LightImportance(both);
    return both;
}

int BvhLightSampler::sample(const LightSampleContext& ctx, float u, float* pmf) const {
    *pmf = 0.0f;
    if (u < pInfinite_) {
        float choice = 0.0f;
        const int i = infiniteChoice_->sampleDiscrete(std::min(u / pInfinite_, kOneMinusEpsilon), &choice);
        *pmf = pInfinite_ * choice;
        return infinite_[size_t(i)];
    }
    if (nodes_.empty()) return -1;
    u = std::min((u - pInfinite_) / (1.0f - pInfinite_), kOneMinusEpsilon);
    float p = 1.0f - pInfinite_;
    for (size_t at = 0;;) {
        const Node& node = nodes_[at];
        if (node.leaf) {
            *pmf = p;
            return node.childOrLight;
        }
        const size_t second = size_t(node.childOrLight);
        const float i0 = nodes_[at + 1].importance(ctx.p, ctx.n), i1 = nodes_[second].importance(ctx.p, ctx.n);
        if (!(i0 + i1 > 0.0f)) return -1;
        const float p0 = childProbability(i0, i1, 0);
        if (u < p0) {
            u = std::min(u / p0, kOneMinusEpsilon);
            p *= p0;
            at = at + 1;
        } else {
            u = std::min((u - p0) / (1.0f - p0), kOneMinusEpsilon);
            p *= childProbability(i0, i1, 1);
            at = second;
        }
    }
}

float BvhLightSampler::pmf(const LightSampleContext& ctx, int index) const {
    if (index < 0 || size_t(index) >= where_.size() || where_[size_t(index)] == kNever) return 0.0f;
    if (where_[size_t(index)] == kInfinite) return pInfinite_ * infiniteChoice_->discretePmf(int(trail_[size_t(index)]));
    float p = 1.0f - pInfinite_;
    uint64_t bits = trail_[size_t(index)];
    for (size_t at = 0; !nodes_[at].leaf; bits >>= 1) {
        const size_t second = size_t(nodes_[at].childOrLight);
        const float i0 = nodes_[at + 1].importance(ctx.p, ctx.n), i1 = nodes_[second].importance(ctx.p, ctx.n);
        if (!(i0 + i1 > 0.0f)) return 0.0f;
        const int child = int(bits & 1);
        p *= childProbability(i0, i1, child);
        at = child == 0 ? at + 1 : second;
    }
    return p;
}

}  // namespace woven
