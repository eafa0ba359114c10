// woven fit's synthetic round trips (docs/FIT.md): woven renders a known material in the capture
// rig (capture_rig.h) and the fit recovers it from that photo alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iostream>
#include <string>

#include "capture_rig.h"
#include "exposure_fold.h"
#include "fabric_fit.h"
#include "fit_output.h"
#include "shot.h"
#include "temp_dir_test.h"
#include "weave_candidates.h"  // describeWeave, for a failure's message

namespace woven::test {
namespace {

class RoundTrip : public TempDirTest {
protected:
    // `renders` > 0: a budget of renders instead of time, so the fit is the same on any machine.
    FitResult fit(const RigPhoto& photo, double seconds, int renders = 0, int spp = 2, uint64_t seed = 1) {
        return fit(std::vector<RigPhoto>{photo}, seconds, renders, spp, seed);
    }
    // Several shots of one swatch, in the rig under different lights.
    FitResult fit(const std::vector<RigPhoto>& photos, double seconds, int renders = 0, int spp = 2, uint64_t seed = 1) {
        shots_.clear();
        for (size_t i = 0; i < photos.size(); ++i)
            shots_.push_back(loadShot(writeCaptureShot(dir_.string(), "shot" + std::to_string(i), photos[i]), "Swatch"));
        FitOptions options;
        options.seconds = seconds;
        options.renders = renders;
        options.render.spp = spp;
        options.render.seed = seed;
        const std::atomic<bool> cancel{false};
        FitResult r = fitFabric(shots_, options, cancel);
        // What a failure needs to be understood.
        std::cerr << "fit: " << describeWeave(r.params.pattern) << ", repeat " << r.params.repeat.x << " x "
                  << r.params.repeat.y << ", loss " << r.loss << ", " << r.evaluations << " renders, weft "
                  << r.params.weft_color.r << " " << r.params.weft_color.g << " " << r.params.weft_color.b << ", warp "
                  << r.params.warp_color.r << " " << r.params.warp_color.g << " " << r.params.warp_color.b
                  << ", exposure " << r.exposure << ", rs " << r.params.rs << ", ex " << r.params.ex << ", ey "
                  << r.params.ey << ", widths " << r.params.yarn_width << " " << r.params.warp_width << ", cy "
                  << r.params.cy << ", transmission " << r.params.transmission << ", transmission_gloss "
                  << r.params.transmission_gloss
                  << (r.complete ? "" : ", incomplete") << "\n";
        for (const std::string& w : r.warnings) std::cerr << "fit: " << w << "\n";
        return r;
    }

    // The rig's cloth: 8 ends and 6 picks per cm (27 and 20 threads across the photo's 3.4 cm,
    // 4.7 and 6.3 pixels a thread at 128 pixels: below 4 pixels a thread the pixel grid folds
    // the 3rd harmonic onto half the fundamental's frequency), yarns of two colours.
    static WovenParams cloth(glm::ivec3 pattern) {
        WovenParams p;
        p.pattern = pattern;
        p.repeat = {800.0f, 600.0f};  // per metre: one UV unit is a metre
        p.weft_color = {0.70f, 0.62f, 0.45f};
        p.warp_color = {0.10f, 0.16f, 0.42f};
        p.ex = p.warp_ex = 60.0f;
        p.ey = p.warp_ey = 4.0f;
        p.rs = 0.05f;
        p.cy = 0.6f;
        p.yarn_width = 0.85f;
        p.warp_width = 0.9f;
        return p;
    }

    // A photo as a phone takes it: 3 % sensor noise, a 150 px vignette, an exposure the fit is
    // not told.
    static RigPhoto noisyPhoto(glm::ivec3 pattern, float exposure = 0.5f) {
        RigPhoto photo;
        photo.truth = cloth(pattern);
        photo.noise = 0.03f;
        photo.vignetteSigmaPx = 150.0f;
        photo.exposure = exposure;
        photo.exposureKnown = false;
        return photo;
    }

