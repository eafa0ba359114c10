#include "filtered_weave_lobe.h"

#include <algorithm>
#include <cmath>

namespace woven {

namespace {
// eval() divides by |cos| to the surface normal, but by no less than this: f cos stays finite as
// cos -> 0, f alone would not, and BDPT's shading-normal correction divides by |cos| once more
// (an outlier of relMSE 3.7 in a converge run of the satin at 1e-6). Within 3 degrees of the
// surface f cos is under-counted by |cos| / kMinCos.
constexpr float kMinCos = 0.05f;
}  // namespace

FilteredWeaveLobe::FilteredWeaveLobe(const WeaveFarField& farField, const glm::vec3 (&colors)[3],
                                     const glm::vec3& scales, float farWeight, const Frame& nearFrame,
                                     const AshikhminShirley& nearLobe)
    : farField_(&farField), colors_{colors[0], colors[1], colors[2]},
      weights_{farWeight * scales[0], farWeight * scales[1], farWeight * scales[2]}, farWeight_(farWeight),
      nearFrame_(nearFrame), nearLobe_(nearLobe) {}

void FilteredWeaveLobe::evalAndPdf(const glm::vec3& wo, const glm::vec3& wi, glm::vec3* fCos, float* pdf) const {
    glm::vec3 f(0.0f);
    float p = 0.0f;
    auto add = [&](const Frame& frame, const AshikhminShirley& l, float weight) {
        const glm::vec3 o = frame.toLocal(wo), i = frame.toLocal(wi);
        if (o.z <= 0.0f || i.z <= 0.0f) return;
        if (fCos) f += weight * i.z * l.eval(o, i);
        if (pdf) p += weight * l.pdf(o, i);
    };
    if (farWeight_ < 1.0f) add(nearFrame_, nearLobe_, 1.0f - farWeight_);
    if (farWeight_ > 0.0f)
        for (const FarFieldLobe& l : farField_->lobes()) add(l.frame, lobe(l), weights_[int(l.color)] * l.weight);
    if (fCos) *fCos = f;
    if (pdf) *pdf = p;
}

glm::vec3 FilteredWeaveLobe::albedo() const {
    glm::vec3 a = (1.0f - farWeight_) * nearLobe_.albedo();
    if (farWeight_ > 0.0f)
        for (const FarFieldLobe& l : farField_->lobes()) a += weights_[int(l.color)] * l.weight * lobe(l).albedo();
    return a;
}

glm::vec3 FilteredWeaveLobe::eval(const glm::vec3& wo, const glm::vec3& wi) const {
    glm::vec3 fCos;
    evalAndPdf(wo, wi, &fCos, nullptr);
    return fCos / std::max(std::fabs(wi.z), kMinCos);
}

float FilteredWeaveLobe::pdf(const glm::vec3& wo, const glm::vec3& wi) const {
    float p;
    evalAndPdf(wo, wi, nullptr, &p);
    return p;
}

std::optional<BsdfSample> FilteredWeaveLobe::sample(const glm::vec3& wo, const glm::vec2& u, float uc) const {
    // Pick a lobe by its weight, then reuse what is left of uc for the lobe's own choice.
    auto sampleWith = [&](const Frame& frame, const AshikhminShirley& l, float ucLobe) -> std::optional<BsdfSample> {
        const glm::vec3 o = frame.toLocal(wo);
        const auto s = l.sample(o, u, std::min(ucLobe, 0x1.fffffep-1f));
        if (!s) return std::nullopt;
        BsdfSample out;
        out.wi = frame.toWorld(s->wi);
        glm::vec3 fCos;
        evalAndPdf(wo, out.wi, &fCos, &out.pdf);
        if (!(out.pdf > 0.0f) || !std::isfinite(out.pdf)) return std::nullopt;
        out.f = fCos / std::max(std::fabs(out.wi.z), kMinCos);
        out.weight = fCos / out.pdf;
        return out;
    };
    float c = uc;
    if (farWeight_ < 1.0f) {
        const float w = 1.0f - farWeight_;
        if (c < w || farWeight_ <= 0.0f) return sampleWith(nearFrame_, nearLobe_, c / w);
        c -= w;
    }
    const std::vector<FarFieldLobe>& lobes = farField_->lobes();
    for (size_t k = 0; k < lobes.size(); ++k) {
        const float w = weights_[int(lobes[k].color)] * lobes[k].weight;
        // Rounding leaves the shares' sum a hair off 1: the last lobe takes what is left.
        if (c < w) return sampleWith(lobes[k].frame, lobe(lobes[k]), c / w);
        c -= w;
    }
    // Rounding left uc a hair past the weights' sum: the last lobe that can be chosen.
    for (size_t k = lobes.size(); k-- > 0;) {
        const float w = weights_[int(lobes[k].color)] * lobes[k].weight;
        if (w > 0.0f) return sampleWith(lobes[k].frame, lobe(lobes[k]), 1.0f);
    }
    return std::nullopt;
}

}  // namespace woven
