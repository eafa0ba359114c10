// The weave from the photo's spectrum alone (weave_lattice.h): each weave the fit tries, woven's
// render of it in the capture rig (capture_rig.h), shortlists itself and its complement only.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "capture_rig.h"
#include "shot.h"
#include "weave_candidates.h"
#include "weave_lattice.h"

namespace woven::test {
namespace {

namespace fs = std::filesystem;

TEST(WeaveLattice, EachRigWeaveShortlistsItselfAndItsComplementOnly) {
    const fs::path dir = fs::temp_directory_path() / ("woven_weave_lattice_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const WeaveCandidate& c : weaveCandidates()) {
        // The round trips' cloth (round_trip_test.cpp), with their noise and vignette; 8 samples
        // a pixel, as the lattice's peaks stand 10 (in log) above a floor this noise sets.
        RigPhoto photo;
        photo.truth.pattern = c.pattern;
        photo.truth.repeat = {800.0f, 600.0f};
        photo.truth.weft_color = {0.70f, 0.62f, 0.45f};
        photo.truth.warp_color = {0.10f, 0.16f, 0.42f};
        photo.truth.yarn_width = 0.85f;
        photo.truth.warp_width = 0.9f;
        photo.truth.cy = 0.6f;
        photo.spp = 8;
        photo.noise = 0.03f;
        photo.vignetteSigmaPx = 150.0f;
        const Shot shot = loadShot(writeCaptureShot(dir.string(), "shot", photo), "Swatch");
        // One cycle per weave element along U and along V, in pixels: what the fit's thread
        // counter measures (round_trip_test.cpp checks it to 3 %).
        const glm::dvec2 gradU(shot.uvPerPixel[0][0], shot.uvPerPixel[1][0]), gradV(shot.uvPerPixel[0][1], shot.uvPerPixel[1][1]);
        const auto ranking = rankWeavesBySpectrum(shot.image, gradU * double(photo.truth.repeat.x),
                                                  gradV * double(photo.truth.repeat.y));
        std::vector<glm::ivec3> expected{c.pattern, glm::ivec3(c.pattern.y, c.pattern.x, c.pattern.z)};
        if (expected[0] == expected[1]) expected.pop_back();  // plain and the 2/2 twills are their own complements
        std::vector<glm::ivec3> shortlist = weaveShortlist(ranking);
        const auto less = [](const glm::ivec3& a, const glm::ivec3& b) {
            return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
        };
        std::sort(shortlist.begin(), shortlist.end(), less);
        std::sort(expected.begin(), expected.end(), less);
        std::string got;
        for (const glm::ivec3& p : shortlist) got += " " + describeWeave(p);
        EXPECT_EQ(shortlist, expected) << describeWeave(c.pattern) << " shortlisted" << got;
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace woven::test
