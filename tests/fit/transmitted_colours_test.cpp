// The colours solved against reflected and backlit statistics together (transmitted_colours.h), on
// statistics made from known colours, so that the answer is known exactly.
#include <gtest/gtest.h>

#include <functional>
#include <random>

#include "transmitted_colours.h"
#include "yarn_transmission.h"

namespace woven {
namespace {

constexpr size_t kEntries = 8 * 8 * 3;  // block means: 8 x 8 blocks, RGB

struct Truth {
    glm::dvec3 weft{0.70, 0.62, 0.45}, warp{0.10, 0.16, 0.42};
    double exposure = 0.5, diffuse = 0.35, glossy = 0.15;  // t = 0.5, g = 0.3
};

// Six parts of a backlit shot, each block's share drawn at random (fixed seed), and the photo
// they make at the truth.
void backlitShot(const Truth& truth, std::mt19937& rng, TransmissionStats& parts, ImageStats& photo) {
    std::uniform_real_distribution<float> share(0.1f, 1.0f);
    for (std::vector<float>& part : parts.blockMeans) {
        part.resize(kEntries);
        for (size_t b = 0; b < kEntries; b += 3) part[b] = part[b + 1] = part[b + 2] = share(rng);  // grey, as renders of parts are
    }
    const std::array<glm::dvec3, kTransmittedRegionCount> tau = regionTransmittances(truth.weft, truth.warp);
    std::vector<float>& p = photo.values[kStatBlockMeans];
    p.assign(kEntries, 0.0f);
    for (size_t i = 0; i < kEntries; ++i)
        for (int r = 0; r < kTransmittedRegionCount; ++r)
            p[i] += float(truth.exposure * tau[size_t(r)][int(i % 3)] *
                          (truth.diffuse * parts.blockMeans[size_t(r)][i] +
                           truth.glossy * parts.blockMeans[size_t(kTransmittedRegionCount + r)][i]));
}

// A reflected shot's K_weft, K_warp and R, each block's drawn at random (fixed seed), R grey as
// `gloss` makes it from the weft's and the warp's draws and one more, and the photo they make at
// the truth with R scaled by `rsScale`.
void reflectedShot(const Truth& truth, std::mt19937& rng, const std::function<float(float, float, float)>& gloss,
                   double rsScale, LinearStats& reflected, ImageStats& photo) {
    std::uniform_real_distribution<float> share(0.1f, 1.0f);
    for (std::vector<float>& k : reflected.blockMeans) k.resize(kEntries);
    std::vector<float>& p = photo.values[kStatBlockMeans];
    p.resize(kEntries);
    for (size_t b = 0; b < kEntries; b += 3) {
        const float weft = share(rng), warp = share(rng), r = gloss(weft, warp, share(rng));
        for (size_t c = 0; c < 3; ++c) {
            reflected.blockMeans[0][b + c] = weft;
            reflected.blockMeans[1][b + c] = warp;
            reflected.blockMeans[2][b + c] = r;
            p[b + c] = float(truth.exposure * (truth.weft[int(c)] * weft + truth.warp[int(c)] * warp + rsScale * r));
        }
    }
}

// The joint solve of one reflected and one backlit shot, the exposure free, from `start`.
TransmittedColours solveFree(const LinearStats& reflected, const ImageStats& reflectedPhoto,
                             const TransmissionStats& parts, const ImageStats& backlitPhoto, const LinearColours& start) {
    const std::vector<std::optional<double>> free{std::nullopt};
    return solveColoursWithTransmission({&reflectedPhoto}, {reflected}, free, {&backlitPhoto}, {parts}, free, {start}, true);
}

// The colours, the exposure and t within 1 % of the truth's.
void expectTruth(const TransmittedColours& fit, const Truth& truth) {
    ASSERT_TRUE(fit.colours.valid);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(fit.colours.weft[c] / truth.weft[c], 1.0, 0.01) << "weft channel " << c;
        EXPECT_NEAR(fit.colours.warp[c] / truth.warp[c], 1.0, 0.01) << "warp channel " << c;
    }
    EXPECT_NEAR(fit.colours.exposure / truth.exposure, 1.0, 0.01);
    EXPECT_NEAR(fit.split.transmission(), 0.5, 0.01);
}

TEST(TransmittedColours, TheCrossingPassesTheSmallerOfTheTwoYarnsPerChannel) {
    const glm::dvec3 weft(0.70, 0.62, 0.45), warp(0.10, 0.16, 0.42);
    const auto tau = regionTransmittances(weft, warp);
    EXPECT_NEAR(tau[kWeftAlone].b, double(yarnTransmittance(glm::vec3(weft), 1.0f).b), 1e-7);
    EXPECT_NEAR(tau[kWarpAlone].r, double(yarnTransmittance(glm::vec3(warp), 1.0f).r), 1e-7);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(tau[kCrossing][c], std::min(tau[kWeftAlone][c], tau[kWarpAlone][c]));
    // A white yarn reflects all that enters it: it passes nothing, alone or crossed.
    const auto white = regionTransmittances(glm::dvec3(1.0), warp);
    EXPECT_EQ(white[kWeftAlone], glm::dvec3(0.0));
    EXPECT_EQ(white[kCrossing], glm::dvec3(0.0));
}

TEST(TransmittedColours, TheTransmissionOfKnownColoursIsSolvedExactly) {
    std::mt19937 rng(7);
    const Truth truth;
    TransmissionStats parts;
    ImageStats photo;
    backlitShot(truth, rng, parts, photo);
    const TransmissionSplit split = solveTransmission({&photo}, {parts}, {truth.exposure}, truth.weft, truth.warp);
    EXPECT_NEAR(split.transmission(), 0.5, 1e-5);
    EXPECT_NEAR(split.gloss(), 0.3, 1e-5);
    // A photo twice as bright asks for t = 1.1: t stays at most 1, along the same split.
    const TransmissionSplit bright = solveTransmission({&photo}, {parts}, {truth.exposure / 2.2}, truth.weft, truth.warp);
    EXPECT_NEAR(bright.transmission(), 1.0, 1e-6);
    EXPECT_NEAR(bright.gloss(), 0.3, 1e-5);
}

// The reflected shot is made degenerate on purpose: its gloss R lies where the two yarns lie,
// grey, so exposure x colour and exposure trade along a line (a grey share of each colour
// against the gloss), as a flash beside the lens nearly makes them. Its own solve then has no
// unique answer; the backlit shot's hue, (R_d / max R_d)^2, tells the points of that line apart.
TEST(TransmittedColours, TheBacklitShotTellsTheColoursFromTheGloss) {
    std::mt19937 rng(11);
    const Truth truth;
    LinearStats reflected;
    ImageStats reflectedPhoto;
    reflectedShot(truth, rng, [](float weft, float warp, float) { return 0.2f * (weft + warp); }, 1.0, reflected,
                  reflectedPhoto);
    TransmissionStats parts;
    ImageStats backlitPhoto;
    backlitShot(truth, rng, parts, backlitPhoto);

    // A start on the reflected shot's line of equal loss, 30 % brighter in exposure: each colour
    // c' = (e (c + 0.2) / e') - 0.2.
    LinearColours start;
    start.exposure = 1.3 * truth.exposure;
    start.weft = (truth.weft + 0.2) / 1.3 - 0.2;
    start.warp = glm::max((truth.warp + 0.2) / 1.3 - 0.2, glm::dvec3(0.002));
    const TransmittedColours fit = solveFree(reflected, reflectedPhoto, parts, backlitPhoto, start);
    expectTruth(fit, truth);
    EXPECT_NEAR(fit.split.gloss(), 0.3, 0.01);
    EXPECT_NEAR(fit.rsScale, 1.0, 0.01);
}

// The reflected renders made at an rs 0.8 times the truth's (the shot material's 0.04 for cloth's
// 0.05): the reflected shot alone is met exactly by the colours 0.8 times the truth's at an
// exposure 1.25 times, with R unscaled, and by the truth with R scaled 1.25 times. The backlit shot
// tells them apart.
TEST(TransmittedColours, TheBacklitShotTellsRsFromTheExposure) {
    std::mt19937 rng(12);
    const Truth truth;
    constexpr double kRsScale = 1.25;
    LinearStats reflected;
    ImageStats reflectedPhoto;
    reflectedShot(truth, rng, [](float, float, float r) { return 0.2f * r; }, kRsScale, reflected, reflectedPhoto);
    TransmissionStats parts;
    ImageStats backlitPhoto;
    backlitShot(truth, rng, parts, backlitPhoto);

    LinearColours start;
    start.exposure = kRsScale * truth.exposure;
    start.weft = truth.weft / kRsScale;
    start.warp = truth.warp / kRsScale;
    const TransmittedColours fit = solveFree(reflected, reflectedPhoto, parts, backlitPhoto, start);
    expectTruth(fit, truth);
    EXPECT_NEAR(fit.rsScale / kRsScale, 1.0, 0.01);
}

}  // namespace
}  // namespace woven
