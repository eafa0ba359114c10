#include "far_field.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace woven {

const std::vector<DirectionPair>& farFieldDirections() {
    static const std::vector<DirectionPair> pairs = [] {
        // A Fibonacci spiral on the unit disk lifted to the hemisphere: n directions spread
        // cosine-weighted, turned by `turn`.
        const auto spiral = [](int k, int n, double turn) {
            const double r = std::sqrt((k + 0.5) / n), psi = k * 2.399963229728653 + turn;
            const double x = r * std::cos(psi), y = r * std::sin(psi);
            return glm::vec3(float(x), float(y), float(std::sqrt(std::max(0.0, 1.0 - x * x - y * y))));
        };
        std::vector<DirectionPair> all;
        for (int o = 0; o < 40; ++o)
            for (int i = 0; i < 32; ++i) all.push_back({spiral(o, 40, 0.5), spiral(i, 32, 0.0)});
        return all;
    }();
    return pairs;
}

std::vector<glm::dvec2> farFieldPoints(glm::dvec2 uvSize, int points) {
    // Roberts' R2 sequence: the plastic number's powers as the two strides.
    constexpr double g = 1.32471795724474602596;
    const glm::dvec2 stride(1.0 / g, 1.0 / (g * g));
    std::vector<glm::dvec2> all(size_t(std::max(points, 0)));
    for (size_t i = 0; i < all.size(); ++i) all[i] = glm::fract(0.5 + stride * double(i + 1)) * uvSize;
    return all;
}

SurfaceHit flatHit(glm::dvec2 uv) {
    SurfaceHit hit;
    hit.ng = hit.ns = glm::vec3(0.0f, 0.0f, 1.0f);
    hit.dpdu = glm::vec3(1.0f, 0.0f, 0.0f);
    hit.dpdv = glm::vec3(0.0f, 1.0f, 0.0f);
    hit.tex.uv[0] = glm::vec2(uv);
    hit.tex.hasUv = true;
    return hit;
}

std::vector<glm::vec3> farField(const SurfaceMaterial& material, const std::vector<glm::dvec2>& points,
                                const std::vector<DirectionPair>& directions) {
    // Fixed chunks summed in order: the same sums, to the last bit, on any number of threads.
    constexpr size_t kChunk = 64;
    const size_t chunks = (points.size() + kChunk - 1) / kChunk;
    std::vector<std::vector<glm::dvec3>> partial(chunks, std::vector<glm::dvec3>(directions.size(), glm::dvec3(0.0)));
    tbb::parallel_for(size_t(0), chunks, [&](size_t c) {
        std::vector<glm::dvec3>& s = partial[c];
        for (size_t p = c * kChunk; p < std::min(points.size(), (c + 1) * kChunk); ++p) {
            const SurfaceHit hit = flatHit(points[p]);
            if (material.passesThrough(hit.tex, 0.0f)) continue;
            std::optional<Bsdf> bsdf;
            for (size_t d = 0; d < directions.size(); ++d) {
                const DirectionPair& pair = directions[d];
                // One BSDF per view: the pairs come grouped by wo.
                if (d == 0 || pair.wo != directions[d - 1].wo) bsdf = material.bsdf(hit, pair.wo);
                if (!bsdf) continue;
                s[d] += glm::dvec3(bsdf->eval(pair.wo, pair.wi) * std::abs(glm::dot(pair.wi, bsdf->shadingNormal())));
            }
        }
    });
    std::vector<glm::dvec3> sums(directions.size(), glm::dvec3(0.0));
    for (const auto& s : partial)
        for (size_t d = 0; d < sums.size(); ++d) sums[d] += s[d];
    std::vector<glm::vec3> mean(sums.size());
    for (size_t i = 0; i < sums.size(); ++i) mean[i] = glm::vec3(sums[i] / double(std::max<size_t>(points.size(), 1)));
    return mean;
}

double relativeRmse(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& reference) {
    double error = 0.0, norm = 0.0;
    for (size_t i = 0; i < a.size() && i < reference.size(); ++i) {
        const glm::dvec3 d = glm::dvec3(a[i]) - glm::dvec3(reference[i]);
        error += glm::dot(d, d);
        norm += glm::dot(glm::dvec3(reference[i]), glm::dvec3(reference[i]));
    }
    return norm > 0.0 ? std::sqrt(error / norm) : 0.0;
}

}  // namespace woven
