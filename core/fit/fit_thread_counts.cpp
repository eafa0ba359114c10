#include "fitter.h"

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
    repeat = threadCountsFromPhotos(repeat);
    threadCountSeconds_ = std::chrono::duration<double>(Clock::now() - start).count();
    for (size_t i = 0; i < shots_.size(); ++i) {
        std::vector<glm::dvec2> threads;
        if (photoPeaks_[i].ends) threads.push_back(photoPeaks_[i].ends->frequency);
        if (photoPeaks_[i].picks) threads.push_back(photoPeaks_[i].picks->frequency);
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

bool Fitter::calibrateThreadCounts(WovenParams& p) {
    for (int iteration = 0; iteration < 2; ++iteration) {
        if (stop()) return false;
        const std::vector<Image> images = render(p);
        if (images.empty()) return false;
        const ThreadPeaks r = threadPeaks(images[0], renderShots_[0].uvPerPixel, kPeakHalfAngle);
        const ThreadPeaks& photo = photoPeaks_[0];
        if (photo.ends && r.ends) p.repeat.x *= float(glm::length(photo.ends->frequency) / glm::length(r.ends->frequency));
        if (photo.picks && r.picks)
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
        const ThreadPeaks r = threadPeaks(f.render, renderShots_[i].uvPerPixel, kPeakHalfAngle);
        const ThreadPeaks& p = photoPeaks_[i];
        if (r.ends) f.renderFrequency.x = glm::length(r.ends->frequency);
        if (r.picks) f.renderFrequency.y = glm::length(r.picks->frequency);
        if (r.ends && p.ends) f.directionError.x = angleDegrees(r.ends->frequency, p.ends->frequency);
        if (r.picks && p.picks) f.directionError.y = angleDegrees(r.picks->frequency, p.picks->frequency);
    }
}

}  // namespace woven
