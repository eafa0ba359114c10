// The thread counter (stage 1 of woven fit, core/fit/thread_frequencies.h) alone on photos: for
// each image, the threads found across x and across y (cycles per pixel, pixels a thread, threads
// across the frame) and the time the counter took. The camera is taken to look straight down with
// U along x and V along y, as in the real-photo rig of docs/FIT.md.
// With --rig, the round trips' photos of the synthetic capture rig (tests/fit/capture_rig.h)
// instead, each with the ratio of what was found to the truth.
// With --spectrum DIR, each image's log spectrum as DIR/NAME.pgm (the zero frequency at the
// centre), its strongest local maxima and each direction's candidates over the noise floor.
// Usage: bench_threads IMAGE [IMAGE ...] [--spectrum DIR]
//        bench_threads --rig
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "capture_rig.h"
#include "image_io.h"
#include "shot.h"
#include "power_spectrum.h"
#include "thread_fold.h"
#include "thread_frequencies.h"
#include "weave_lattice.h"

namespace {

void writeSpectrum(const woven::PowerSpectrum& s, const std::string& path) {
    const int w = s.width, h = s.height;
    std::vector<double> logs(size_t(w) * h);
    double lo = INFINITY, hi = -INFINITY;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // fftshifted: the zero frequency at the centre.
            int kx = x - w / 2, ky = y - h / 2;
            if (kx < 0) {
                kx = -kx;
                ky = -ky;
            }
            if (kx > w / 2) continue;
            ky = ((ky % h) + h) % h;
            const double v = std::log10(s.at(kx, ky) + 1e-12);
            logs[size_t(y) * w + x] = v;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    lo = std::max(lo, hi - 5.0);
    std::ofstream out(path, std::ios::binary);
    out << "P5\n" << w << " " << h << "\n255\n";
    for (double v : logs) out.put(char(std::clamp(int(255.0 * (v - lo) / (hi - lo)), 0, 255)));
}

// The strongest local maxima of the spectrum (a 5 x 5 neighbourhood) beyond 6 bins from zero.
void printPeaks(const woven::PowerSpectrum& s, int count) {
    struct P { int kx, ky; float p; };
    std::vector<P> ps;
    const int nx = s.width / 2 + 1;
    const auto at = [&](int kx, int ky) {
        if (kx < 0) { kx = -kx; ky = -ky; }
        if (kx >= nx) return 0.0f;
        return s.at(kx, ((ky % s.height) + s.height) % s.height);
    };
    for (int ky = -s.height / 2 + 1; ky < s.height / 2; ++ky)
        for (int kx = 0; kx < nx; ++kx) {
            if (kx * kx + ky * ky < 36 || (kx == 0 && ky < 0)) continue;
            const float c = at(kx, ky);
            bool max = true;
            for (int dy = -2; dy <= 2 && max; ++dy)
                for (int dx = -2; dx <= 2; ++dx)
                    if ((dx || dy) && at(kx + dx, ky + dy) > c) { max = false; break; }
            if (max) ps.push_back({kx, ky, c});
        }
    std::sort(ps.begin(), ps.end(), [](const P& a, const P& b) { return a.p > b.p; });
    for (int i = 0; i < count && i < int(ps.size()); ++i)
        std::printf("  (%4d, %4d) bins  f (%.4f, %.4f)  |f| %.4f  power %.3g\n", ps[i].kx, ps[i].ky,
                    double(ps[i].kx) / s.width, double(ps[i].ky) / s.height,
                    std::hypot(double(ps[i].kx) / s.width, double(ps[i].ky) / s.height), ps[i].p);
}

// Each round-trip photo's threads found over the truth, ends and picks.
int rigPhotos() {
    using namespace woven;
    const auto dir = std::filesystem::temp_directory_path() / ("woven_bench_threads_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    struct Case {
        const char* name;
        test::RigPhoto photo;
    };
    const auto cloth = [](glm::ivec3 pattern) {
        test::RigPhoto photo;
        photo.truth.pattern = pattern;
        photo.truth.repeat = {800.0f, 600.0f};
        photo.truth.weft_color = {0.70f, 0.62f, 0.45f};
        photo.truth.warp_color = {0.10f, 0.16f, 0.42f};
        photo.truth.ex = photo.truth.warp_ex = 60.0f;
        photo.truth.ey = photo.truth.warp_ey = 4.0f;
        photo.truth.rs = 0.05f;
        photo.truth.cy = 0.6f;
        photo.truth.yarn_width = 0.85f;
        photo.truth.warp_width = 0.9f;
        return photo;
    };
    const auto noisy = [&](glm::ivec3 pattern, float exposure) {
        test::RigPhoto photo = cloth(pattern);
        photo.noise = 0.03f;
        photo.vignetteSigmaPx = 150.0f;
        photo.exposure = exposure;
        return photo;
    };
    std::vector<Case> cases{{"twill", cloth({1, 3, 1})}, {"plain", cloth({1, 1, 1})}, {"satin noisy", noisy({4, 1, 2}, 1.6f)},
                            {"plain noisy", noisy({1, 1, 1}, 0.5f)}, {"twill noisy", noisy({1, 3, 1}, 0.5f)},
                            {"satin 4/1 noisy", noisy({4, 1, 2}, 0.5f)}};
    test::RigPhoto denim;
    denim.truth.pattern = {1, 3, 1};
    denim.truth.repeat = {2500.0f, 1600.0f};
    denim.size = 512;
    cases.push_back({"denim 512", denim});
    test::RigPhoto portrait = noisy({1, 3, 1}, 0.5f);
    portrait.size = 120;
    portrait.height = 160;
    cases.push_back({"portrait", portrait});
    for (float degrees : {3.0f, -3.0f}) {
        test::RigPhoto askew = noisy({1, 3, 1}, 0.5f);
        askew.turnDegrees = degrees;
        cases.push_back({degrees > 0 ? "askew +3" : "askew -3", askew});
    }
    for (glm::ivec3 pattern : {glm::ivec3(1, 1, 1), glm::ivec3(1, 3, 1), glm::ivec3(4, 1, 2)}) {
        test::RigPhoto backlit = cloth(pattern);
        backlit.truth.transmission = 0.5f;
        backlit.truth.transmission_gloss = 0.3f;
        backlit.noise = 0.03f;
        backlit.exposure = 0.5f;
        backlit.light = {0.02f, -0.15f, 0.0f};
        backlit.lightIntensity = 0.8f;
        cases.push_back({"backlit", backlit});
    }
    std::printf("| photo | ends found / truth | picks found / truth |\n|---|---|---|\n");
    int n = 0;
    for (const Case& c : cases) {
        const Shot shot = loadShot(test::writeCaptureShot(dir.string(), "rig" + std::to_string(n++), c.photo), "Swatch");
        const ThreadPeaks peaks = threadPeaks(shot.image, shot.uvPerPixel, 4.0 * M_PI / 180.0);
        const auto ratio = [](const std::optional<SpectralPeak>& p, double truth, const glm::dvec2& grad) {
            return p ? glm::length(p->frequency) / (truth * glm::length(grad)) : 0.0;
        };
        std::printf("| %s | %.3f | %.3f |\n", c.name, ratio(peaks.ends, c.photo.truth.repeat.x, gradientU(shot.uvPerPixel)),
                    ratio(peaks.picks, c.photo.truth.repeat.y, gradientV(shot.uvPerPixel)));
        std::fflush(stdout);
    }
    std::filesystem::remove_all(dir);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace woven;
    if (argc == 2 && std::string(argv[1]) == "--rig") return rigPhotos();
    std::vector<std::string> images;
    std::string spectrumDir;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--spectrum" && i + 1 < argc)
            spectrumDir = argv[++i];
        else
            images.push_back(a);
    }
    if (images.empty()) {
        std::fprintf(stderr, "usage: bench_threads IMAGE [IMAGE ...] [--spectrum DIR]\n");
        return 2;
    }
    std::printf("| image | across x: cycles/px, px a thread, threads | across y: cycles/px, px a thread, threads | s |\n");
    std::printf("|---|---|---|---|\n");
    for (const std::string& path : images) {
        const Image image = readImage(path);
        const auto start = std::chrono::steady_clock::now();
        const ThreadPeaks peaks = threadPeaks(image, glm::dmat2(1.0), 4.0 * M_PI / 180.0);
        const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const auto cell = [&](const std::optional<SpectralPeak>& p, int side) {
            if (!p) return std::string("none");
            const double f = glm::length(p->frequency);
            char buf[96];
            std::snprintf(buf, sizeof buf, "%.4f, %.2f, %.1f", f, 1.0 / f, f * side);
            return std::string(buf);
        };
        std::printf("| %s | %s | %s | %.2f |\n", std::filesystem::path(path).filename().c_str(),
                    cell(peaks.ends, image.width).c_str(), cell(peaks.picks, image.height).c_str(), took);
        if (peaks.ends && peaks.picks) {
            // The fold (thread_fold.h): each way of unfolding, the best weave's lattice score.
            const glm::dvec2 e = peaks.ends->frequency.x < 0.0 ? -peaks.ends->frequency : peaks.ends->frequency;
            const glm::dvec2 p = peaks.picks->frequency.y < 0.0 ? -peaks.picks->frequency : peaks.picks->frequency;
            const auto score = [&](const glm::dvec2& a, const glm::dvec2& b) {
                const WeaveLatticeScore best = rankWeavesBySpectrum(image, a, b).front();
                char buf[96];
                std::snprintf(buf, sizeof buf, "%.1f (%d, %d, %d)", best.score, best.pattern.x, best.pattern.y, best.pattern.z);
                return std::string(buf);
            };
            const UnfoldedThreads u = unfoldThreads(image, e, p);
            std::printf("  lattice score as found %s, ends unfolded %s, picks unfolded %s, both %s: threads %.1f x %.1f\n",
                        score(e, p).c_str(), score(unfolded(e), p).c_str(), score(e, unfolded(p)).c_str(),
                        score(unfolded(e), unfolded(p)).c_str(), glm::length(u.ends) * image.width,
                        glm::length(u.picks) * image.height);
        }
        if (!spectrumDir.empty()) {
            std::vector<float> lum(image.pixels.size());
            for (size_t i = 0; i < lum.size(); ++i) lum[i] = luminance(image.pixels[i]);
            const PowerSpectrum s = powerSpectrum(lum, image.width, image.height);
            printPeaks(s, 14);
            const SpectralNoiseFloor noise = spectralNoiseFloor(s);
            for (const glm::dvec2 d : {glm::dvec2(1, 0), glm::dvec2(0, 1)}) {
                std::vector<ThreadCandidate> cs = threadCandidates(s, noise, d, 4.0 * M_PI / 180.0, 3.0 / 512, kHighestThreadFrequency);
                std::sort(cs.begin(), cs.end(), [](auto& a, auto& b) { return a.score > b.score; });
                std::printf("  along (%g, %g):", d.x, d.y);
                for (size_t i = 0, n = 0; i < cs.size() && n < 6; ++i)
                    if (cs[i].height >= kLeastThreadPeakHeight && ++n)
                        std::printf(" [%.4f h %.1f s %.1f]", glm::length(cs[i].peak.frequency), cs[i].height, cs[i].score);
                std::printf("\n");
            }
            writeSpectrum(s,
                          spectrumDir + "/" + std::filesystem::path(path).stem().string() + ".pgm");
        }
    }
    return 0;
}