    // A flash shot and a shot lit from 15 cm behind the swatch, the lamp 2 cm aside so that the
    // glossy part's forward peak falls inside the frame, 10 times the flash's intensity as a lamp
    // behind cloth is exposed for; yarns that pass t = 0.5 with g = 0.3, 3 % noise, the exposure
    // (shared) given.
    static std::vector<RigPhoto> flashAndBacklit(glm::ivec3 pattern) {
        RigPhoto flash;
        flash.truth = cloth(pattern);
        flash.truth.transmission = 0.5f;
        flash.truth.transmission_gloss = 0.3f;
        flash.noise = 0.03f;
        flash.exposure = 0.5f;
        RigPhoto backlit = flash;
        backlit.light = {0.02f, -0.15f, 0.0f};
        backlit.lightIntensity = 0.8f;
        backlit.seed += 1;
        return {flash, backlit};
    }

    // The weave class, exact, from the pair of photos (flashAndBacklit()) as a phone takes
    // them: a 150 px vignette and an exposure the fit is not told.
    FitResult expectWeaveFromAFlashAndABacklitShot(glm::ivec3 pattern, uint64_t seed = 1) {
        std::vector<RigPhoto> photos = flashAndBacklit(pattern);
        for (RigPhoto& photo : photos) {
            photo.vignetteSigmaPx = 150.0f;
            photo.exposureKnown = false;
        }
        FitResult r = fit(photos, 600.0, 250, 8, seed);
        EXPECT_EQ(r.params.pattern, pattern) << "fitted " << describeWeave(r.params.pattern) << " at seed " << seed;
        expectThreadCounts(r, photos[0].truth);
        expectBeatsLambertianPlane(r.shots[0]);
        return r;
    }

    // The weave at each of the fit's render seeds 1 to 3, and the worst channel of the colours
    // (worstColourError()) over them (expectOverSeeds()).
    void expectWeaveAndColoursOverSeeds(glm::ivec3 pattern, double median, double largest) {
        std::vector<double> errors;
        for (uint64_t seed = 1; seed <= kSeeds; ++seed)
            errors.push_back(worstColourError(expectWeaveFromAFlashAndABacklitShot(pattern, seed), cloth(pattern), 0.5f));
        expectOverSeeds(errors, median, largest, "worst colour channel");
    }

    // A statistic of a fit at each of its render seeds 1 to kSeeds: their median within `median`
    // and each within `largest`. A fit is chaotic in its arithmetic, so one seed's result moves
    // with the CPU's kernels (Embree's, FFTW's, libm's); the bounds come from the distribution
    // measured over seeds and Embree's kernel paths, written beside each test.
    static void expectOverSeeds(std::vector<double> values, double median, double largest, const std::string& what) {
        for (size_t i = 0; i < values.size(); ++i) std::cerr << "fit: seed " << i + 1 << ", " << what << " " << values[i] << "\n";
        std::sort(values.begin(), values.end());
        EXPECT_LE(values[values.size() / 2], median) << "the median " << what << " over seeds 1 to " << kSeeds;
        EXPECT_LE(values.back(), largest) << "the largest " << what << " over seeds 1 to " << kSeeds;
    }
    static constexpr uint64_t kSeeds = 3;

    // Thread counts within 3 %, the bound: the spectrum's peaks, located to a tenth of a
    // bin of 1/128 cycle per pixel, are good to 0.5 % at 27 threads across.
    static void expectThreadCounts(const FitResult& r, const WovenParams& truth) {
        EXPECT_NEAR(r.params.repeat.x / truth.repeat.x, 1.0, 0.03);
        EXPECT_NEAR(r.params.repeat.y / truth.repeat.y, 1.0, 0.03);
    }

