#include "thread_frequencies.h"

#include <cmath>
#include <vector>

#include "shot.h"
#include "tile_fold.h"

namespace woven {

namespace {

// Signed angle from d to f, f taken with the sign that points along d (a real image's spectrum is
// symmetric).
double turnFrom(const glm::dvec2& d, glm::dvec2 f) {
    if (glm::dot(f, d) < 0.0) f = -f;
    return std::atan2(d.x * f.y - d.y * f.x, glm::dot(d, f));
}

// The candidates that may be threads: kLeastThreadPeakHeight over the noise floor and at least
// kThreadHeightShare of the direction's highest.
std::vector<ThreadCandidate> contenders(const std::vector<ThreadCandidate>& cs) {
    double highest = 0.0;
    for (const ThreadCandidate& c : cs) highest = std::max(highest, c.height);
    std::vector<ThreadCandidate> out;
    for (const ThreadCandidate& c : cs)
        if (c.height >= std::max(kLeastThreadPeakHeight, kThreadHeightShare * highest)) out.push_back(c);
    return out;
}

// The contender with the best score, or the candidate over the noise floor whose 2nd or 3rd
// harmonic that is (within half a bin or 1.5 %): a thread's harmonic scores as well as the
// thread where the harmonic's own folded harmonics find the lattice's points, and yarns of full
// width put far more power in the 2nd harmonic than in the fundamental (the example shot's denim,
// assets/fit: 280 times).
std::optional<SpectralPeak> best(const std::vector<ThreadCandidate>& contenders, const std::vector<ThreadCandidate>& all,
                                 double bin) {
    const ThreadCandidate* b = nullptr;
    for (const ThreadCandidate& c : contenders)
        if (!b || c.score > b->score) b = &c;
    for (bool lowered = b != nullptr; lowered;) {
        lowered = false;
        const double tolerance = std::max(0.5 * bin, 0.015 * glm::length(b->peak.frequency));
        for (const ThreadCandidate& g : all)
            for (int n = 2; n <= 3 && !lowered && g.height >= kLeastThreadPeakHeight; ++n)
                if (glm::length(double(n) * g.peak.frequency - b->peak.frequency) <= tolerance ||
                    glm::length(double(n) * g.peak.frequency + b->peak.frequency) <= tolerance) {
                    b = &g;
                    lowered = true;
                }
    }
    return b ? std::optional<SpectralPeak>(b->peak) : std::nullopt;
}

}  // namespace

std::vector<ThreadCandidate> threadCandidates(const PowerSpectrum& s, const SpectralNoiseFloor& noise,
                                              const glm::dvec2& direction, double halfAngle, double fMin, double fMax) {
    const std::vector<SpectralPeak> peaks = localPeaks(s, direction, halfAngle, fMin, fMax);
    // A ring with no power (a render without noise) leaves its peaks' heights finite.
    double strongest = 0.0;
    for (const SpectralPeak& p : peaks) strongest = std::max(strongest, p.power);
    const double least = 1e-9 * strongest + 1e-30;
    const auto height = [&](const glm::dvec2& f) { return powerNear(s, f) / std::max(noise.at(f), least); };
    const double bin = 1.0 / std::max(s.width, s.height);
    std::vector<ThreadCandidate> out;
    for (const SpectralPeak& p : peaks) {
        ThreadCandidate c{p, p.power / std::max(noise.at(p.frequency), least), 0.0};
        std::vector<glm::dvec2> counted;
        for (int n = 1; n <= kThreadHarmonics; ++n) {
            const glm::dvec2 h = double(n) * p.frequency - glm::round(double(n) * p.frequency);
            bool seen = glm::length(h) < fMin;
            for (const glm::dvec2& g : counted) seen = seen || std::min(glm::length(h - g), glm::length(h + g)) <= 2.0 * bin;
            if (seen) continue;
            counted.push_back(h);
            c.score += n == 1 ? std::log(std::max(c.height, 1.0))
                              : std::log(std::max(height(h) / kLeastThreadPeakHeight, 1.0));
        }
        out.push_back(c);
    }
    return out;
}

ThreadPeaks threadFundamentals(const PowerSpectrum& s, const glm::dvec2& gradU, const glm::dvec2& gradV, double halfAngle,
                               double fMin, double fMax) {
    ThreadPeaks peaks;
    if (!(glm::length(gradU) > 0.0) || !(glm::length(gradV) > 0.0)) return peaks;
    const SpectralNoiseFloor noise = spectralNoiseFloor(s);
    const std::vector<ThreadCandidate> ends = threadCandidates(s, noise, glm::normalize(gradU), halfAngle, fMin, fMax);
    const std::vector<ThreadCandidate> picks = threadCandidates(s, noise, glm::normalize(gradV), halfAngle, fMin, fMax);
    const double bin = 1.0 / std::max(s.width, s.height);
    peaks.ends = best(contenders(ends), ends, bin);
    peaks.picks = best(contenders(picks), picks, bin);
    return peaks;
}

ThreadPeaks threadPeaks(const Image& image, const glm::dmat2& uvPerPixel, double halfAngle) {
    std::vector<float> lum(image.pixels.size());
    for (size_t i = 0; i < lum.size(); ++i) lum[i] = luminance(image.pixels[i]);
    const PowerSpectrum s = powerSpectrum(lum, image.width, image.height);
    const double fMin = 3.0 / std::min(image.width, image.height);
    const glm::dvec2 gradU = gradientU(uvPerPixel), gradV = gradientV(uvPerPixel);
    ThreadPeaks peaks = threadFundamentals(s, gradU, gradV, halfAngle, fMin, kHighestThreadFrequency);
    for (std::optional<SpectralPeak>* peak : {&peaks.ends, &peaks.picks})
        if (*peak) (*peak)->frequency = refineThreadFrequency(lum, image.width, image.height, (*peak)->frequency);
    return peaks;
}

double threadTurn(const ThreadPeaks& peaks, const glm::dmat2& uvPerPixel) {
    const glm::dvec2 gradU = gradientU(uvPerPixel), gradV = gradientV(uvPerPixel);
    double sum = 0.0;
    int n = 0;
    if (peaks.ends) {
        sum += turnFrom(gradU, peaks.ends->frequency);
        ++n;
    }
    if (peaks.picks) {
        sum += turnFrom(gradV, peaks.picks->frequency);
        ++n;
    }
    return n > 0 ? sum / n : 0.0;
}

}  // namespace woven
