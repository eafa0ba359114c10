#include "fitter.h"

#include "photo_model.h"
#include "shot_render.h"
#include "target_in_view.h"

namespace woven {

namespace {

// p made the best fit so far: its loss, and each shot's terms and render.
void keepFit(FitResult& best, const WovenParams& p, double exposure, double loss, const std::vector<LossTerms>& terms,
             std::vector<Image> images) {
    best.params = p;
    best.exposure = exposure;
    best.loss = loss;
    best.shots.resize(terms.size());
    for (size_t i = 0; i < terms.size(); ++i) {
        best.shots[i].terms = terms[i];
        best.shots[i].render = std::move(images[i]);
    }
}

}  // namespace

FitResult Fitter::run() {
    for (const Shot& shot : shots_) checkTargetSeenAndLit(shot, options_.render, cancel_);
    WovenParams p = shots_[0].scene->materials[size_t(shots_[0].materials.at(0))].woven.value_or(WovenParams{});
    p.tile.clear();  // the fit tries (i, j, k) weaves
    p.warp_colors.clear();
    p.weft_colors.clear();
    p.warp_ex = p.ex;
    p.warp_ey = p.ey;

    const float shotRs = p.rs;
    stage_ = "thread counts";
    p.repeat = measurePhotos(p.repeat);
    result_.params = p;  // what stands where no render finishes within the budget
    compareWithLambertianPlanes();
    p = initialColours(p);
    const bool weaveDone = chooseWeave(p);
    bool calibrated = false;
    if (weaveDone && !stop()) {
        stage_ = "thread counts";
        p = result_.params;
        calibrated = calibrateThreadCounts(p);
    }
    int refined = 0;
    if (calibrated && !stop()) refined = refine(shotRs);
    polishColours();
    measureThreads();
    result_.complete = weaveDone && calibrated && refined >= 2 * int(shapeAxes().size()) + 1 && !cancel_;
    if (!std::isfinite(result_.loss))
        result_.warnings.push_back("no render finished within the budget: the material is the shot's, with the thread "
                                   "counts of the photos' spectra");
    return std::move(result_);
}

FitResult Fitter::lossOf(const WovenParams& p) {
    measurePhotos(p.repeat);
    evaluate(p);
    return std::move(result_);
}

bool Fitter::stop() const {
    const double polish = shotRenders_ > 0 ? renderSeconds_ / shotRenders_ * kPolishSamples * polishShotRenders() : 0.0;
    return outOfTime() ||
           Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(polish)) >= renderDeadline_ ||
           (options_.renders > 0 && result_.evaluations >= options_.renders);
}

void Fitter::progress() {
    if (!onProgress_) return;
    FitProgress p;
    p.stage = stage_;
    p.evaluations = result_.evaluations;
    p.elapsed = elapsed();
    p.budget = options_.seconds;
    p.bestLoss = result_.loss;
    onProgress_(p);
}

std::vector<Image> Fitter::render(const WovenParams& p, const std::vector<bool>& which) {
    std::vector<Image> images(shots_.size());
    for (size_t i = 0; i < shots_.size(); ++i) {
        if ((!which.empty() && !which[i]) || (rendersLeaveBacklitOut_ && !fitsColours_[i])) continue;
        const Clock::time_point start = Clock::now();
        images[i] = renderShot(renderShots_[i], p, options_.render, cancel_);
        if (images[i].pixels.empty()) return {};
        renderSeconds_ += std::chrono::duration<double>(Clock::now() - start).count();
        ++shotRenders_;
        applyVignette(images[i], shots_[i].photo.vignetteSigmaPx);
    }
    ++result_.evaluations;
    return images;
}

