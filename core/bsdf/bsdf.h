#pragma once
// The BSDF at a hit as the integrators use it: any of woven's lobes in its shading frame. A
// value type (a variant, no allocation per hit), so a path keeps its vertices' BSDFs by value.
#include <utility>
#include <variant>

#include "filtered_weave_lobe.h"
#include "gltf_bxdf.h"
#include "surface_bsdf.h"
#include "transmitting_yarn.h"

namespace woven {

class Bxdf {
public:
    Bxdf(const AshikhminShirley& lobe) : lobe_(lobe) {}
    Bxdf(const GltfBxdf& lobe) : lobe_(lobe) {}
    Bxdf(const FilteredWeaveLobe& lobe) : lobe_(lobe) {}
    Bxdf(const TransmittingYarn& lobe) : lobe_(lobe) {}
    // A lobe of type L built in place from its constructor's arguments (FramedLobe's in-place
    // constructor), not copied in.
    template <class L, class... Args>
    explicit Bxdf(std::in_place_type_t<L> type, Args&&... args) : lobe_(type, std::forward<Args>(args)...) {}

    glm::vec3 eval(const glm::vec3& wo, const glm::vec3& wi) const {
        return std::visit([&](const auto& l) { return l.eval(wo, wi); }, lobe_);
    }
    float pdf(const glm::vec3& wo, const glm::vec3& wi) const {
        return std::visit([&](const auto& l) { return l.pdf(wo, wi); }, lobe_);
    }
    std::optional<BsdfSample> sample(const glm::vec3& wo, const glm::vec2& u, float uc) const {
        return std::visit([&](const auto& l) { return l.sample(wo, u, uc); }, lobe_);
    }
    bool choosesLobe() const {
        return std::visit([](const auto& l) { return l.choosesLobe(); }, lobe_);
    }
    bool transmits() const {
        return std::visit([](const auto& l) { return l.transmits(); }, lobe_);
    }
    glm::vec3 albedo() const {
        return std::visit([](const auto& l) { return l.albedo(); }, lobe_);
    }

    // The yarn that transmits this is, if it is one.
    const TransmittingYarn* transmittingYarn() const { return std::get_if<TransmittingYarn>(&lobe_); }

private:
    std::variant<AshikhminShirley, GltfBxdf, FilteredWeaveLobe, TransmittingYarn> lobe_;
};

using Bsdf = FramedLobe<Bxdf>;

// The woven model's per-yarn BSDF as a Bsdf.
inline Bsdf toBsdf(const SurfaceBsdf& b) { return Bsdf(b.frame(), Bxdf(b.lobe())); }
// The woven model filtered over a footprint as a Bsdf.
inline Bsdf toBsdf(const FramedLobe<FilteredWeaveLobe>& b) { return Bsdf(b.frame(), Bxdf(b.lobe())); }
// A yarn that reflects and transmits as a Bsdf.
inline Bsdf toBsdf(const FramedLobe<TransmittingYarn>& b) { return Bsdf(b.frame(), Bxdf(b.lobe())); }

// The normal the integrators take the cosine factor of wo, wi about: the shading normal, but
// where a yarn passes light between them its transmission's (TransmittingYarn::cosineNormal()).
inline glm::vec3 cosineNormal(const Bsdf& b, const glm::vec3& wo, const glm::vec3& wi) {
    const TransmittingYarn* yarn = b.lobe().transmittingYarn();
    if (!yarn) return b.shadingNormal();
    return b.frame().toWorld(yarn->cosineNormal(b.frame().toLocal(wo), b.frame().toLocal(wi)));
}

}  // namespace woven
