#include "fit_loss.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace woven {

double colourError(const std::vector<float>& photo, const std::vector<float>& render, size_t stride) {
    const glm::dvec3 mean = channelMeans(photo, stride);
    double e = 0.0;
    for (size_t i = 0; i < photo.size(); ++i) {
        const double d = (double(render[i]) - photo[i]) / mean[int((i / stride) % 3)];
        e += d * d;
    }
    return e / double(std::max<size_t>(photo.size(), 1));
}

namespace {

double spectrumError(const std::vector<float>& photo, const std::vector<float>& render) {
    const size_t perChannel = photo.size() / 3;
    double e = 0.0;
    for (size_t c = 0; c < 3; ++c) {
        std::vector<float> sorted(photo.begin() + std::ptrdiff_t(c * perChannel), photo.begin() + std::ptrdiff_t((c + 1) * perChannel));
        std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(perChannel / 2), sorted.end());
        const double floor = std::max(double(sorted[perChannel / 2]), 1e-12);
        for (size_t i = c * perChannel; i < (c + 1) * perChannel; ++i) {
            const double d = std::log10(render[i] + floor) - std::log10(photo[i] + floor);
            e += d * d;
        }
    }
    return e / double(std::max<size_t>(photo.size(), 1));
}

double relativeError(const std::vector<float>& photo, const std::vector<float>& render) {
    double e = 0.0;
    for (size_t i = 0; i < photo.size(); ++i) {
        const double d = (double(render[i]) - photo[i]) / std::max(std::abs(double(photo[i])), 1e-9);
        e += d * d;
    }
    return e / double(std::max<size_t>(photo.size(), 1));
}

}  // namespace

glm::dvec3 channelMeans(const std::vector<float>& values, size_t stride) {
    glm::dvec3 mean(0.0), n(0.0);
    for (size_t i = 0; i < values.size(); ++i) {
        mean[int((i / stride) % 3)] += values[i];
        n[int((i / stride) % 3)] += 1.0;
    }
    return glm::max(mean / glm::max(n, glm::dvec3(1.0)), glm::dvec3(1e-4));
}

const std::array<double, kStatGroupCount>& lossWeights() {
    // The spectrum's log error is larger by nature (a factor of 2 in power is 0.09); at half the
    // colours' weight it still decides between weaves whose colours are only half fitted (stage 2
    // of fabric_fit.h): at 0.05 the synthetic 3/1 twill came out plain, at 0.5 a twill.
    // The tile fold weighs as the block means: both are relative colour errors.
    static const std::array<double, kStatGroupCount> w{1.0, 1.0, 0.5, 1.0, 0.1, 1.0};
    return w;
}

LossTerms loss(const ImageStats& photo, const ImageStats& render) {
    LossTerms t;
    t.error[kStatBlockMeans] = colourError(photo.values[kStatBlockMeans], render.values[kStatBlockMeans], 1);
    t.error[kStatQuantiles] = colourError(photo.values[kStatQuantiles], render.values[kStatQuantiles], 5);
    t.error[kStatSpectrum] = spectrumError(photo.values[kStatSpectrum], render.values[kStatSpectrum]);
    // Laid out channel by channel, the thread frequencies within: relative to each channel's mean
    // amplitude, so that the yarns' colours count as the block means' do.
    const size_t perChannel = photo.values[kStatThreadPeaks].size() / 3;
    if (perChannel > 0)
        t.error[kStatThreadPeaks] =
            colourError(photo.values[kStatThreadPeaks], render.values[kStatThreadPeaks], perChannel);
    t.error[kStatGram] = relativeError(photo.values[kStatGram], render.values[kStatGram]);
    t.error[kStatTileFold] = foldError(photo.fold, render.fold);
    for (int g = 0; g < kStatGroupCount; ++g) t.total += lossWeights()[size_t(g)] * t.error[size_t(g)];
    return t;
}

}  // namespace woven