double Fitter::freeExposure(const std::vector<Image>& images) const {
    bool anyReflectedFree = false;
    for (size_t i = 0; i < shots_.size(); ++i)
        anyReflectedFree = anyReflectedFree || (!shots_[i].photo.exposure && fitsColours_[i] && !images[i].pixels.empty());
    const auto counted = [&](size_t i) {
        return !shots_[i].photo.exposure && !images[i].pixels.empty() && (fitsColours_[i] || !anyReflectedFree);
    };
    std::vector<float> photoMeans, renderMeans;
    for (size_t i = 0; i < shots_.size(); ++i) {
        if (!counted(i)) continue;
        const std::vector<float>& pm = photoStats_[i].values[kStatBlockMeans];
        photoMeans.insert(photoMeans.end(), pm.begin(), pm.end());
        const std::vector<float> rm = blockMeans(images[i]);
        renderMeans.insert(renderMeans.end(), rm.begin(), rm.end());
    }
    if (photoMeans.empty()) return 1.0;
    double free = bestExposure(photoMeans, renderMeans);
    // Where a free shot's photo clips its highlights, the exposure whose render, clipped
    // alike, has the photo's block means: a few steps of that fixed point, each raising the
    // exposure by what the clipping took away.
    bool clips = false;
    for (size_t i = 0; i < shots_.size(); ++i) clips = clips || (counted(i) && std::isfinite(photoSaturation(shots_[i].photo)));
    for (int step = 0; clips && step < kClippedExposureSteps; ++step) {
        std::vector<float> clipped;
        for (size_t i = 0; i < shots_.size(); ++i) {
            if (!counted(i)) continue;
            Image exposed = images[i];
            expose(exposed, float(free), photoSaturation(shots_[i].photo));
            const std::vector<float> m = blockMeans(exposed);
            clipped.insert(clipped.end(), m.begin(), m.end());
        }
        free *= bestExposure(photoMeans, clipped);
    }
    return free;
}

double Fitter::evaluate(const WovenParams& p, std::vector<Image> images, bool record) {
    const double free = freeExposure(images);
    double total = 0.0;
    std::vector<LossTerms> terms(shots_.size());
    for (size_t i = 0; i < shots_.size(); ++i) {
        if (images[i].pixels.empty()) continue;
        expose(images[i], float(shots_[i].photo.exposure.value_or(float(free))), photoSaturation(shots_[i].photo));
        std::optional<ThreadGrid> grid = renderGrid(p, i);
        if (grid) foldPhoto(i, grid->period);
        terms[i] = loss(photoStats_[i], imageStats(images[i], threadFrequencies_[i], grid ? &*grid : nullptr));
        total += terms[i].total;
    }

    if (record) {
        if (total < result_.loss) keepFit(result_, p, free, total, terms, std::move(images));
        result_.history.emplace_back(elapsed(), result_.loss);
        progress();
    }
    return total;
}

double Fitter::evaluate(const WovenParams& p) {
    std::vector<Image> images = render(p);
    return images.empty() ? INFINITY : evaluate(p, std::move(images), true);
}

std::optional<ThreadGrid> Fitter::photoGrid(size_t i) const {
    const ThreadPeaks& peaks = photoPeaks_[i];
    if (!peaks.ends || !peaks.picks) return std::nullopt;
    const glm::dmat2& uvPerPixel = shots_[i].uvPerPixel;
    const glm::dvec2 gradU = gradientU(uvPerPixel), gradV = gradientV(uvPerPixel);
    ThreadGrid g;
    g.ends = glm::dot(peaks.ends->frequency, gradU) < 0.0 ? -peaks.ends->frequency : peaks.ends->frequency;
    g.picks = glm::dot(peaks.picks->frequency, gradV) < 0.0 ? -peaks.picks->frequency : peaks.picks->frequency;
    return g;
}

std::optional<ThreadGrid> Fitter::renderGrid(const WovenParams& p, size_t i) const {
    if (!photoGrids_[i]) return std::nullopt;
    const glm::dmat2& uvPerPixel = renderShots_[i].uvPerPixel;
    ThreadGrid g;
    g.ends = double(p.repeat.x) * gradientU(uvPerPixel);
    g.picks = double(p.repeat.y) * gradientV(uvPerPixel);
    g.period = p.pattern.x + p.pattern.y;
    return g;
}

void Fitter::foldPhoto(size_t i, int period) {
    if (photoStats_[i].fold.side == 0 || photoGrids_[i]->period != period) {
        photoGrids_[i]->period = period;
        photoStats_[i].fold = foldTile(shots_[i].image, *photoGrids_[i]);
    }
}

bool Fitter::litWhiteAndTargetOnly(const Shot& shot) {
    const SceneDescription& scene = *shot.scene;
    auto grey = [](const glm::vec3& c) { return c.r == c.g && c.g == c.b; };
    for (const PunctualLight& l : scene.lights)
        if (!grey(l.intensity)) return false;
    if (!grey(scene.environment.color) || scene.environment.image) return false;
    for (const Mesh& m : scene.meshes)
        if (std::find(shot.materials.begin(), shot.materials.end(), m.material) == shot.materials.end()) return false;
    return true;
}

int Fitter::minimise(std::vector<double>& x, const Objective& objective, int evaluations) {
    return minimiseInUnitBox(x, objective, evaluations, [this] { return stop(); });
}

}  // namespace woven