    // The largest relative error of a channel of either yarn's colour times the fitted exposure
    // over the photo's: a free exposure scales the render as the colours do, so a photo shows
    // only their product.
    static double worstColourError(const FitResult& r, const WovenParams& truth, float exposure) {
        const glm::vec3 weft = r.params.weft_color * float(r.exposure) / exposure;
        const glm::vec3 warp = r.params.warp_color * float(r.exposure) / exposure;
        std::cerr << "fit: weft x exposure (" << weft.r << ", " << weft.g << ", " << weft.b << "), warp x exposure ("
                  << warp.r << ", " << warp.g << ", " << warp.b << ")\n";
        double worst = 0.0;
        for (int c = 0; c < 3; ++c)
            worst = std::max({worst, std::abs(weft[c] / truth.weft_color[c] - 1.0), std::abs(warp[c] / truth.warp_color[c] - 1.0)});
        return worst;
    }

    // The light's fall-off and the flash's highlight (the block means) nearer the photo's than
    // the best Lambertian plane's under the same light, as the issue asks of real photos.
    static void expectBeatsLambertianPlane(const ShotFit& shot) {
        std::cerr << "fit: block means error " << shot.terms.error[kStatBlockMeans] << ", the best Lambertian plane's "
                  << shot.lambertianBlockMeansError << "\n";
        ASSERT_GE(shot.lambertianBlockMeansError, 0.0);
        EXPECT_LT(shot.terms.error[kStatBlockMeans], shot.lambertianBlockMeansError);
    }

    // The thread counts are the fit's first stage; this budget ends the fit inside the weave
    // search.
    static double seconds() { return 2.0; }

    // The weave class, exact, from a photo with sensor noise, a vignette and an exposure the fit
    // is not told: 0.5 by default, where nothing clips; at 1.6 the rig's flash clips 17 % (twill)
    // to 50 % (satin) of the photo's pixels at the PNG's 1, which the fit's renders must clip
    // alike (photo_model.h) to be compared (the truth's loss was above a wrong fit's). The budget: the spectrum's
    // shortlist of a weave and its complement, each refined over 50 renders (stage 2), and the
    // thread counts' calibration; 8 samples a pixel, as at 2 to 4 the renders' own noise raises
    // their spectrum above the photo's and the truth's loss above a wrong fit's.
    FitResult expectWeave(glm::ivec3 pattern, float exposure = 0.5f, int renders = 115) {
        const RigPhoto photo = noisyPhoto(pattern, exposure);
        FitResult r = fit(photo, 600.0, renders, 8);
        EXPECT_EQ(r.params.pattern, pattern) << "fitted " << describeWeave(r.params.pattern);
        expectThreadCounts(r, photo.truth);
        expectBeatsLambertianPlane(r.shots[0]);
        return r;
    }

    // The truth's tile fold against the photo's (tile_fold.h): the photo folded on its measured
    // threads, the render on the material's. Measured 1.7e-5 (plain) and 5.8e-5 (3/1 twill) with
    // the threads' frequencies refined by the fold's sharpness; 5.7e-4 and 2.1e-3 with the
    // spectrum's peaks alone, whose 0.9 % error drifts the fold by a tenth of a thread at the
    // edges. The 5-end satin's: 5.7e-5 (2026-12-05; it was 2e-3 when its ends were measured 0.5 %
    // short, 796 per metre for 800), 2.2e-5 with the photo folded on the exact threads.
    void expectTruthFolds(glm::ivec3 pattern) {
        const RigPhoto photo = noisyPhoto(pattern);
        shots_ = {loadShot(writeCaptureShot(dir_.string(), "shot", photo), "Swatch")};
        FitOptions options;
        options.render.spp = 8;
        const FitResult truth = fitLoss(shots_, photo.truth, options);
        EXPECT_LT(truth.shots[0].terms.error[kStatTileFold], 2e-4);
        EXPECT_NEAR(truth.exposure, photo.exposure, 0.01);
    }

