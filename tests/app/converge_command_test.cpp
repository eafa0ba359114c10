// `woven converge` ends, and compares against the reference of the scene it was given: numeric
// options that would make a render run without a time limit are refused by name, a cached
// reference is reused only for the same scene content, not for another file of the same name, and
// its table takes its name only once complete.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "../common/run_woven.h"
#include "shell_quote.h"

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
        // A value twice made two rows of one name, their runs pooled as one variant's.
        {"--budgets 0.05,0.05", "--budgets: a value is given twice"},
        {"--integrators path,bdpt,path", "--integrators: a value is given twice"},
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

// The table takes its name only once complete (the output rule, docs/LIMITS.md): its rows go to
// NAME.partial.csv as they are measured, so a comparison stopped part-way leaves no
// _convergence.csv; a FIFO where a row would go is refused before any work, and stays a FIFO.
TEST_F(ConvergeCommand, TheTableTakesItsNameOnlyOnceComplete) {
    const std::string s = scene("a", 0.5f), table = file("out/scene_convergence.csv"),
                      partial = file("out/scene_convergence.partial.csv");
    Result r = converge(s, "--denoise off");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_TRUE(fs::exists(table));
    EXPECT_FALSE(fs::exists(partial));

    // Stopped in its second budget (a minute), once the first row is written.
    fs::remove(table);
    const std::string command =
        std::string("'") + WOVEN_EXECUTABLE + "' converge " + s + " --out-dir " + file("out") +
        " --width 8 --height 8 --reference-time 0.2 --budgets 0.05,60 --integrators path --filter off "
        "--noise-thresholds 0 --denoise off >/dev/null 2>&1 & pid=$!; for i in $(seq 600); do "
        "[ \"$(wc -l < " + partial + " 2>/dev/null)\" = 2 ] && break; sleep 0.1; done; kill $pid; wait $pid";
    std::system(command.c_str());
    EXPECT_FALSE(fs::exists(table));
    std::ifstream rows(partial);
    std::string header, row;
    std::getline(rows, header);
    std::getline(rows, row);
    EXPECT_THAT(header, HasSubstr("variant,seconds,"));
    EXPECT_THAT(row, HasSubstr("path,0.0"));

    fs::remove(partial);
    ASSERT_EQ(mkfifo(partial.c_str(), 0644), 0);
    r = converge(s, "--denoise off");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("scene_convergence.partial.csv"));
    EXPECT_THAT(r.out, Not(HasSubstr("rendering reference")));
    EXPECT_TRUE(fs::is_fifo(partial));
    EXPECT_FALSE(fs::exists(table));
}

// The plot's title and paths reached gnuplot through a shell, inside double quotes: a scene named
// with $( ) ran a command, and one with a quote drew no plot. gnuplot now runs without a shell.
TEST_F(ConvergeCommand, AFileNameIsANameNotACommand) {
    fs::create_directories(file("odd"));
    const std::string s = file("odd/it's $(echo>injected).json");
    fs::copy_file(scene("a", 0.5f), s);
    fs::copy_file(file("a/cloth_drape.glb"), file("odd/cloth_drape.glb"));
    const Result r = run("converge " + woven::shellQuote(s) + " --out-dir " + file("out") +
                         " --width 8 --height 8 --reference-time 0.2 --budgets 0.05 --integrators path --filter off "
                         "--noise-thresholds 0 --denoise off");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_FALSE(fs::exists("injected"));
    EXPECT_TRUE(fs::exists(file("out/it's $(echo>injected)_convergence.csv")));
    if (r.out.find("gnuplot is not installed") == std::string::npos)
        EXPECT_TRUE(fs::exists(file("out/it's $(echo>injected)_convergence.png"))) << r.out;
}

}  // namespace
