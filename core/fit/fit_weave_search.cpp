#include "fitter.h"

#include "weave_candidates.h"
#include "weave_lattice.h"

namespace woven {

WovenParams Fitter::initialColours(WovenParams p) {
    p.weft_color = p.warp_color = glm::vec3(0.5f);
    const std::vector<Image> images = render(p);
    if (images.empty()) return p;
    const size_t first = size_t(std::find(fitsColours_.begin(), fitsColours_.end(), true) - fitsColours_.begin());
    glm::dvec3 photo(0.0), rendered(0.0);
    for (const glm::vec3& v : shots_[first].image.pixels) photo += glm::dvec3(v);
    for (const glm::vec3& v : images[first].pixels) rendered += glm::dvec3(v);
    const double e = shots_[first].photo.exposure.value_or(1.0f);
    for (int c = 0; c < 3; ++c)
        p.weft_color[c] = float(std::clamp(0.5 * photo[c] / std::max(e * rendered[c], 1e-9), 0.02, 0.9));
    p.warp_color = p.weft_color;
    evaluate(p, images, true);
    return p;
}

bool Fitter::chooseWeave(const WovenParams& start) {
    const std::vector<glm::ivec3> candidates = shortlist();
    if (solvesTransmission_) countBacklitShots(false);
    bool done = true;
    for (size_t c = 0; c < candidates.size(); ++c) {
        if (stop()) {
            result_.warnings.push_back("the time ran out during the weave search (" + std::to_string(c) + " of " +
                                       std::to_string(candidates.size()) + " weaves tried)");
            done = false;
            break;
        }
        stage_ = "weave " + std::to_string(c + 1) + "/" + std::to_string(candidates.size());
        WovenParams p = start;
        p.pattern = candidates[c];
        fitColours(p);
        // A lone weave is refined too where backlit shots join: each point of stage 4 then
        // costs three renders, and from the shot material's widths and gloss it ended where
        // the flash's loss was 7 times its truth's (the rig's plain weave, its weft 0.97
        // wide for 0.85).
        if (candidates.size() == 1 && !solvesTransmission_) {
            evaluate(p);
            continue;
        }
        p = rescaled(p);
        std::vector<double> x = encode(p);
        const Objective objective = [&](const std::vector<double>& v) { return evaluate(decode(v, p)); };
        minimise(x, objective, kShortlistRefineRenders);
    }
    if (solvesTransmission_) countBacklitShots(true);
    return done;
}

std::vector<glm::ivec3> Fitter::shortlist() const {
    for (size_t i = 0; i < shots_.size(); ++i) {
        if (!photoGrids_[i]) continue;
        return weaveShortlist(rankWeavesBySpectrum(shots_[i].image, photoGrids_[i]->ends, photoGrids_[i]->picks));
    }
    std::vector<glm::ivec3> all;
    for (const WeaveCandidate& c : weaveCandidates()) all.push_back(c.pattern);
    return all;
}

Fitter::ColourBasis Fitter::colourBasis(WovenParams p) {
    ColourBasis basis(shots_.size());
    if (oneRenderColourBasis_) {
        p.weft_color = glm::vec3(1.0f, 0.0f, 0.0f);
        p.warp_color = glm::vec3(0.0f, 1.0f, 0.0f);
        const std::vector<Image> images = render(p, fitsColours_);
        if (images.empty()) return {};
        for (size_t s = 0; s < shots_.size(); ++s) {
            basis[s] = {images[s], images[s], images[s]};
            for (size_t i = 0; i < images[s].pixels.size(); ++i) {
                const glm::vec3 v = images[s].pixels[i];
                basis[s][0].pixels[i] = glm::vec3(v.r - v.b);
                basis[s][1].pixels[i] = glm::vec3(v.g - v.b);
                basis[s][2].pixels[i] = glm::vec3(v.b);
            }
        }
        return basis;
    }
    p.weft_color = p.warp_color = glm::vec3(0.0f);
    const std::vector<Image> black = render(p, fitsColours_);
    p.weft_color = glm::vec3(1.0f);
    const std::vector<Image> weft = render(p, fitsColours_);
    p.weft_color = glm::vec3(0.0f);
    p.warp_color = glm::vec3(1.0f);
    const std::vector<Image> warp = render(p, fitsColours_);
    if (black.empty() || weft.empty() || warp.empty()) return {};
    for (size_t s = 0; s < shots_.size(); ++s) {
        basis[s] = {weft[s], warp[s], black[s]};
        for (size_t i = 0; i < black[s].pixels.size(); ++i) {
            basis[s][0].pixels[i] -= black[s].pixels[i];
            basis[s][1].pixels[i] -= black[s].pixels[i];
        }
    }
    return basis;
}

std::vector<Image> Fitter::mixture(const ColourBasis& basis, const WovenParams& p, float rsScale) {
    std::vector<Image> images;
    for (const std::array<Image, 3>& b : basis) {
        images.push_back(b[2]);
        for (size_t i = 0; i < b[2].pixels.size(); ++i)
            images.back().pixels[i] = rsScale * b[2].pixels[i] + (p.weft_color * b[0].pixels[i] + p.warp_color * b[1].pixels[i]);
    }
    return images;
}

void Fitter::fitColours(WovenParams& p) {
    const ColourBasis basis = colourBasis(p);
    if (basis.empty()) return;
    const Objective objective = [&](const std::vector<double>& x) {
        const WovenParams q = decode(x, p);
        return evaluate(q, mixture(basis, q), false);
    };
    std::vector<double> x = encode(p);
    x.resize(kColourAxes);
    minimise(x, objective, kColourEvaluations);
    p = decode(x, p);
}

WovenParams Fitter::rescaled(WovenParams p) const {
    const float brightest = std::max({p.weft_color.r, p.weft_color.g, p.weft_color.b, p.warp_color.r,
                                      p.warp_color.g, p.warp_color.b});
    if (!anyExposureFree_ || !(brightest > 0.0f)) return p;
    const float k = 0.5f / brightest;
    p.weft_color *= k;
    p.warp_color *= k;
    p.rs = float(fullAxes()[kRsAxis].clamped(double(p.rs * k)));
    return p;
}

}  // namespace woven
