#include "fitter.h"

#include "photo_model.h"
#include "shot_render.h"

namespace woven {

std::vector<size_t> Fitter::shapeAxes() const {
    std::vector<size_t> axes;
    for (size_t a = anyExposureFree_ ? kRsAxis + 1 : kRsAxis; a < fullAxes().size(); ++a) axes.push_back(a);
    return axes;
}

double Fitter::evaluateSolvingColours(WovenParams p) {
    const ColourBasis basis = colourBasis(p);
    if (basis.empty()) return INFINITY;
    // Where only some exposures are free, the free one is held at its best so far: the
    // colours and the exposure are then a product only in the free shots.
    std::vector<std::optional<double>> exposures;
    std::vector<const ImageStats*> photos;
    std::vector<size_t> solved;  // the shots the colours are solved from
    for (size_t i = 0; i < shots_.size(); ++i) {
        if (!fitsColours_[i]) continue;
        const Shot& s = shots_[i];
        exposures.push_back(s.photo.exposure ? std::optional<double>(*s.photo.exposure)
                            : everyColourShotFree_ ? std::nullopt
                                                : std::optional<double>(result_.exposure));
        photos.push_back(&photoStats_[i]);
        solved.push_back(i);
    }
    LinearColours colours;  // the last solve's
    colours.weft = glm::dvec3(p.weft_color);
    colours.warp = glm::dvec3(p.warp_color);
    colours.exposure = result_.exposure;
    // The solve with the backlit shots starts from the last solve's colours and from p's as it
    // came (the best fit's in stage 4), and lays every fold at p's colours as it came: the
    // reflected shots' solve is ill-conditioned where the gloss's pattern nears the yarns'
    // (the rig's satin at ey = 4 gave every colour above 1 and an exposure a third of its
    // neighbours'), and folds laid at such colours pair the wrong places.
    const WovenParams entry = p;
    const LinearColours entryColours = colours;
    std::vector<LinearStats> entryStats;
    std::vector<LinearStats> stats(solved.size());
    for (int solve = 0; solve < kColourSolves; ++solve) {
        const std::vector<Image> reference = mixture(basis, p);
        for (size_t j = 0; j < solved.size(); ++j) {
            const size_t i = solved[j];
            for (size_t k = 0; k < 3; ++k) stats[j].blockMeans[k] = blockMeans(basis[i][k]);
            const std::optional<ThreadGrid> grid = renderGrid(p, i);
            if (!grid) continue;
            foldPhoto(i, grid->period);
            const std::vector<TileFold> folds =
                foldsLaidOn(photoStats_[i].fold, reference[i], {&basis[i][0], &basis[i][1], &basis[i][2]}, *grid);
            std::copy(folds.begin(), folds.end(), stats[j].folds.begin());
        }
        if (solve == 0) entryStats = stats;
        const LinearColours c = solveColours(photos, stats, exposures);
        if (!c.valid) break;
        colours = c;
        const Axis& axis = fullAxes()[0];
        p.weft_color = glm::vec3(glm::clamp(c.weft, glm::dvec3(axis.lo), glm::dvec3(axis.hi)));
        p.warp_color = glm::vec3(glm::clamp(c.warp, glm::dvec3(axis.lo), glm::dvec3(axis.hi)));
    }
    std::vector<Image> images = mixture(basis, p);
    if (solvesTransmission_ && !rendersLeaveBacklitOut_) {
        const TransmissionParts parts = transmissionParts(p);
        if (parts.empty()) return INFINITY;
        const ReflectedSolve reflected{photos, exposures, entryStats, colours, entryColours};
        const WovenParams scaled = withRsScaled(p, float(solveWithBacklitShots(p, entry, reflected, parts)));
        images = mixture(basis, p, scaled.rs / p.rs);
        const std::vector<Image> transmitted = backlitRenders(parts, p);
        for (size_t i = 0; i < shots_.size(); ++i)
            if (!fitsColours_[i]) images[i] = transmitted[i];
        p = scaled;
    }
    return evaluate(p, std::move(images), true);
}

WovenParams Fitter::withRsScaled(WovenParams p, float k) {
    if (k == 1.0f || !(p.rs > 0.0f)) return p;
    const float rs = float(fullAxes()[kRsAxis].clamped(double(p.rs * k))), keep = (1.0f - p.rs) / (1.0f - rs);
    p.weft_color = glm::min(p.weft_color * keep, glm::vec3(1.0f));
    p.warp_color = glm::min(p.warp_color * keep, glm::vec3(1.0f));
    p.transmission = std::min(p.transmission * keep, 1.0f);
    p.rs = rs;
    return p;
}

int Fitter::refine(float shotRs) {
    stage_ = solvesTransmission_ ? "gloss, widths, bump, transmission" : "gloss, widths, bump";
    const std::vector<size_t> axes = shapeAxes();
    int points = 0;
    for (double before = INFINITY; result_.loss < before * (1.0 - kRestartGain) && !stop();) {
        before = result_.loss;
        WovenParams base = result_.params;
        if (anyExposureFree_ && !rsSolvedWithColours()) base.rs = shotRs;
        const std::vector<double> full = encode(base);
        std::vector<double> x;
        for (size_t a : axes) x.push_back(full[a]);
        const Objective objective = [&](const std::vector<double>& v) {
            std::vector<double> y = full;
            for (size_t k = 0; k < axes.size(); ++k) y[axes[k]] = v[k];
            return evaluateSolvingColours(decode(y, base));
        };
        points += minimise(x, objective, 0);
    }
    return points;
}

void Fitter::polishColours() {
    if (!std::isfinite(result_.loss) || outOfTime()) return;
    FitResult before = result_;
    const int samples = options_.render.spp;
    options_.render.spp = samples * kPolishSamples;
    result_.loss = INFINITY;
    stage_ = "colours";
    const bool whole = std::isfinite(evaluate(before.params)) && std::isfinite(evaluateSolvingColours(before.params));
    options_.render.spp = samples;
    if (!whole) result_ = std::move(before);
}

int Fitter::polishShotRenders() const {
    const int backlit = int(std::count(fitsColours_.begin(), fitsColours_.end(), false));
    const int reflected = int(shots_.size()) - backlit;
    return int(shots_.size()) + reflected * (oneRenderColourBasis_ ? 1 : 3) + backlit * (oneRenderColourBasis_ ? 2 : 6);
}

void Fitter::compareWithLambertianPlanes() {
    for (size_t i = 0; i < shots_.size(); ++i) {
        if (shots_[i].backlit || outOfTime()) continue;
        Image plane = renderShotLambertian(shots_[i], options_.render, cancel_);
        if (plane.pixels.empty()) continue;  // the budget's end: not measured
        applyVignette(plane, shots_[i].photo.vignetteSigmaPx);
        const std::vector<float> rendered = blockMeans(plane);
        const std::vector<float>& photo = photoStats_[i].values[kStatBlockMeans];
        glm::dvec3 pr(0.0), rr(0.0);
        for (size_t k = 0; k < photo.size(); ++k) {
            pr[int(k % 3)] += double(photo[k]) * rendered[k];
            rr[int(k % 3)] += double(rendered[k]) * rendered[k];
        }
        const glm::dvec3 scale = pr / glm::max(rr, glm::dvec3(1e-300));
        std::vector<float> scaled(rendered.size());
        for (size_t k = 0; k < scaled.size(); ++k) scaled[k] = float(scale[int(k % 3)] * rendered[k]);
        result_.shots[i].lambertianBlockMeansError = colourError(photo, scaled, 1);
    }
}

}  // namespace woven
