// The thread counter (core/fit/thread_frequencies.h) on crops of weaves drawn here with what real
// phone photos of cloth hold (docs/FIT.md, "Real photographs"): threads of 2 to 4 pixels, the
// lens's blur, sensor noise, specular speckle, a coarse fuzz texture that holds more raw power
// than the threads, the flash's fall-off, a swatch turned by a degree or two.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "spectral_noise_floor.h"
#include "thread_fold.h"
#include "thread_frequencies.h"

namespace woven {
namespace {

struct Weave {
    double endPixels, pickPixels;  // pixels a thread across x (ends) and across y (picks)
    int shafts;                    // the repeat: 2 plain, 3 or 4 a twill, 5 a satin
    int up;                        // of each end's `shafts` picks, how many it floats over
    int step;                      // the float's move from one pick to the next (1: a twill)
    double turnDegrees;            // the cloth turned in the image
};

// Whether the warp end `i` floats over the weft pick `j`.
bool warpUp(const Weave& w, long i, long j) {
    const long m = ((i - long(w.step) * j) % w.shafts + w.shafts) % w.shafts;
    return m < w.up;
}

// The cloth's luminance at (x, y) pixels: each yarn a rounded bump across its width, the one on
// top seen, dark gaps between.
double cloth(const Weave& w, double x, double y) {
    const double t = w.turnDegrees * M_PI / 180.0;
    const double u = (std::cos(t) * x + std::sin(t) * y) / w.endPixels;
    const double v = (-std::sin(t) * x + std::cos(t) * y) / w.pickPixels;
    const long i = long(std::floor(u)), j = long(std::floor(v));
    const double across = warpUp(w, i, j) ? u - double(i) : v - double(j);
    return 0.75 + 0.25 * std::pow(std::sin(M_PI * across), 0.5) * (warpUp(w, i, j) ? 1.0 : 0.8);
}

// A photo of `size` pixels: 4 x 4 samples a pixel, a Gaussian blur of 0.6 pixels, a fuzz texture
// (smoothed noise over 6 to 30 pixels, +-35 %), the flash's fall-off, 1 % of pixels speckled up
// to 3 times as bright, 4 % sensor noise.
Image photo(const Weave& w, int size, uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const double ox = 1000.0 * uniform(rng), oy = 1000.0 * uniform(rng);
    std::vector<double> v(size_t(size) * size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            double sum = 0.0;
            for (int s = 0; s < 16; ++s) sum += cloth(w, ox + x + (s % 4 + 0.5) / 4.0, oy + y + (s / 4 + 0.5) / 4.0);
            v[size_t(y) * size + x] = sum / 16.0;
        }
    const auto blur = [size](std::vector<double>& a, double sigma) {
        const int r = int(std::ceil(3.0 * sigma));
        std::vector<double> k(size_t(2 * r + 1));
        double total = 0.0;
        for (int i = -r; i <= r; ++i) total += k[size_t(i + r)] = std::exp(-0.5 * i * i / (sigma * sigma));
        for (double& c : k) c /= total;
        std::vector<double> b(a.size());
        for (int pass = 0; pass < 2; ++pass) {
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) {
                    double s = 0.0;
                    for (int i = -r; i <= r; ++i) {
                        const int xx = std::clamp(pass == 0 ? x + i : x, 0, size - 1), yy = std::clamp(pass == 0 ? y : y + i, 0, size - 1);
                        s += k[size_t(i + r)] * a[size_t(yy) * size + xx];
                    }
                    b[size_t(y) * size + x] = s;
                }
            a.swap(b);
        }
    };
    blur(v, 0.6);
    std::vector<double> fuzz(v.size()), coarse(v.size());
    for (double& f : fuzz) f = gauss(rng);
    for (double& f : coarse) f = gauss(rng);
    blur(fuzz, 4.0);
    blur(coarse, 16.0);
    double fuzzScale = 0.0, coarseScale = 0.0;
    for (size_t i = 0; i < v.size(); ++i) {
        fuzzScale = std::max(fuzzScale, std::abs(fuzz[i]));
        coarseScale = std::max(coarseScale, std::abs(coarse[i]));
    }
    Image image;
    image.width = image.height = size;
    image.pixels.resize(v.size());
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const size_t i = size_t(y) * size + x;
            const double dx = (x - 0.4 * size) / size, dy = (y - 0.3 * size) / size;
            double value = v[i] * (1.0 + 0.5 * fuzz[i] / fuzzScale + 0.3 * coarse[i] / coarseScale) *
                           (0.3 + std::exp(-4.0 * (dx * dx + dy * dy)));
            if (uniform(rng) < 0.01) value *= 1.0 + 2.0 * uniform(rng);
            value *= 1.0 + 0.04 * gauss(rng);
            image.pixels[i] = glm::vec3(float(std::max(value, 0.0)));
        }
    return image;
}

// Found over true frequency, across x (ends) and across y (picks); 0 where none was found.
glm::dvec2 foundOverTrue(const Weave& w, uint32_t seed) {
    const Image image = photo(w, 256, seed);
    const ThreadPeaks peaks = threadPeaks(image, glm::dmat2(1.0), 4.0 * M_PI / 180.0);
    return {peaks.ends ? glm::length(peaks.ends->frequency) * w.endPixels : 0.0,
            peaks.picks ? glm::length(peaks.picks->frequency) * w.pickPixels : 0.0};
}

