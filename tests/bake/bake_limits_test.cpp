// What a bake asks of the machine: an estimate larger than its memory is refused before anything
// is allocated (--size 16384 died with std::bad_alloc), and a long bake reports its progress.
#include <gtest/gtest.h>

#include <vector>

#include "system_memory.h"
#include "woven_bake.h"

namespace woven {
namespace {

TEST(BakeLimits, ABakeLargerThanMemoryIsRefusedBeforeAllocating) {
    BakeOptions options;
    options.size = 16384;  // the command line's largest: 2^28 texels, about 80 GiB estimated
    const double needed = double(options.size) * options.size * double(kBakeBytesPerTexel);
    if (physicalMemoryBytes() == 0 || needed <= double(physicalMemoryBytes()))
        GTEST_SKIP() << "this machine holds a 16384^2 bake's estimate: nothing to refuse";
    WovenParams p;
    p.pattern = {1, 1, 1};  // a plain weave: a 2 x 2 repeat, so 16384 texels stay a valid size
    try {
        bakeWoven(p, options);
        FAIL() << "a bake beyond memory was not refused";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("16384 x 16384 bake needs about"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--size"), std::string::npos) << e.what();
    }
}

TEST(BakeLimits, ProgressRisesToTheWholeBake) {
    BakeOptions options;
    options.size = 64;
    std::vector<double> seen;
    options.progress = [&](double fraction) { seen.push_back(fraction); };
    WovenParams p;
    p.pattern = {1, 1, 1};
    bakeWoven(p, options);
    ASSERT_FALSE(seen.empty());
    for (size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]);
    EXPECT_GT(seen.front(), 0.0);
    EXPECT_LE(seen.back(), 1.0);
    // One call per row at most (calls are skipped while another is under way).
    EXPECT_LE(seen.size(), 64u);
}

}  // namespace
}  // namespace woven
