// `woven converge` ends, and compares against the reference of the scene it was given: numeric
// options that would make a render run without a time limit are refused by name, and a cached
// reference is reused only for the same scene content, not for another file of the same name.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../common/run_woven.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;

using Result = woven::test::RunResult;
Result run(const std::string& args) { return woven::test::runWovenCommand(args); }

class ConvergeCommand : public woven::test::CommandTest {
protected:
    // `folder`/scene.json: the bundled drape under a uniform sky of radiance `sky`.
    std::string scene(const std::string& folder, float sky) {
        fs::create_directories(file(folder));
        fs::copy_file(std::string(WOVEN_ASSETS_DIR) + "/cloth_drape.glb", file(folder + "/cloth_drape.glb"));
        const std::string path = file(folder + "/scene.json");
        std::ofstream(path) << R"({"gltf": "cloth_drape.glb", "environment": {"color": [)" << sky << ", " << sky << ", "
                            << sky << "]}}";
        return path;
    }
    // The smallest comparison: one integrator, one budget, an 8 x 8 frame.
    Result converge(const std::string& scene, const std::string& options = "") {
        return run("converge " + scene + " --out-dir " + file("out") +
                   " --width 8 --height 8 --reference-time 0.2 --budgets 0.05 --integrators path --filter off "
                   "--noise-thresholds 0 " + options);
    }
};

TEST_F(ConvergeCommand, TimesThatSetNoLimitAreRefusedByName) {
    const std::string s = scene("a", 0.5f);
    const std::pair<const char*, const char*> refused[] = {
        {"--budgets 0", "--budgets: '0' is outside the range: it must be from 0.001 to 86400"},
        {"--budgets 1,-1", "--budgets: '-1' is outside the range"},
        {"--budgets nan", "--budgets: 'nan' is not a finite number"},
        {"--budgets 1e9", "--budgets: '1e9' is outside the range"},
        {"--reference-time nan", "--reference-time: 'nan' is not a finite number"},
        {"--reference-time 0", "--reference-time: '0' is outside the range"},
        {"--reference-time inf", "--reference-time: 'inf' is not a finite number"},
        {"--noise-thresholds nan", "--noise-thresholds: 'nan' is not a finite number"},
    };
    for (const auto& [options, message] : refused) {
        const Result r = converge(s, options);
        EXPECT_NE(r.exitCode, 0) << options;
        EXPECT_THAT(r.out, HasSubstr(message)) << options;
    }
    EXPECT_FALSE(fs::exists(file("out")));
}

TEST_F(ConvergeCommand, AnotherSceneOfTheSameNameGetsItsOwnReference) {
    const std::string dim = scene("dim", 0.1f), bright = scene("bright", 2.0f);
    Result r = converge(dim);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, HasSubstr("converge: rendering reference"));

    r = converge(bright);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, HasSubstr("converge: rendering reference"));
    EXPECT_THAT(r.out, Not(HasSubstr("reusing")));

    // The same content again, and only that, reuses its own.
    r = converge(dim);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_THAT(r.out, HasSubstr("converge: reusing reference"));
    r = converge(dim, "--reference-time 0.25");
    EXPECT_THAT(r.out, Not(HasSubstr("reusing")));
}

}  // namespace
