#include "fitter.h"

#include "thread_fold.h"

namespace woven {

namespace {

double angleDegrees(const glm::dvec2& a, const glm::dvec2& b) {
    // Peaks are defined up to sign (the spectrum of a real image is symmetric).
    const double c = std::abs(glm::dot(a, b)) / (glm::length(a) * glm::length(b));
    return std::acos(std::min(1.0, c)) * 180.0 / M_PI;
}

}  // namespace

glm::vec2 Fitter::measurePhotos(glm::vec2 repeat) {
    const Clock::time_point start = Clock::now();
    repeat = unfoldThreadCounts(threadCountsFromPhotos(repeat));
    renderDeadline_ = std::max(start_, deadline_ - 2 * (Clock::now() - start));
    options_.render.deadline = renderDeadline_;
    for (size_t i = 0; i < shots_.size(); ++i) {
        // The thread peaks' statistic reads each peak's power where the spectrum holds it: folded.
        std::vector<glm::dvec2> threads;
        if (photoPeaks_[i].ends) threads.push_back(photoPeaks_[i].ends->frequency - glm::round(photoPeaks_[i].ends->frequency));
        if (photoPeaks_[i].picks) threads.push_back(photoPeaks_[i].picks->frequency - glm::round(photoPeaks_[i].picks->frequency));
        threadFrequencies_.push_back(threads);
        photoStats_.push_back(imageStats(shots_[i].image, threads));
        photoGrids_.push_back(photoGrid(i));
        const double turn = threadTurn(photoPeaks_[i], shots_[i].uvPerPixel);
        renderShots_.push_back(turnedShot(shots_[i], std::abs(turn) >= kLeastTurn ? turn : 0.0));
    }
    measureBacklitPhotos();
    return repeat;
}

glm::vec2 Fitter::threadCountsFromPhotos(glm::vec2 repeat) {
    bool ends = false, picks = false;
    for (size_t i = 0; i < shots_.size(); ++i) {
        const Shot& s = shots_[i];
        const ThreadPeaks peaks = threadPeaks(s.image, s.uvPerPixel, kPeakHalfAngle);
        const glm::dvec2 gradU = gradientU(s.uvPerPixel), gradV = gradientV(s.uvPerPixel);
        if (peaks.ends) result_.shots[i].photoFrequency.x = glm::length(peaks.ends->frequency);
        if (peaks.picks) result_.shots[i].photoFrequency.y = glm::length(peaks.picks->frequency);
        photoPeaks_.push_back(peaks);
        if (!ends && peaks.ends) {
            repeat.x = float(glm::length(peaks.ends->frequency) / glm::length(gradU));
            ends = true;
        }
        if (!picks && peaks.picks) {
            repeat.y = float(glm::length(peaks.picks->frequency) / glm::length(gradV));
            picks = true;
        }
    }
    if (!ends || !picks)
        result_.warnings.push_back(std::string("no photo shows the threads ") + (!ends ? "across u (warp ends)" : "") +
                                   (!ends && !picks ? " or " : "") + (!picks ? "across v (weft picks)" : "") +
                                   " as a peak of its spectrum: the thread count there stays the shot's material's (" +
                                   std::to_string(!ends ? repeat.x : repeat.y) +
                                   " per UV unit); a sharper or closer photo resolves them");
    return repeat;
}

glm::vec2 Fitter::unfoldThreadCounts(glm::vec2 repeat) {
    for (size_t i = 0; i < shots_.size(); ++i) {
        const std::optional<ThreadGrid> grid = photoGrid(i);
        if (!grid) continue;
        const UnfoldedThreads u = unfoldThreads(shots_[i].image, grid->ends, grid->picks);
        unfoldedEnds_ = u.endsUnfolded;
        unfoldedPicks_ = u.picksUnfolded;
        const glm::dmat2& m = shots_[i].uvPerPixel;
        if (unfoldedEnds_) repeat.x = float(glm::length(u.ends) / glm::length(gradientU(m)));
        if (unfoldedPicks_) repeat.y = float(glm::length(u.picks) / glm::length(gradientV(m)));
        // Every shot's peak that is the same threads folded alike.
        for (size_t j = 0; j < shots_.size(); ++j) {
            const auto unfold = [&](std::optional<SpectralPeak>& peak, double frequency, double& reported) {
                if (!peak || std::abs(glm::length(unfolded(peak->frequency)) - frequency) > kSameThreads * frequency) return;
                peak->frequency = unfolded(peak->frequency);
                reported = glm::length(peak->frequency);
            };
            if (unfoldedEnds_) unfold(photoPeaks_[j].ends, glm::length(u.ends), result_.shots[j].photoFrequency.x);
            if (unfoldedPicks_) unfold(photoPeaks_[j].picks, glm::length(u.picks), result_.shots[j].photoFrequency.y);
        }
        if (unfoldedEnds_ || unfoldedPicks_)
            result_.warnings.push_back(std::string("the ") + (unfoldedEnds_ && unfoldedPicks_ ? "ends and picks are" : unfoldedEnds_ ? "ends are" : "picks are") +
                                       " finer than 2 pixels a thread: their peaks are where the pixel grid folds them, "
                                       "unfolded by the weave's lattice (docs/FIT.md)");
        break;
    }
    return repeat;
}

bool Fitter::calibrateThreadCounts(WovenParams& p) {
    for (int iteration = 0; iteration < 2; ++iteration) {
        if (stop()) return false;
        const std::vector<Image> images = render(p);
        if (images.empty()) return false;
        const ThreadPeaks r = threadPeaks(images[0], renderShots_[0].uvPerPixel, kPeakHalfAngle);
        const ThreadPeaks& photo = photoPeaks_[0];
        // An unfolded direction is left as the lattice placed it: a folded peak moves against its
        // threads' frequency, so the ratio of the render's to the photo's would step away.
        if (photo.ends && r.ends && !unfoldedEnds_)
            p.repeat.x *= float(glm::length(photo.ends->frequency) / glm::length(r.ends->frequency));
        if (photo.picks && r.picks && !unfoldedPicks_)
            p.repeat.y *= float(glm::length(photo.picks->frequency) / glm::length(r.picks->frequency));
    }
    // Kept where their loss is lower: a render's peak can be pulled by the weave's own peaks
    // beside it (the synthetic 3/1 twill's ends' peak moved 3 % from the photo's after the
    // counts had been scaled to meet it, the counts 3 % off and the loss 5 times the truth's).
    evaluate(p);
    return true;
}

void Fitter::measureThreads() {
    for (size_t i = 0; i < shots_.size() && i < photoPeaks_.size(); ++i) {
        ShotFit& f = result_.shots[i];
        if (f.render.pixels.empty()) continue;
        ThreadPeaks r = threadPeaks(f.render, renderShots_[i].uvPerPixel, kPeakHalfAngle);
        if (r.ends && unfoldedEnds_) r.ends->frequency = unfolded(r.ends->frequency);
        if (r.picks && unfoldedPicks_) r.picks->frequency = unfolded(r.picks->frequency);
        const ThreadPeaks& p = photoPeaks_[i];
        if (r.ends) f.renderFrequency.x = glm::length(r.ends->frequency);
        if (r.picks) f.renderFrequency.y = glm::length(r.picks->frequency);
        if (r.ends && p.ends) f.directionError.x = angleDegrees(r.ends->frequency, p.ends->frequency);
        if (r.picks && p.picks) f.directionError.y = angleDegrees(r.picks->frequency, p.picks->frequency);
    }
}

}  // namespace woven