    std::vector<Shot> shots_;
};

TEST_F(RoundTrip, TwillThreadCounts) {
    RigPhoto photo;
    photo.truth = cloth({1, 3, 1});
    const FitResult r = fit(photo, seconds());
    expectThreadCounts(r, photo.truth);
    const auto counts = threadsPerCm(shots_[0], r.params.repeat);
    ASSERT_TRUE(counts);
    EXPECT_NEAR(counts->x, 8.0, 0.24);
    EXPECT_NEAR(counts->y, 6.0, 0.18);
    // The photo's thread directions are the render's: the swatch lies along the camera's axes.
    EXPECT_LT(r.shots[0].directionError.x, 1.0);
    EXPECT_LT(r.shots[0].directionError.y, 1.0);
}

// Denim's 25 ends and 16 picks per cm as a 3/1 twill at 512 pixels (6 and 9.4 pixels a thread,
// yarns of full width): the twill's lattice folded by the pixel grid puts a point 3.9 degrees off
// the ends' axis at 2.25 times their frequency whose folded harmonics outscored the ends' own
// (bench_fit counted 2.25 times the ends); the picks' direction, not turned, rules it out
// (thread_frequencies.h).
TEST_F(RoundTrip, DenimThreadCountsAt512Pixels) {
    RigPhoto photo;
    photo.truth.pattern = {1, 3, 1};
    photo.truth.repeat = {2500.0f, 1600.0f};
    photo.truth.weft_color = {0.70f, 0.62f, 0.45f};
    photo.truth.warp_color = {0.10f, 0.16f, 0.42f};
    photo.size = 512;
    expectThreadCounts(fit(photo, seconds()), photo.truth);
}

// A photo not cropped square (120 x 160, as a phone's portrait frame): the spectrum's bins differ
// either way.
TEST_F(RoundTrip, TwillWeaveClassFromAPortraitPhoto) {
    RigPhoto photo = noisyPhoto({1, 3, 1});
    photo.size = 120;
    photo.height = 160;
    const FitResult r = fit(photo, 600.0, 115, 8);
    EXPECT_EQ(r.params.pattern, photo.truth.pattern) << "fitted " << describeWeave(r.params.pattern);
    expectThreadCounts(r, photo.truth);
    expectBeatsLambertianPlane(r.shots[0]);
}

TEST_F(RoundTrip, PlainWeaveThreadCounts) {
    RigPhoto photo;
    photo.truth = cloth({1, 1, 1});
    expectThreadCounts(fit(photo, seconds()), photo.truth);
}

TEST_F(RoundTrip, SatinThreadCountsWithNoiseVignetteAndUnknownExposure) {
    const RigPhoto photo = noisyPhoto({4, 1, 2}, 1.6f);
    expectThreadCounts(fit(photo, seconds()), photo.truth);
}

// The plain weave's class from the flash photo alone. Its colours x exposure are not asserted:
// from one flash photo they are loosely held, and their worst channel at the fit's render seed 1
// with 250 renders was 4.7 % on the AVX-512 path and 27.6 % with Embree pinned to AVX2 (15.7 and
// 10.9 % at seeds 2 and 3; docs/FIT.md): a single seed's pass was one draw of a wide distribution.
// What the flash alone does hold, the photo's mean colour, FoldedMaterialRendersAsItsPhotoInItsOwnRig checks.
TEST_F(RoundTrip, PlainWeaveClassWithNoiseVignetteAndUnknownExposure) { expectWeave({1, 1, 1}); }
TEST_F(RoundTrip, TwillWeaveClassWithNoiseVignetteAndUnknownExposure) { expectWeave({1, 3, 1}); }
TEST_F(RoundTrip, SatinWeaveClassWithNoiseVignetteAndUnknownExposure) { expectWeave({4, 1, 2}); }
// Half the satin's photo clipped (exposure 1.6): the weave and thread counts at each seed; the
// fit's block means' error over the best Lambertian plane's, near 1 here (the clipped highlight
// is flat in both), measured at the fit's render seeds 1 to 3 (2026-12-07; expectOverSeeds()):
// AVX-512 0.58, 0.64, 0.72, SSE4.2 1.29, 0.52, 1.09, AVX2 0.86, 0.58, 0.73. Its median is held
// within 1.3 and each within 1.6: where half the photo clips, the fit is not always nearer the
// photo's fall-off than a plain colour is.
TEST_F(RoundTrip, SatinWeaveClassFromAPhotoHalfClipped) {
    const RigPhoto photo = noisyPhoto({4, 1, 2}, 1.6f);
    std::vector<double> ratios;
    for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const FitResult r = fit(photo, 600.0, 115, 8, seed);
        EXPECT_EQ(r.params.pattern, photo.truth.pattern) << "fitted " << describeWeave(r.params.pattern) << " at seed " << seed;
        expectThreadCounts(r, photo.truth);
        ratios.push_back(r.shots[0].terms.error[kStatBlockMeans] / r.shots[0].lambertianBlockMeansError);
    }
    expectOverSeeds(ratios, 1.3, 1.6, "block means error over the best Lambertian plane's");
}

// The backlit photo's light through the yarns (MODEL_TRANSMISSION.md), from flashAndBacklit()'s
// pair, the exposure given. With a free one (0.478 fitted for 0.5) t came out 0.589
// and the backlit render's red 13 % low: the transmitted colour t (1 - R_d) R_d^2 / max(R_d)^2
// doubles the colours' errors and the yarns' widths set how much of each yarn the light crosses
// (docs/FIT.md).
TEST_F(RoundTrip, PlainWeaveTransmissionFromABacklitShot) {
    const std::vector<RigPhoto> photos = flashAndBacklit({1, 1, 1});
    const RigPhoto& flash = photos[0];
    const FitResult r = fit(photos, 600.0, 250, 8);
    EXPECT_EQ(r.params.pattern, flash.truth.pattern) << "fitted " << describeWeave(r.params.pattern);
    expectThreadCounts(r, flash.truth);
    // Measured 0.450 (0.526 before the colours were solved against both photos, which brought
    // the satin's t within 1.3 %; the next test), and 0.455 and 0.457 at the fit's render seeds
    // 2 and 3: 10 % low at every seed, with the split between the glossy and the diffuse part,
    // which is not checked, at 0.20 to 0.26 for 0.3 and stage 4 ending at ex 56 to 85 and ey 5.0
    // to 7.6 for 60 and 4 (docs/FIT.md). The bound leaves that bias room.
    EXPECT_NEAR(r.params.transmission, 0.5f, 0.06f);
    // Each photo's mean colour, the render's within 5 % per channel.
    for (size_t i = 0; i < shots_.size(); ++i) {
        glm::dvec3 photo(0.0), render(0.0);
        for (const glm::vec3& v : shots_[i].image.pixels) photo += glm::dvec3(v);
        for (const glm::vec3& v : r.shots[i].render.pixels) render += glm::dvec3(v);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(render[c] / photo[c], 1.0, 0.05) << "shot " << i << " channel " << c;
    }
    expectBeatsLambertianPlane(r.shots[0]);
    EXPECT_LT(r.shots[1].lambertianBlockMeansError, 0.0) << "a backlit shot has no Lambertian plane to beat";
}

// A swatch laid 3 degrees askew (either way) of the shot's mesh: the fit renders its cloth turned as
// the photo's threads lie (Shot turnedShot), so the render's threads run along the photo's. Not
// turned, the twill's loss ended at 0.207 (its truth's about 0.017) with the warp 27 % low; turned,
// 0.017, the weft within 1 % and the warp within 7 %.
TEST_F(RoundTrip, TwillLaidAskew) {
    for (float degrees : {3.0f, -3.0f}) {
        RigPhoto photo = noisyPhoto({1, 3, 1});
        photo.turnDegrees = degrees;
        const FitResult r = fit(photo, 600.0, 115, 8);
        EXPECT_EQ(r.params.pattern, photo.truth.pattern) << "fitted " << describeWeave(r.params.pattern);
        expectThreadCounts(r, photo.truth);
        EXPECT_LT(r.shots[0].directionError.x, 0.5) << degrees << " degrees";
        EXPECT_LT(r.shots[0].directionError.y, 0.5) << degrees << " degrees";
    }
}

TEST_F(RoundTrip, PlainWeaveTruthFoldsOntoThePhoto) { expectTruthFolds({1, 1, 1}); }
TEST_F(RoundTrip, TwillTruthFoldsOntoThePhoto) { expectTruthFolds({1, 3, 1}); }
TEST_F(RoundTrip, SatinTruthFoldsOntoThePhoto) { expectTruthFolds({4, 1, 2}); }

// The twill and the satin from the pair of photos. The weave is chosen by the flash
// shot's loss (fabric_fit.h, stage 2): with the backlit shot's loss counted, the fit chose the
// 3/1 twill's complement (seeds 1 and 2) or a plain weave (seed 3), and the satin's complement
// (seeds 1 to 3) (2026-12-05). The colours, the exposure and rs are solved against both photos
// (transmitted_colours.h) and polished (stage 5). The worst channel of colour x exposure,
// per cent, at the fit's render seeds 1 to 5 on three of Embree's kernel paths (2026-12-07, the
// project's VM, an AVX-512 CPU; WOVEN_EMBREE_CONFIG, README.md; docs/FIT.md has the table):
//   twill  AVX-512 1.6, 3.7, 3.9, 2.2, 4.9   SSE4.2 1.5, 0.6, 4.7, 4.1, 3.0   AVX2 5.5, 1.1, 0.8, 5.2, 4.1
//   satin  AVX-512 2.8, 1.3, 10.5, 2.3, 8.3  SSE4.2 9.8, 2.2, 9.0, 4.5, 6.6   AVX2 12.0, 4.0, 8.5, 6.6, 7.0
// (the AVX-512 row measured 2026-12-06), the weave right in all 30. One seed's 5 % held on one
// path and failed on another (the twill's seed 1, 1.6 % and 5.5 %), so each test asserts seeds 1
// to 3: the twill's median within 5 % and each within 8 % (its 15 measured: median 3.7 %, the
// largest 5.5 %); the satin's median within 12 % and each within 15 % (median 6.6 %, the largest
// 12.0 %; its warp, a fifth of its face, is loosely held: docs/FIT.md).
TEST_F(RoundTrip, TwillWeaveClassAndColoursFromAFlashAndABacklitShot) {
    expectWeaveAndColoursOverSeeds({1, 3, 1}, 0.05, 0.08);
}
TEST_F(RoundTrip, SatinWeaveClassAndColoursFromAFlashAndABacklitShot) {
    expectWeaveAndColoursOverSeeds({4, 1, 2}, 0.12, 0.15);
}

// The satin's colours and light through its yarns from the pair, the exposure given (the shot's
// default, 1 in a shot file): rs is then one of stage 4's axes. Measured at the fit's render
// seeds 1 to 3 (2026-12-07; expectOverSeeds()), the worst channel AVX-512 2.7, 4.1, 5.8 %,
// SSE4.2 6.1, 7.5, 4.6 %, AVX2 1.4, 10.0, 4.3 % (seeds 4 and 5 on AVX-512: 5.2, 9.1 %), held at
// a median within 8 % and each within 13 %; t's error AVX-512 2.4, 4.2, 7.3 %, SSE4.2 2.5, 4.2,
// 6.7 %, AVX2 4.0, 11.6, 8.1 % of 0.5, held at a median within 10 % and each within 15 %.
TEST_F(RoundTrip, SatinColoursAndTransmissionFromAFlashAndABacklitShot) {
    const std::vector<RigPhoto> photos = flashAndBacklit({4, 1, 2});
    std::vector<double> colours, transmission;
    for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
        const FitResult r = fit(photos, 600.0, 250, 8, seed);
        EXPECT_EQ(r.params.pattern, photos[0].truth.pattern) << "fitted " << describeWeave(r.params.pattern) << " at seed " << seed;
        // The exposure given: r.exposure is 1, the colours absolute.
        colours.push_back(worstColourError(r, photos[0].truth, 1.0f));
        transmission.push_back(std::abs(r.params.transmission - 0.5) / 0.5);
    }
    expectOverSeeds(colours, 0.08, 0.13, "worst colour channel");
    expectOverSeeds(transmission, 0.10, 0.15, "transmission's relative error");
}