// Over seeds 1 to 6 every direction within 3 %. Measured (2026-12-07), found over true, the worst
// of the six seeds: plain 0.9913, 2/2 twill 0.9891, 2/1 twill 0.9976, satin 0.9990; a bin of the
// spectrum at 256 pixels is 1.2 % of 0.33 cycles a pixel. The counter before the noise floor
// (raw power) was wrong in 10 of the 48 directions (6 to 10 times too few threads in 7, 1.3 to 2
// times too many in 3), and found threads in all 6 photos without them.
void expectThreads(const Weave& w) {
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        const glm::dvec2 r = foundOverTrue(w, seed);
        EXPECT_NEAR(r.x, 1.0, 0.03) << "ends at seed " << seed;
        EXPECT_NEAR(r.y, 1.0, 0.03) << "picks at seed " << seed;
    }
}

TEST(ThreadCounter, PlainWeaveAtThreePixels) { expectThreads({3.0, 3.4, 2, 1, 1, 0.0}); }
TEST(ThreadCounter, TwoTwoTwillAtTwoAndAHalfPixels) { expectThreads({2.6, 3.3, 4, 2, 1, 0.0}); }
TEST(ThreadCounter, TwoOneTwillTurnedADegreeAndAHalf) { expectThreads({3.5, 3.0, 3, 2, 1, 1.5}); }
TEST(ThreadCounter, FiveShaftSatinAtFourAndTwoAndAHalfPixels) { expectThreads({4.0, 2.5, 5, 1, 2, -1.0}); }

// The threads found, unfolded by the weave's lattice (thread_fold.h), over the true frequency.
glm::dvec2 unfoldedOverTrue(const Weave& w, uint32_t seed) {
    const Image image = photo(w, 256, seed);
    const ThreadPeaks peaks = threadPeaks(image, glm::dmat2(1.0), 4.0 * M_PI / 180.0);
    if (!peaks.ends || !peaks.picks) return glm::dvec2(0.0);
    const glm::dvec2 ends = peaks.ends->frequency.x < 0.0 ? -peaks.ends->frequency : peaks.ends->frequency;
    const glm::dvec2 picks = peaks.picks->frequency.y < 0.0 ? -peaks.picks->frequency : peaks.picks->frequency;
    const UnfoldedThreads u = unfoldThreads(image, ends, picks);
    return {glm::length(u.ends) * w.endPixels, glm::length(u.picks) * w.pickPixels};
}

TEST(ThreadFold, UnfoldedPeakIsTheFinerThreadsTheGridFoldsOntoIt) {
    EXPECT_NEAR(unfolded(glm::dvec2(0.01, 0.36)).x, -0.01, 1e-12);
    EXPECT_NEAR(unfolded(glm::dvec2(0.01, 0.36)).y, 0.64, 1e-12);
    EXPECT_NEAR(unfolded(glm::dvec2(-0.3, 0.02)).x, -0.7, 1e-12);
    EXPECT_NEAR(unfolded(glm::dvec2(-0.3, 0.02)).y, -0.02, 1e-12);
}

// A 2/2 twill whose picks, 1.56 pixels a thread (twill4's), the pixel grid folds to 2.8 pixels:
// the lattice puts them back. Measured (2026-12-07), unfolded over true at seeds 1 to 6: ends
// 0.998 to 1.002, picks 0.993 to 1.003. (A drawn 3/1 twill hides its picks from the counter.)
TEST(ThreadFold, PicksFinerThanTwoPixelsAreUnfolded) {
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        const glm::dvec2 r = unfoldedOverTrue({3.2, 1.56, 4, 2, 1, 0.0}, seed);
        EXPECT_NEAR(r.x, 1.0, 0.03) << "ends at seed " << seed;
        EXPECT_NEAR(r.y, 1.0, 0.03) << "picks at seed " << seed;
    }
}

// The same twill with picks of 2.7 pixels, as folded ones look: nothing is unfolded. Measured
// (2026-12-07) at seeds 1 to 6: ends 0.998 to 1.002, picks 1.006 to 1.012.
TEST(ThreadFold, ThreadsCoarserThanTwoPixelsStayAsFound) {
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        const glm::dvec2 r = unfoldedOverTrue({3.2, 2.7, 4, 2, 1, 0.0}, seed);
        EXPECT_NEAR(r.x, 1.0, 0.03) << "ends at seed " << seed;
        EXPECT_NEAR(r.y, 1.0, 0.03) << "picks at seed " << seed;
    }
}

// A photo of fuzz, speckle and noise with no threads: no direction is reported, where the
// strongest peak of raw power would have been taken for threads.
TEST(ThreadCounter, NoThreadsInAPhotoWithoutThem) {
    for (uint32_t seed = 1; seed <= 6; ++seed) {
        const Image flat = photo({1e9, 1e9, 2, 1, 1, 0.0}, 256, seed);
        const ThreadPeaks peaks = threadPeaks(flat, glm::dmat2(1.0), 4.0 * M_PI / 180.0);
        EXPECT_FALSE(peaks.ends) << "seed " << seed;
        EXPECT_FALSE(peaks.picks) << "seed " << seed;
    }
}

}  // namespace
}  // namespace woven
