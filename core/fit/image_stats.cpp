#include "image_stats.h"

#include <algorithm>
#include <cmath>

#include "luminance.h"
#include "power_spectrum.h"

namespace woven {

namespace {

constexpr int kMeanBlocks = 8;
constexpr int kQuantileBlocks = 4;
constexpr std::array<float, 5> kQuantiles{0.1f, 0.3f, 0.5f, 0.7f, 0.9f};
constexpr int kSpectrumBinsY = 32;  // over fy in [-0.5, 0.5): bins of 1/32 cycle per pixel
constexpr int kSpectrumBinsX = kSpectrumBinsY / 2;

// On the image averaged over 2 x 2 pixels: a photo's sensor noise widens the spread of single
// pixels, which would read as yarns of more different colours.
std::vector<float> quantiles(const Image& im) {
    const int w = std::max(1, im.width / 2), h = std::max(1, im.height / 2);
    std::vector<std::vector<float>> cells(size_t(kQuantileBlocks) * kQuantileBlocks * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec3 v(0.0f);
            int n = 0;
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx)
                    if (2 * x + dx < im.width && 2 * y + dy < im.height) {
                        v += im.at(2 * x + dx, 2 * y + dy);
                        ++n;
                    }
            v /= float(std::max(n, 1));
            const size_t b = size_t(y * kQuantileBlocks / h) * kQuantileBlocks + size_t(x * kQuantileBlocks / w);
            for (int c = 0; c < 3; ++c) cells[3 * b + c].push_back(v[c]);
        }
    std::vector<float> out;
    for (std::vector<float>& cell : cells)
        for (float q : kQuantiles) {
            if (cell.empty()) {
                out.push_back(0.0f);
                continue;
            }
            const size_t k = std::min(cell.size() - 1, size_t(q * float(cell.size())));
            std::nth_element(cell.begin(), cell.begin() + std::ptrdiff_t(k), cell.end());
            out.push_back(cell[k]);
        }
    return out;
}

void spectrumStats(const Image& im, const std::vector<glm::dvec2>& threads, std::vector<float>& out,
                   std::vector<float>& peaks) {
    std::vector<float> channel(im.pixels.size());
    for (int c = 0; c < 3; ++c) {
        for (size_t i = 0; i < channel.size(); ++i) channel[i] = im.pixels[i][c];
        const PowerSpectrum s = powerSpectrum(channel, im.width, im.height);
        for (const glm::dvec2& f : threads) peaks.push_back(float(std::sqrt(powerNear(s, f))));
        std::vector<double> bins(size_t(kSpectrumBinsX) * kSpectrumBinsY, 0.0);
        for (int ky = 0; ky < s.height; ++ky) {
            const int sy = ky <= s.height / 2 ? ky : ky - s.height;
            const double fy = double(sy) / s.height;
            for (int kx = 0; kx <= s.width / 2; ++kx) {
                const double fx = double(kx) / s.width;
                // The lowest frequencies are the fall-off the block means compare already.
                if (std::hypot(kx, sy) < 3.0) continue;
                const int bx = std::min(kSpectrumBinsX - 1, int(fx * 2.0 * kSpectrumBinsX));
                const int by = std::clamp(int((fy + 0.5) * kSpectrumBinsY), 0, kSpectrumBinsY - 1);
                bins[size_t(by) * kSpectrumBinsX + size_t(bx)] += s.at(kx, ky);
            }
        }
        for (double b : bins) out.push_back(float(b));
    }
}

std::vector<float> gram(const Image& im) {
    constexpr int kFeatures = 5;
    std::array<double, kFeatures * kFeatures> m{};
    double n = 0.0;
    for (int y = 1; y + 1 < im.height; ++y)
        for (int x = 1; x + 1 < im.width; ++x) {
            const glm::vec3& p = im.at(x, y);
            const float gx = 0.5f * (luminance(im.at(x + 1, y)) - luminance(im.at(x - 1, y)));
            const float gy = 0.5f * (luminance(im.at(x, y + 1)) - luminance(im.at(x, y - 1)));
            const std::array<double, kFeatures> f{p.r, p.g, p.b, std::abs(gx), std::abs(gy)};
            for (int i = 0; i < kFeatures; ++i)
                for (int j = i; j < kFeatures; ++j) m[size_t(i * kFeatures + j)] += f[size_t(i)] * f[size_t(j)];
            n += 1.0;
        }
    std::vector<float> out;
    for (int i = 0; i < kFeatures; ++i)
        for (int j = i; j < kFeatures; ++j) out.push_back(float(m[size_t(i * kFeatures + j)] / std::max(n, 1.0)));
    return out;
}

}  // namespace

std::vector<float> blockMeans(const Image& im) {
    std::vector<double> sum(size_t(kMeanBlocks) * kMeanBlocks * 3, 0.0);
    std::vector<double> count(size_t(kMeanBlocks) * kMeanBlocks, 0.0);
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const size_t b = size_t(y * kMeanBlocks / im.height) * kMeanBlocks + size_t(x * kMeanBlocks / im.width);
            for (int c = 0; c < 3; ++c) sum[3 * b + c] += im.at(x, y)[c];
            count[b] += 1.0;
        }
    std::vector<float> out(sum.size());
    for (size_t i = 0; i < sum.size(); ++i) out[i] = float(sum[i] / std::max(count[i / 3], 1.0));
    return out;
}

const std::array<const char*, kStatGroupCount>& statGroupNames() {
    static const std::array<const char*, kStatGroupCount> names{"block means", "quantiles", "spectrum", "thread peaks", "gram", "tile fold"};
    return names;
}

ImageStats imageStats(const Image& image, const std::vector<glm::dvec2>& threads, const ThreadGrid* grid) {
    ImageStats s;
    s.values[kStatBlockMeans] = blockMeans(image);
    s.values[kStatQuantiles] = quantiles(image);
    spectrumStats(image, threads, s.values[kStatSpectrum], s.values[kStatThreadPeaks]);
    s.values[kStatGram] = gram(image);
    if (grid) s.fold = foldTile(image, *grid);
    return s;
}

}  // namespace woven
