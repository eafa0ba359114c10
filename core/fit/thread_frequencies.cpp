#include "thread_frequencies.h"

#include <cmath>
#include <vector>

#include "shot.h"
#include "tile_fold.h"

namespace woven {

namespace {

struct Candidate {
    SpectralPeak peak;
    double score = 0.0;  // the sum of the logs of its first three harmonics' power, folded
    double turn = 0.0;   // radians from the direction searched, signed
};

// Signed angle from d to f, f taken with the sign that points along d (a real image's spectrum is
// symmetric).
double turnFrom(const glm::dvec2& d, glm::dvec2 f) {
    if (glm::dot(f, d) < 0.0) f = -f;
    return std::atan2(d.x * f.y - d.y * f.x, glm::dot(d, f));
}

std::vector<Candidate> candidates(const PowerSpectrum& s, const glm::dvec2& direction, double halfAngle, double fMin,
                                  double fMax) {
    const std::optional<SpectralPeak> strongest = strongestPeak(s, direction, halfAngle, fMin, fMax);
    if (!strongest) return {};
    const double floor = 1e-3 * strongest->power;
    const auto folded = [](const glm::dvec2& f) { return f - glm::round(f); };
    const double bin = 1.0 / std::max(s.width, s.height);
    std::vector<Candidate> out;
    for (double f = fMin; f <= fMax; f += bin) {
        // The strongest bin of this ring of the window, kept if no bin around it is stronger.
        const auto peak = strongestPeak(s, direction, halfAngle, f, f + bin);
        if (!peak || peak->power < 0.05 * strongest->power) continue;
        const double at = glm::length(peak->frequency);
        const auto around = strongestPeak(s, direction, halfAngle, std::max(fMin, at - 2.0 * bin), at + 2.0 * bin);
        if (!around || around->power > peak->power) continue;
        Candidate c{*peak, 0.0, turnFrom(direction, peak->frequency)};
        for (int n = 1; n <= 3; ++n) c.score += std::log(powerNear(s, folded(double(n) * peak->frequency)) + floor);
        out.push_back(c);
        f = at + bin;  // past this peak
    }
    return out;
}

const Candidate* best(const std::vector<Candidate>& cs) {
    const Candidate* b = nullptr;
    for (const Candidate& c : cs)
        if (!b || c.score > b->score + 1e-9) b = &c;
    return b;
}

}  // namespace

ThreadPeaks threadFundamentals(const PowerSpectrum& s, const glm::dvec2& gradU, const glm::dvec2& gradV, double halfAngle,
                               double fMin, double fMax) {
    ThreadPeaks peaks;
    if (!(glm::length(gradU) > 0.0) || !(glm::length(gradV) > 0.0)) return peaks;
    const std::vector<Candidate> ends = candidates(s, glm::normalize(gradU), halfAngle, fMin, fMax);
    const std::vector<Candidate> picks = candidates(s, glm::normalize(gradV), halfAngle, fMin, fMax);
    const double skew = kThreadSkewDegrees * M_PI / 180.0;
    const Candidate *bestEnds = nullptr, *bestPicks = nullptr;
    for (const Candidate& e : ends)
        for (const Candidate& p : picks)
            if (std::abs(e.turn - p.turn) <= skew &&
                (!bestEnds || e.score + p.score > bestEnds->score + bestPicks->score + 1e-9)) {
                bestEnds = &e;
                bestPicks = &p;
            }
    if (!bestEnds) {
        bestEnds = best(ends);
        bestPicks = best(picks);
    }
    if (bestEnds) peaks.ends = bestEnds->peak;
    if (bestPicks) peaks.picks = bestPicks->peak;
    return peaks;
}

ThreadPeaks threadPeaks(const Image& image, const glm::dmat2& uvPerPixel, double halfAngle) {
    std::vector<float> lum(image.pixels.size());
    for (size_t i = 0; i < lum.size(); ++i) lum[i] = luminance(image.pixels[i]);
    const PowerSpectrum s = powerSpectrum(lum, image.width, image.height);
    const double fMin = 3.0 / std::min(image.width, image.height);
    const glm::dvec2 gradU = gradientU(uvPerPixel), gradV = gradientV(uvPerPixel);
    ThreadPeaks peaks = threadFundamentals(s, gradU, gradV, halfAngle, fMin, 0.5);
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
