// The reader on thousands of broken files (fixed seed): valid drafts mutated byte- and
// line-wise, numbers swapped for huge ones, sections and keys inserted. It must never crash or
// throw anything but DraftError, what it returns must be a valid draft, and its memory must stay
// bounded whatever the file declares.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <random>

#include "allocation_counter.h"
#include "draft_tile.h"
#include "drawdown.h"
#include "wif_reader.h"
#include "wif_test_files.h"

namespace woven {
namespace {

// The most the reader may hold on any file: the per-thread arrays at the count limits (about
// 200 bytes per end and pick) and a few bytes per byte of the file.
size_t memoryBound(size_t fileBytes) { return (size_t(32) << 20) + 4 * fileBytes; }

std::string fileText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A rich valid draft: tie-up, treadling and a lift plan, per-thread colours, spacing, thickness.
std::string richWif() {
    std::string text = test::twillWif();
    text = test::replaced(text, "[WARP]\nThreads=8\nColor=1\n", "[WARP]\nThreads=8\nColor=1\nUnits=Decipoints\nSpacing=100\nThickness=80\n");
    text += "[WARP COLORS]\n3=2\n4=2\n[WEFT SPACING]\n2=0.2\n[WEFT THICKNESS]\n1=0.1\n[TEXT]\nTitle=Caf\xE9\n";
    text += "[LIFTPLAN]\n1=1,2\n2=2,3\n3=3,4\n4=4,1\n5=1,2\n6=2,3\n7=3,4\n8=1,4\n";
    return text;
}

class Mutator {
public:
    explicit Mutator(uint32_t seed) : random_(seed) {}

    std::string mutate(std::string text) {
        const int steps = 1 + int(pick(4));
        for (int s = 0; s < steps; ++s) text = step(std::move(text));
        return text;
    }

private:
    size_t pick(size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<size_t>(0, n - 1)(random_); }

    std::string step(std::string text) {
        static const char* kNumbers[] = {"0", "-1", "1000000000", "99999999999999999999", "65536", "65537",
                                         "256", "257", "4294967297", "1e300", "nan", "", ",", "1,2,3,4,5,300"};
        static const char* kHeaders[] = {"[WIF]", "[WEAVING]", "[WARP]", "[WEFT]", "[THREADING]", "[TIEUP]",
                                         "[TREADLING]", "[LIFTPLAN]", "[COLOR TABLE]", "[COLOR PALETTE]",
                                         "[WARP COLORS]", "[WEFT SPACING]", "[", "[]", "[PRIVATE]"};
        static const char* kLines[] = {"Threads=1000000000", "Shafts=0", "Treadles=-3", "Entries=65536",
                                       "Range=0,0", "Range=5", "Rising Shed=false", "1=1,1,1,1", "65536=256",
                                       "0=0", "=", "Units=furlongs", "Color=99", "Spacing=-0", "999999=1"};
        const size_t size = text.size();
        switch (pick(10)) {
            case 0:  // overwrite a byte
                if (size) text[pick(size)] = char(pick(256));
                break;
            case 1: {  // delete a range
                const size_t at = pick(size + 1);
                text.erase(at, pick(64));
                break;
            }
            case 2: {  // insert printable or arbitrary bytes
                std::string bytes;
                for (size_t n = pick(16); n > 0; --n) bytes += char(pick(3) ? 32 + pick(95) : pick(256));
                text.insert(pick(size + 1), bytes);
                break;
            }
            case 3:  // truncate
                text.resize(pick(size + 1));
                break;
            case 4: {  // replace a number
                const size_t at = text.find_first_of("0123456789", pick(size + 1));
                if (at == std::string::npos) break;
                const size_t end = text.find_first_not_of("0123456789", at);
                text.replace(at, (end == std::string::npos ? size : end) - at, kNumbers[pick(std::size(kNumbers))]);
                break;
            }
            case 5:  // a section header somewhere
                text.insert(lineStart(text, pick(size + 1)), std::string(kHeaders[pick(std::size(kHeaders))]) + "\n");
                break;
            case 6:  // a key=value line somewhere
                text.insert(lineStart(text, pick(size + 1)), std::string(kLines[pick(std::size(kLines))]) + "\n");
                break;
            case 7: {  // duplicate a line
                const size_t start = lineStart(text, pick(size + 1));
                const size_t end = text.find('\n', start);
                const std::string line = text.substr(start, end == std::string::npos ? std::string::npos : end - start + 1);
                text.insert(lineStart(text, pick(size + 1)), line + (line.empty() || line.back() != '\n' ? "\n" : ""));
                break;
            }
            case 8:  // change line ends
                for (size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 2)) {
                    if (pick(2)) {
                        text.insert(at, "\r");
                    }
                }
                break;
            default:  // repeat a chunk many times, so counts and lengths grow
                if (size) {
                    const size_t at = lineStart(text, pick(size));
                    const std::string chunk = text.substr(at, 1 + pick(200));
                    std::string repeated;
                    for (size_t n = 1 + pick(200); n > 0; --n) repeated += chunk;
                    text.insert(at, repeated);
                }
        }
        return text;
    }

    static size_t lineStart(const std::string& text, size_t at) {
        if (at == 0 || text.empty()) return 0;
        const size_t newline = text.rfind('\n', std::min(at, text.size()) - 1);
        return newline == std::string::npos ? 0 : newline + 1;
    }

