#include "fitter.h"

#include "photo_model.h"
#include "yarn_transmission.h"

namespace woven {

Fitter::TransmissionParts Fitter::transmissionParts(WovenParams p) {
    std::vector<bool> backlit(shots_.size());
    for (size_t i = 0; i < shots_.size(); ++i) backlit[i] = !fitsColours_[i];
    p.transmission = 1.0f;
    TransmissionParts parts(shots_.size());
    for (int part = 0; part < 2; ++part) {
        p.transmission_gloss = float(part);
        // Per shot: the weft alone, the warp alone and all three regions, at transmittance tau.
        std::vector<std::array<Image, 3>> regions(shots_.size());
        double tau = 0.0;
        if (oneRenderColourBasis_) {
            p.weft_color = {0.5f, 1.0f, 0.5f};
            p.warp_color = {1.0f, 0.5f, 0.5f};
            tau = double(yarnTransmittance(p.weft_color, 1.0f).r);
            const std::vector<Image> images = render(p, backlit);
            if (images.empty()) return {};
            for (size_t s = 0; s < shots_.size(); ++s)
                for (int r = 0; r < 3; ++r) {
                    regions[s][size_t(r)] = images[s];
                    for (glm::vec3& v : regions[s][size_t(r)].pixels) v = glm::vec3(v[r]);
                }
        } else {
            const glm::vec3 grey(0.5f), white(1.0f);
            tau = double(yarnTransmittance(grey, 1.0f).r);
            const std::array<std::pair<glm::vec3, glm::vec3>, 3> colourings{
                {{grey, white}, {white, grey}, {grey, grey}}};
            for (int r = 0; r < 3; ++r) {
                std::tie(p.weft_color, p.warp_color) = colourings[size_t(r)];
                const std::vector<Image> images = render(p, backlit);
                if (images.empty()) return {};
                for (size_t s = 0; s < shots_.size(); ++s) regions[s][size_t(r)] = images[s];
            }
        }
        for (size_t s = 0; s < shots_.size(); ++s) {
            if (!backlit[s]) continue;
            std::array<Image, 3>& r = regions[s];
            for (size_t i = 0; i < r[2].pixels.size(); ++i) {
                r[0].pixels[i] /= float(tau);
                r[1].pixels[i] /= float(tau);
                r[2].pixels[i] = r[2].pixels[i] / float(tau) - r[0].pixels[i] - r[1].pixels[i];
            }
            for (int k = 0; k < kTransmittedRegionCount; ++k)
                parts[s][size_t(part * kTransmittedRegionCount + k)] = std::move(r[size_t(k)]);
        }
    }
    return parts;
}

std::vector<Image> Fitter::backlitRenders(const TransmissionParts& parts, const WovenParams& p) const {
    const std::array<glm::dvec3, kTransmittedRegionCount> tau =
        regionTransmittances(glm::dvec3(p.weft_color), glm::dvec3(p.warp_color));
    const float kd = p.transmission * (1.0f - p.transmission_gloss), kg = p.transmission * p.transmission_gloss;
    std::vector<Image> images(shots_.size());
    for (size_t s = 0; s < shots_.size(); ++s) {
        if (fitsColours_[s]) continue;
        images[s] = parts[s][0];
        for (size_t i = 0; i < images[s].pixels.size(); ++i) {
            glm::vec3 v(0.0f);
            for (int r = 0; r < kTransmittedRegionCount; ++r)
                v += glm::vec3(tau[size_t(r)]) * (kd * parts[s][size_t(r)].pixels[i] +
                                                  kg * parts[s][size_t(kTransmittedRegionCount + r)].pixels[i]);
            images[s].pixels[i] = v;
        }
    }
    return images;
}

void Fitter::measureBacklitPhotos() {
    for (size_t i = 0; i < shots_.size(); ++i) {
        if (fitsColours_[i]) continue;
        BacklitPhoto& b = backlitPhotos_.emplace_back();
        b.shot = i;
        const float saturation = photoSaturation(shots_[i].photo);
        for (const glm::vec3& v : shots_[i].image.pixels) b.clipped.push_back(std::max({v.r, v.g, v.b}) >= kClipped * saturation);
        b.image = b.withoutClipped(shots_[i].image);
        b.stats.values[kStatBlockMeans] = blockMeans(b.image);
    }
}

void Fitter::foldBacklitPhoto(BacklitPhoto& b, int period) {
    if (b.foldPeriod == period) return;
    ThreadGrid grid = *photoGrids_[b.shot];
    grid.period = period;
    b.stats.fold = foldTile(b.image, grid);
    b.foldPeriod = period;
}

std::vector<const ImageStats*> Fitter::backlitPhotoStats() const {
    std::vector<const ImageStats*> out;
    for (const BacklitPhoto& b : backlitPhotos_) out.push_back(&b.stats);
    return out;
}

Fitter::BacklitParts Fitter::backlitParts(const TransmissionParts& parts) const {
    BacklitParts out;
    for (const BacklitPhoto& b : backlitPhotos_) {
        std::array<Image, 2 * kTransmittedRegionCount>& images = out.images.emplace_back();
        TransmissionStats& t = out.stats.emplace_back();
        for (size_t k = 0; k < images.size(); ++k) {
            images[k] = b.withoutClipped(parts[b.shot][k]);
            t.blockMeans[k] = blockMeans(images[k]);
        }
    }
    return out;
}

void Fitter::foldBacklitParts(BacklitParts& out, const TransmissionParts& parts, const WovenParams& p) {
    const std::vector<Image> reference = backlitRenders(parts, p);
    for (size_t j = 0; j < backlitPhotos_.size(); ++j) {
        BacklitPhoto& b = backlitPhotos_[j];
        const std::optional<ThreadGrid> grid = renderGrid(p, b.shot);
        if (!grid) continue;
        foldBacklitPhoto(b, grid->period);
        std::vector<const Image*> images;
        for (const Image& part : out.images[j]) images.push_back(&part);
        const std::vector<TileFold> folds =
            foldsLaidOn(b.stats.fold, b.withoutClipped(reference[b.shot]), images, *grid);
        std::copy(folds.begin(), folds.end(), out.stats[j].folds.begin());
    }
}

std::vector<std::optional<double>> Fitter::backlitExposures(std::optional<double> shared) const {
    std::vector<std::optional<double>> exposures;
    for (size_t i = 0; i < shots_.size(); ++i)
        if (!fitsColours_[i])
            exposures.push_back(shots_[i].photo.exposure ? std::optional<double>(*shots_[i].photo.exposure) : shared);
    return exposures;
}

double Fitter::solveWithBacklitShots(WovenParams& p, const WovenParams& entry, const ReflectedSolve& reflected,
                                     const TransmissionParts& parts) {
    // The backlit folds' reference: the entry, with the transmission solved at its colours.
    const std::optional<double> shared = everyColourShotFree_ ? std::nullopt : std::optional<double>(result_.exposure);
    const std::vector<std::optional<double>> backlitExposed = backlitExposures(shared);
    std::vector<double> exposures;
    for (const std::optional<double>& e : backlitExposed) exposures.push_back(e.value_or(reflected.entry.exposure));
    BacklitParts backlit = backlitParts(parts);
    const TransmissionSplit first = solveTransmission(backlitPhotoStats(), backlit.stats, exposures,
                                                      reflected.entry.weft, reflected.entry.warp);
    WovenParams reference = entry;
    reference.transmission = float(first.transmission());
    reference.transmission_gloss = float(first.gloss());
    foldBacklitParts(backlit, parts, reference);
    LinearColours entryStart = reflected.entry;
    if (!everyColourShotFree_) entryStart.exposure = 1.0;
    const TransmittedColours joint =
        solveColoursWithTransmission(reflected.photos, reflected.entryStats, reflected.exposures, backlitPhotoStats(),
                                     backlit.stats, backlitExposed, {reflected.last, entryStart},
                                     rsSolvedWithColours());
    p.weft_color = glm::vec3(joint.colours.weft);
    p.warp_color = glm::vec3(joint.colours.warp);
    p.transmission = float(joint.split.transmission());
    p.transmission_gloss = float(joint.split.gloss());
    return joint.rsScale;
}

void Fitter::countBacklitShots(bool counted) {
    rendersLeaveBacklitOut_ = !counted;
    if (!std::isfinite(result_.loss) || outOfTime()) return;
    FitResult before = result_;
    result_.loss = INFINITY;
    evaluateSolvingColours(before.params);
    if (!std::isfinite(result_.loss)) result_ = std::move(before);  // cut short: the best as it was
}

}  // namespace woven