// A fitted material reproduces its photo (issue 46): a flash photo at exposure 0.5, not told,
// the fit's exposure folded into its material (exposure_fold.h), which, rendered in the shot's
// own rig at the light it states, has the photo's mean colour within 5 % per channel (measured
// 0.02 to 0.08 %).
TEST_F(RoundTrip, FoldedMaterialRendersAsItsPhotoInItsOwnRig) {
    const FitResult r = fit(noisyPhoto({1, 1, 1}), 600.0, 115, 8);
    const ExposureFold fold = foldFittedExposure(shots_, r);
    ASSERT_TRUE(fold.folded) << fold.note;
    EXPECT_NE(fold.note.find("folded"), std::string::npos) << fold.note;
    std::vector<Shot> stated = shots_;
    for (Shot& shot : stated) shot.photo.exposure = 1.0f;
    FitOptions options;
    options.render.spp = 8;
    const FitResult rendered = fitLoss(stated, fold.params, options);
    glm::dvec3 photo(0.0), render(0.0);
    for (const glm::vec3& v : stated[0].image.pixels) photo += glm::dvec3(v);
    for (const glm::vec3& v : rendered.shots[0].render.pixels) render += glm::dvec3(v);
    std::cerr << "fit: exposure " << r.exposure << " folded; render / photo " << render.r / photo.r << " "
              << render.g / photo.g << " " << render.b / photo.b << "\n";
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(render[c] / photo[c], 1.0, 0.05) << "channel " << c;
}