    std::mt19937 random_;
};

// Reads `text`; returns whether it gave a draft. Fails the test on anything but DraftError, an
// invalid draft, or memory beyond the bound.
bool readsOrRefuses(const std::string& text) {
    std::vector<std::string> warnings;
    test::resetAllocationPeak();
    try {
        const Draft draft = parseWif(text, "fuzz.wif", warnings);
        EXPECT_LE(test::allocationPeakSinceReset(), memoryBound(text.size()));
        validate(draft, "fuzz.wif");
        const Drawdown drawdown(draft, "fuzz.wif");
        if (size_t(draft.ends()) * size_t(draft.picks()) <= (size_t(1) << 16)) draftTile(draft, "fuzz.wif");
        return true;
    } catch (const DraftError& e) {
        EXPECT_LE(test::allocationPeakSinceReset(), memoryBound(text.size()));
        EXPECT_EQ(std::string(e.what()).rfind("fuzz.wif", 0), 0u) << e.what();
        return false;
    }
}

TEST(WifReaderFuzz, MutatedDraftsReadOrGiveDraftErrorWithBoundedMemory) {
    const std::vector<std::string> seeds = {
        test::twillWif(), test::plainLiftplanWif(), richWif(),
        fileText(WOVEN_ASSETS_DIR "/drafts/houndstooth.wif"), fileText(WOVEN_ASSETS_DIR "/drafts/gingham.wif"),
        fileText(WOVEN_ASSETS_DIR "/drafts/twill_stripes.wif")};
    Mutator mutator(20240611);
    int read = 0, refused = 0;
    for (int i = 0; i < 6000; ++i) {
        const std::string text = mutator.mutate(seeds[size_t(i) % seeds.size()]);
        bool gaveDraft = false;
        try {
            gaveDraft = readsOrRefuses(text);
        } catch (const std::exception& e) {
            ADD_FAILURE() << "input " << i << " threw " << typeid(e).name() << ": " << e.what();
        }
        (gaveDraft ? read : refused)++;
        if (HasFailure()) {
            ADD_FAILURE() << "input " << i << ":\n" << text;
            break;
        }
    }
    // The mutations must exercise both outcomes, or the test tests little.
    EXPECT_GT(read, 1000);
    EXPECT_GT(refused, 1000);
}

TEST(WifReaderFuzz, RandomBytesAreRefused) {
    std::mt19937 random(7);
    for (int i = 0; i < 500; ++i) {
        std::string bytes(std::uniform_int_distribution<size_t>(0, 4096)(random), '\0');
        for (char& c : bytes) c = char(random() % 256);
        if (i % 2) bytes = "[WIF]\nVersion=1.1\n" + bytes;
        EXPECT_FALSE(readsOrRefuses(bytes));
    }
}

TEST(WifReaderFuzz, DeclaringBillionsOfThreadsCostsNothing) {
    for (const char* from : {"[WARP]\nThreads=8", "[WEFT]\nThreads=8"}) {
        const std::string text = test::replaced(test::twillWif(), from, std::string(from, 14) + "=1000000000");
        test::resetAllocationPeak();
        std::vector<std::string> warnings;
        EXPECT_THROW(parseWif(text, "huge.wif", warnings), DraftError);
        EXPECT_LT(test::allocationPeakSinceReset(), size_t(1) << 20);
    }
}

TEST(WifReaderFuzz, TheLargestDraftWithinTheLimitsStaysBounded) {
    // Every count at its limit, with an entry at the far end of each list.
    std::string text = "[WIF]\nVersion=1.1\n[WEAVING]\nShafts=256\nTreadles=256\n[WARP]\nThreads=65536\nColor=65536\n"
                       "Spacing=1\n[WEFT]\nThreads=65536\nThickness=2\n[COLOR PALETTE]\nEntries=65536\n"
                       "[COLOR TABLE]\n65536=1,2,3\n[THREADING]\n65536=256\n[TIEUP]\n256=1,256\n"
                       "[TREADLING]\n65536=1,256\n[LIFTPLAN]\n65536=256\n[WARP COLORS]\n1=65536\n";
    test::resetAllocationPeak();
    std::vector<std::string> warnings;
    const Draft draft = parseWif(text, "largest.wif", warnings);
    EXPECT_LE(test::allocationPeakSinceReset(), memoryBound(text.size()));
    EXPECT_EQ(draft.ends(), 65536);
    EXPECT_EQ(draft.picks(), 65536);
    EXPECT_EQ(draft.palette.size(), 65536u);
    // Its drawdown answers any cell in memory independent of ends x picks (2^32 cells here).
    test::resetAllocationPeak();
    const Drawdown drawdown(draft, "largest.wif");
    EXPECT_LE(test::allocationPeakSinceReset(), size_t(8) << 20);
    EXPECT_TRUE(drawdown.warpOnTop(65535, 65535));  // end on shaft 256, pick treadles 1 and 256
    EXPECT_FALSE(drawdown.warpOnTop(0, 65535));     // end 1 is on no shaft
    // The tile for the model is refused rather than built at 4 billion cells.
    EXPECT_THROW(draftTile(draft, "largest.wif"), DraftError);
}

}  // namespace
}  // namespace woven
