// `woven fit` and `woven render` on shot files, run as a user does: bad input refused with a
// message naming the file, a budget too short for the stages, the report folder.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "capture_rig.h"
#include "flat_cloth.h"
#include "frame_io.h"
#include "gltf_writer.h"
#include "image_io.h"
#include "run_woven.h"

namespace woven::test {
namespace {

std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class FitCommand : public CommandTest {
protected:
    // A small rig (64 pixels: the commands' behaviour, not the fit's accuracy, is tested here).
    std::string shot() {
        RigPhoto photo;
        photo.truth.pattern = {1, 2, 1};
        photo.truth.repeat = {800.0f, 800.0f};
        photo.size = 64;
        photo.spp = 4;
        return writeCaptureShot(dir_.string(), "shot", photo);
    }
    RunResult fit(const std::string& shotFile, const std::string& options = "--target Swatch") {
        return runWovenCommand("fit '" + shotFile + "' " + options + " -o '" + file("out.json") + "'");
    }
};

TEST_F(FitCommand, ShotWithoutPhotoKeyIsRefused) {
    const std::string path = writeShotFile(dir_.string(), "nophoto", 64, "");
    const RunResult r = fit(path);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find(path + ": no \"photo\" key"), std::string::npos) << r.out;
}

TEST_F(FitCommand, PhotoOfAnotherSizeIsRefused) {
    shot();  // shot.png, 64 x 64
    const std::string path = writeShotFile(dir_.string(), "bigger", 96, "{\"image\": \"shot.png\"}");
    const RunResult r = fit(path);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find(path + ": photo.image: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("is 64x64 but the render is 96x96"), std::string::npos) << r.out;
}

TEST_F(FitCommand, MissingAndUndecodableImagesAreRefused) {
    const std::string missing = writeShotFile(dir_.string(), "missing", 64, "{\"image\": \"absent.png\"}");
    RunResult r = fit(missing);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find(missing + ": photo.image: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("absent.png"), std::string::npos) << r.out;

    std::ofstream(file("garbage.png")) << "not a PNG at all";
    const std::string garbage = writeShotFile(dir_.string(), "garbage", 64, "{\"image\": \"garbage.png\"}");
    r = fit(garbage);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find(garbage + ": photo.image: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("garbage.png"), std::string::npos) << r.out;
}

TEST_F(FitCommand, TargetThatNamesNothingIsRefused) {
    const std::string path = shot();
    const RunResult r = fit(path, "--target Curtain");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find(path + ": "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("Curtain"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("'Swatch'"), std::string::npos) << r.out;  // what it could have named
}

TEST_F(FitCommand, BadPhotoKeysAreNamed) {
    const std::string path = writeShotFile(dir_.string(), "bad", 64, "{\"image\": \"shot.png\", \"encoding\": \"log\"}");
    const RunResult r = fit(path);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find(path + ": photo.encoding: "), std::string::npos) << r.out;
    // 1e-300 was "must be positive" (it is, and a float makes it 0): the range is said.
    const std::string tiny = writeShotFile(dir_.string(), "tiny", 64, "{\"image\": \"shot.png\", \"exposure\": 1e-300}");
    const RunResult t = fit(tiny);
    EXPECT_NE(t.exitCode, 0);
    EXPECT_NE(t.out.find(tiny + ": photo.exposure: is 1e-300, must be from 1e-06 to 1e+06"), std::string::npos) << t.out;
}

// A budget that ends inside the weave search: the best fit so far, a warning, and the report.
TEST_F(FitCommand, TooShortTimeGivesTheBestFitSoFarWithAWarning) {
    const RunResult r = fit(shot(), "--target Swatch --time 0.05 --report '" + file("report") + "'");
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("warning: fit: --time 0.05 s ran out before the fit finished its stages"), std::string::npos) << r.out;
    std::ifstream in(file("out.json"));
    ASSERT_TRUE(in);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_TRUE(j.contains("pattern"));
    EXPECT_TRUE(j.contains("ends_per_cm"));  // the rig's swatch has UVs of known size
    // Whether a render finished before the budget's end depends on the machine: the report says
    // which, and draws the photo beside the render only where one did.
    const std::string report = readText(file("report/report.txt"));
    EXPECT_NE(report.find("shot.json"), std::string::npos) << report;
    EXPECT_EQ(std::filesystem::exists(file("report/shot_0.png")),
              report.find("no render of the fit finished within its time") == std::string::npos)
        << report;
    EXPECT_TRUE(std::filesystem::exists(file("report/loss.csv")));
}

// A shot that cannot be fitted: its light has intensity 0, or another surface (a card 5 cm above
// the swatch) hides the swatch from the camera. Any material renders it alike, so each is refused
// naming the shot file, and nothing is written.
TEST_F(FitCommand, UnlitOrHiddenTargetIsRefused) {
    shot();  // the rig's swatch.gltf and a photo, shot.png
    const std::string unlit = writeShotFile(dir_.string(), "unlit", 64, "{\"image\": \"shot.png\"}", RigPhoto{}.light, 0.0f);
    RunResult r = fit(unlit);
    EXPECT_NE(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find(unlit + ": no light of the shot reaches the target where the camera sees it"), std::string::npos)
        << r.out;
    EXPECT_FALSE(std::filesystem::exists(file("out.json")));

    SceneDescription scene;
    scene.meshes.push_back(flatCloth(glm::vec2(kSwatchMetres), "Swatch"));
    Mesh card = flatCloth(glm::vec2(0.1f), "Card");
    for (glm::vec3& p : card.positions) p.y = 0.05f;
    card.material = 1;
    scene.meshes.push_back(card);
    scene.materials.resize(2);
    scene.materials[0].name = "Swatch";
    scene.materials[1].name = "Card";
    std::vector<std::string> warnings;
    writeGltf(file("covered.gltf"), scene, Camera{}, warnings);
    std::string text = readText(unlit);
    text.replace(text.find("swatch.gltf"), 11, "covered.gltf");
    text.replace(text.find("\"intensity\": 0"), 14, "\"intensity\": 0.08");
    std::ofstream(file("hidden.json")) << text;
    r = fit(file("hidden.json"));
    EXPECT_NE(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find(file("hidden.json") + ": the camera sees the target in 0 % of the frame: something in the scene hides it"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(std::filesystem::exists(file("out.json")));
}

// A flash shot and one lit from behind: the fit says it took the light through the yarns from the
// backlit shot, writes it, and compares only the flash shot with a Lambertian plane.
TEST_F(FitCommand, BacklitShotFitsTheLightThroughTheYarns) {
    RigPhoto photo;
    photo.truth.pattern = {1, 1, 1};
    photo.truth.repeat = {800.0f, 800.0f};
    photo.truth.yarn_width = photo.truth.warp_width = 0.85f;
    photo.truth.transmission = 0.5f;
    photo.size = 64;
    photo.spp = 4;
    const std::string flash = writeCaptureShot(dir_.string(), "flash", photo);
    photo.light = {0.02f, -0.15f, 0.0f};
    photo.lightIntensity = 0.8f;
    const std::string backlit = writeCaptureShot(dir_.string(), "backlit", photo);
    const RunResult r = runWovenCommand("fit '" + flash + "' '" + backlit + "' --target Swatch --time 3 -o '" +
                                        file("out.json") + "' --report '" + file("report") + "'");
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("from the backlit shots"), std::string::npos) << r.out;
    std::ifstream in(file("out.json"));
    ASSERT_TRUE(in);
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_TRUE(j.contains("transmission")) << j.dump();
    EXPECT_GT(j["transmission"].get<double>(), 0.1) << j.dump();
    const std::string report = readText(file("report/report.txt"));
    const size_t second = report.find("backlit.json");
    ASSERT_NE(second, std::string::npos) << report;
    EXPECT_LT(report.find("best Lambertian plane"), second) << report;  // the flash shot's
    EXPECT_EQ(report.find("best Lambertian plane", second), std::string::npos) << report;
}

TEST_F(FitCommand, RenderTakesAShotAndSaysItDoesNotUseThePhoto) {
    const std::string path = shot();
    const RunResult r = runWovenCommand("render '" + path + "' --spp 1 -o '" + file("frame.png") + "'");
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("is for woven fit; the render does not use it"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(file("frame.png")));
}

// Ctrl-C once the fit has reported progress: the best fit so far, under the partial name (an
// unfinished fit never takes the final one), exit status 130. The process is started by fork and
// exec, as the signal needs its pid.
TEST_F(FitCommand, InterruptWritesTheBestFitSoFarUnderThePartialName) {
    const std::string path = shot();
    const pid_t pid = fork();
    if (pid == 0) {
        if (!freopen(file("stderr.txt").c_str(), "w", stderr) || !freopen(file("stdout.txt").c_str(), "w", stdout)) _exit(127);
        const std::string out = file("out.json");
        execl(WOVEN_EXECUTABLE, WOVEN_EXECUTABLE, "fit", path.c_str(), "--target", "Swatch", "-o", out.c_str(), "--time",
              "600", static_cast<char*>(nullptr));
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (readText(file("stderr.txt")).find("renders") == std::string::npos && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    kill(pid, SIGINT);
    int status = 0;
    waitpid(pid, &status, 0);
    const std::string err = readText(file("stderr.txt"));
    ASSERT_TRUE(WIFEXITED(status)) << err;
    EXPECT_EQ(WEXITSTATUS(status), 130) << err;
    EXPECT_NE(err.find("interrupted: wrote the best fit so far to " + file("out.partial.json")), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(file("out.json")));
    std::ifstream in(file("out.partial.json"));
    ASSERT_TRUE(in) << err;
    EXPECT_TRUE(nlohmann::json::parse(in).contains("pattern"));
}

// A photo with nothing to fit is refused, not fitted as some weave: a uniform grey (it was
// "satin 7/1, 0.85 x 4.3 ends/picks per cm", exit 0) and one whose pixel is not a number.
TEST_F(FitCommand, PhotosWithNoSignalAreRefused) {
    TextureImage grey;
    grey.width = grey.height = 64;
    grey.bytes.assign(64 * 64, glm::u8vec4(128, 128, 128, 255));
    writeTexturePng(file("grey.png"), grey);
    const std::string path = writeShotFile(dir_.string(), "grey", 64, "{\"image\": \"grey.png\"}");
    RunResult r = fit(path);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("grey.png: every pixel is within 1% of the mean"), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(file("out.json")));

    Image nan;
    nan.width = nan.height = 64;
    nan.pixels.assign(64 * 64, glm::vec3(0.2f));
    for (size_t i = 0; i < nan.pixels.size(); i += 3) nan.pixels[i] = glm::vec3(0.6f);
    nan.pixels[65] = glm::vec3(std::nanf(""));
    writeExr(file("nan.exr"), ExrImage{nan, {}});
    const std::string nanShot = writeShotFile(dir_.string(), "nan", 64, "{\"image\": \"nan.exr\"}");
    r = fit(nanShot);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.out.find("nan.exr: pixel (1, 1) is not a finite number"), std::string::npos) << r.out;
}

// Every output is checked before the fit (output_path.h): a FIFO, a read-only file, a report
// "folder" that is a file, a report whose shot_0.png would replace the photo. Each is refused at
// once, naming the file, and nothing is written.
TEST_F(FitCommand, OutputsThatCannotBeWrittenAreRefusedBeforeTheFit) {
    RigPhoto photo;
    photo.size = 64;
    photo.spp = 4;
    const std::string path = writeCaptureShot(dir_.string(), "shot_0", photo);  // its photo: shot_0.png
    const auto refused = [&](const std::string& options, const std::string& named, const std::string& problem) {
        const RunResult r = runWovenCommand("fit '" + path + "' --target Swatch --time 600 " + options);
        EXPECT_NE(r.exitCode, 0) << options;
        EXPECT_NE(r.out.find(named + ": " + problem), std::string::npos) << r.out;
        // Refused up front: a fit that started would run its 600 s past the test's timeout.
    };
    ASSERT_EQ(mkfifo(file("fifo.json").c_str(), 0644), 0);
    refused("-o '" + file("fifo.json") + "'", file("fifo.json"), "is not a regular file");
    std::ofstream(file("kept.json")) << "{}";
    std::filesystem::permissions(file("kept.json"), std::filesystem::perms::owner_read);
    refused("-o '" + file("kept.json") + "'", file("kept.json"), "is read-only");
    EXPECT_EQ(readText(file("kept.json")), "{}");
    std::ofstream(file("report.txt")) << "notes";
    refused("-o '" + file("out.json") + "' --report '" + file("report.txt") + "'", file("report.txt"), "--report: is a file");
    const std::string photoBefore = readText(file("shot_0.png"));
    refused("-o '" + file("out.json") + "' --report '" + dir_.string() + "'", file("shot_0.png"), "is an input of this command");
    EXPECT_EQ(readText(file("shot_0.png")), photoBefore);
    EXPECT_FALSE(std::filesystem::exists(file("out.json")));
}

// The example shot of docs/FIT.md ("Try it"), as documented there, with a short budget: one
// flash photo of the library's denim (25 ends and 16 picks per cm), made by woven
// (assets/fit/make_photo.sh). Its thread counts come from stage 1, inside any budget; the
// exposure is free, so it is folded into the material, and with no backlit shot the
// transmission is said to be unfitted, on stderr and in the material's comment, which scene files
// accept.
TEST_F(FitCommand, ExampleShotFitsAsDocumented) {
    const RunResult r = runWovenCommand("fit '" WOVEN_ASSETS_DIR "/fit/denim_flash.json' --target Swatch -o '" +
                                        file("denim_fit.json") + "' --time 10");
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("transmission not fitted"), std::string::npos) << r.out;
    std::ifstream in(file("denim_fit.json"));
    ASSERT_TRUE(in);
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_TRUE(j.contains("comment")) << j.dump();
    const std::string comment = j["comment"];
    EXPECT_NE(comment.find("are not fitted: no shot is lit from behind"), std::string::npos) << comment;
    EXPECT_NE(comment.find("exposure"), std::string::npos) << comment;
    EXPECT_NEAR(j["ends_per_cm"].get<double>(), 25.0, 25.0 * 0.03) << j.dump();
    EXPECT_NEAR(j["picks_per_cm"].get<double>(), 16.0, 16.0 * 0.03) << j.dump();
    // The fitted material as a scene file's: it renders in the example's rig.
    nlohmann::json scene = nlohmann::json::parse(readText(WOVEN_ASSETS_DIR "/fit/denim_scene.json"));
    scene["gltf"] = WOVEN_ASSETS_DIR "/fit/swatch.gltf";
    scene["materials"]["Swatch"] = j;
    std::ofstream(file("scene.json")) << scene.dump();
    const RunResult render = runWovenCommand("render '" + file("scene.json") + "' --spp 1 -o '" + file("fit.png") + "'");
    EXPECT_EQ(render.exitCode, 0) << render.out;
}

}  // namespace
}  // namespace woven::test