// Where the folded colours would pass 1 the material is kept as fitted and the note says the
// light was brighter than the shot states; where a backlit shot tied the colours to the exposure
// the fold would change the light through the yarns, and it is kept too; at exposure 1 there is
// nothing to say.
TEST(ExposureFold, FoldsWhereTheMaterialCanTakeIt) {
    WovenParams p;
    p.weft_color = {0.70f, 0.62f, 0.45f};
    p.warp_color = {0.10f, 0.16f, 0.42f};
    p.rs = 0.05f;
    const ExposureFold dim = foldExposure(p, 0.5);
    ASSERT_TRUE(dim.folded) << dim.note;
    EXPECT_NEAR(dim.params.rs, 0.025f, 1e-6f);
    EXPECT_NEAR(dim.params.weft_color.r, 0.5f * 0.70f * 0.95f / 0.975f, 1e-6f);

    const ExposureFold bright = foldExposure(p, 1.6);
    EXPECT_FALSE(bright.folded);
    EXPECT_EQ(bright.params.weft_color, p.weft_color);
    EXPECT_NE(bright.note.find("brighter"), std::string::npos) << bright.note;

    p.transmission = 0.5f;
    const ExposureFold backlit = foldExposure(p, 0.5);
    EXPECT_FALSE(backlit.folded);
    EXPECT_NE(backlit.note.find("backlit"), std::string::npos) << backlit.note;
    const ExposureFold near = foldExposure(p, 0.99);
    EXPECT_TRUE(near.folded) << near.note;
    EXPECT_LT(near.params.transmission, 0.5f);

    EXPECT_TRUE(foldExposure(p, 1.0).note.empty());
}

}  // namespace
}  // namespace woven::test
