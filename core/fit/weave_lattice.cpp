#include "weave_lattice.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "power_spectrum.h"
#include "weave_candidates.h"

namespace woven {

namespace {

// Lattice points as integers over a common denominator: every candidate's P divides it.
constexpr int kDenominator = 840;  // lcm(1 ... 8)

using LatticePoint = std::pair<int, int>;  // (p, q) x kDenominator, mod kDenominator

// A lattice point has a peak where its bin stands above the median of the bins within
// kFloorRadius by kPeakLogRatio in log (55 times), and by no less than the strongest lattice
// point's less kBelowStrongest: every weave candidate's pattern has the same amplitude at each of
// its points (1, or a 2/2 twill's sqrt 2), so a real peak is about as strong as the others, while
// how the yarns' floats bend puts weaker peaks off the pattern's lattice (a 2/2 twill's
// (1/2, 1/2), 5.4 below its (1/4, 1/4) in the rig, where the weave's own peaks stood 9.6 to 13
// above their floor and no other point above 5.7). kPeakLogWidth: how sharp the step is, a
// 2/2 twill's (1/2, 1/2) 1.4 below the threshold counting 2.8 against the 3/1 twills.
constexpr int kFloorRadius = 6;
constexpr double kPeakLogRatio = 4.0;
constexpr double kBelowStrongest = 4.0;
constexpr double kPeakLogWidth = 0.5;

// (p, q) and (-p, -q) are one peak: the spectrum of a real image is symmetric.
LatticePoint canonical(int p, int q) {
    const auto mod = [](int x) { return ((x % kDenominator) + kDenominator) % kDenominator; };
    const LatticePoint a{mod(p), mod(q)}, b{mod(-p), mod(-q)};
    return std::min(a, b);
}

// The points of a weave's lattice where its pattern's spectrum is not zero (a 2/2 twill's a = 2
// is: two weft elements and two warp elements cancel).
std::vector<LatticePoint> latticeOf(const glm::ivec3& w) {
    const int period = w.x + w.y;
    std::vector<LatticePoint> points;
    for (int a = 1; a < period; ++a) {
        const double amplitude = std::abs(std::sin(M_PI * a * w.x / period) / std::sin(M_PI * a / period));
        if (amplitude < 1e-6) continue;
        const int p = a * (kDenominator / period);
        const LatticePoint point = canonical(p, int((int64_t(p) * w.z) % kDenominator));
        if (std::find(points.begin(), points.end(), point) == points.end()) points.push_back(point);
    }
    return points;
}

// The power of bin (kx, ky), either half-plane, any ky.
double powerAt(const PowerSpectrum& s, int kx, int ky) {
    if (kx < 0) {  // the conjugate half-plane
        kx = -kx;
        ky = -ky;
    }
    if (kx > s.width / 2) return 0.0;
    ky = ((ky % s.height) + s.height) % s.height;
    return s.at(kx, ky);
}

// How far the spectrum has a peak at frequency f (cycles per pixel): the log of the strongest bin
// within one bin of f over the median of the bins within kFloorRadius (the floor it stands on,
// which the few peaks in the window do not move), or 0 where that bin is not a local maximum:
// a strong peak a couple of bins away leaks onto its neighbours (the Hann window's main lobe is
// 4 bins wide), and a slope down from it is no peak.
double peakLogRatio(const PowerSpectrum& s, const glm::dvec2& f) {
    const int cx = int(std::lround(f.x * s.width)), cy = int(std::lround(f.y * s.height));
    int bx = cx, by = cy;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (powerAt(s, cx + dx, cy + dy) > powerAt(s, bx, by)) {
                bx = cx + dx;
                by = cy + dy;
            }
    const double peak = powerAt(s, bx, by);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if (powerAt(s, bx + dx, by + dy) > peak) return 0.0;
    std::vector<double> v;
    for (int dy = -kFloorRadius; dy <= kFloorRadius; ++dy)
        for (int dx = -kFloorRadius; dx <= kFloorRadius; ++dx) v.push_back(powerAt(s, cx + dx, cy + dy));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return std::max(0.0, std::log(peak / std::max(v[v.size() / 2], 1e-30)));
}

}  // namespace

std::vector<WeaveLatticeScore> rankWeavesBySpectrum(const Image& photo, const glm::dvec2& ends, const glm::dvec2& picks) {
    std::vector<PowerSpectrum> spectra;
    std::vector<float> channel(photo.pixels.size());
    for (int c = 0; c < 3; ++c) {
        for (size_t i = 0; i < channel.size(); ++i) channel[i] = photo.pixels[i][c];
        spectra.push_back(powerSpectrum(channel, photo.width, photo.height));
    }

    // Every candidate's points, each measured once: how far its strongest copy stands above its
    // floor, in any channel.
    std::map<LatticePoint, double> logRatio;
    for (const WeaveCandidate& c : weaveCandidates())
        for (const LatticePoint& point : latticeOf(c.pattern)) logRatio[point] = 0.0;
    double strongest = 0.0;
    for (auto& [point, ratio] : logRatio) {
        // The copies (p - n, q - m) of the zone |p|, |q| < 1: the nearest to the origin hold the
        // colours' difference between the yarns, the others their shapes'.
        for (int n = 0; n <= 1; ++n)
            for (int m = 0; m <= 1; ++m) {
                const double p = double(point.first) / kDenominator - n, q = double(point.second) / kDenominator - m;
                glm::dvec2 f = p * ends + q * picks;
                f -= glm::round(f);  // as the pixel grid folds it
                for (const PowerSpectrum& s : spectra) ratio = std::max(ratio, peakLogRatio(s, f));
            }
        strongest = std::max(strongest, ratio);
    }
    const double threshold = std::max(kPeakLogRatio, strongest - kBelowStrongest);
    std::map<LatticePoint, double> peakProbability;
    for (const auto& [point, ratio] : logRatio)
        peakProbability[point] = std::clamp(1.0 / (1.0 + std::exp(-(ratio - threshold) / kPeakLogWidth)), 1e-3, 1.0 - 1e-3);

    std::vector<WeaveLatticeScore> scores;
    for (const WeaveCandidate& c : weaveCandidates()) {
        const std::vector<LatticePoint> own = latticeOf(c.pattern);
        double score = 0.0;
        for (const auto& [point, probability] : peakProbability) {
            const bool expected = std::find(own.begin(), own.end(), point) != own.end();
            score += std::log(expected ? probability : 1.0 - probability);
        }
        scores.push_back({c.pattern, score});
    }
    std::stable_sort(scores.begin(), scores.end(), [](const auto& a, const auto& b) { return a.score > b.score; });
    return scores;
}

std::vector<glm::ivec3> weaveShortlist(const std::vector<WeaveLatticeScore>& ranking) {
    std::vector<glm::ivec3> list;
    for (const WeaveLatticeScore& s : ranking)
        if (s.score >= ranking.front().score - 2.0) list.push_back(s.pattern);
    return list;
}

}  // namespace woven
