// Textile keys and the fabric library (docs/FABRICS.md): yarn counts in every unit, the yarn
// diameter against Peirce's cotton rule, widths, weight, cover and repeat of a known cloth,
// presets and their overrides, mistakes that name the key or the fabric file, every library
// fabric shading through {"preset": NAME}, and `woven fabrics --json`.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "fabric_library.h"
#include "fabric_measures.h"
#include "material_json.h"
#include "temp_dir.h"
#include "textile_units.h"
#include "woven_material.h"

#include "../common/run_woven.h"

namespace woven {
namespace {

using ::testing::HasSubstr;
using json = nlohmann::json;

MaterialJson read(const json& j, std::vector<std::string>* warnings = nullptr) {
    std::vector<std::string> ignored;
    return materialFromJson(j, WovenParams{}, "", warnings ? *warnings : ignored);
}

std::string error(const json& j) {
    try {
        read(j);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(TextileUnits, YarnCountsInEveryUnit) {
    // 20 tex: 200 dtex, 180 denier (g per 9 km), 50 Nm (km per kg), 29.525 Ne (590.5 / tex).
    for (const char* count : {"20 tex", "200 dtex", "180 den", "50 Nm", "29.525 Ne", "20tex"})
        EXPECT_NEAR(parseYarnCount(count, "warp_count"), 20.0, 1e-9) << count;
}

TEST(TextileUnits, CottonDiameterAgreesWithPeircesRule) {
    // Peirce (1937): a cotton yarn of count N (Ne) is 1 / (28 sqrt(N)) inches across, from the
    // same fibre density and a packing near 0.6; woven's formula must agree to 1 %.
    for (double ne : {6.0, 20.0, 40.0, 80.0}) {
        const double peirce = kCmPerInch / (28.0 * std::sqrt(ne));
        EXPECT_NEAR(yarnDiameterCm(590.5 / ne, 1.52) / peirce, 1.0, 0.01) << ne << " Ne";
    }
    EXPECT_NEAR(yarnTex(yarnDiameterCm(37.0, 1.31), 1.31), 37.0, 1e-9);
}

TEST(TextileUnits, CountsSetWidthsAndMeasures) {
    const MaterialJson m = read({{"ends_per_cm", 8}, {"picks_per_cm", 12}, {"warp_count", "20 tex"},
                                 {"weft_count", "30 tex"}, {"fibre", "wool"}});
    ASSERT_TRUE(m.threadsPerCm);
    EXPECT_EQ(*m.threadsPerCm, glm::vec2(8, 12));
    EXPECT_NEAR(m.params.warp_width, yarnDiameterCm(20, 1.31) * 8, 1e-6);
    EXPECT_NEAR(m.params.yarn_width, yarnDiameterCm(30, 1.31) * 12, 1e-6);
    const FabricMeasures f = measureMaterial(m).value();
    EXPECT_NEAR(f.gramsPerSquareMetre, (8 * 20 + 12 * 30) / 10.0, 1e-9);  // 52 g/m2
    EXPECT_FALSE(f.weightFromWidths);
    EXPECT_NEAR(f.cover.x, m.params.warp_width, 1e-6);
    EXPECT_NEAR(f.clothCover, f.cover.x + f.cover.y - f.cover.x * f.cover.y, 1e-12);
    EXPECT_EQ(f.repeatThreads, glm::ivec2(2, 2));  // plain weave
    EXPECT_NEAR(f.repeatCm.x, 0.25, 1e-9);
    EXPECT_NEAR(f.repeatCm.y, 2.0 / 12.0, 1e-9);
    // Without counts the weight comes from the widths, and gives the counts back.
    json widths = {{"ends_per_inch", 8 * kCmPerInch}, {"picks_per_cm", 12}, {"fibre", "wool"},
                   {"warp_width", m.params.warp_width}, {"yarn_width", m.params.yarn_width}};
    const FabricMeasures g = measureMaterial(read(widths)).value();
    EXPECT_TRUE(g.weightFromWidths);
    EXPECT_NEAR(g.gramsPerSquareMetre, f.gramsPerSquareMetre, 1e-4);
}

TEST(TextileUnits, JammedYarnsFillTheirCellsWithAWarning) {
    // 200 tex of cotton is 0.053 cm across, 2.64 times the 0.02 cm spacing of 50 ends per cm.
    std::vector<std::string> warnings;
    const MaterialJson m = read({{"ends_per_cm", 50}, {"picks_per_cm", 10}, {"warp_count", "200 tex"}}, &warnings);
    EXPECT_EQ(m.params.warp_width, 1.0f);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_THAT(warnings[0], HasSubstr("'warp_count' at 50 ends per cm: yarns 2.64 times their spacing, jammed"));
}

TEST(TextileUnits, MistakesNameTheKey) {
    EXPECT_THAT(error({{"ends_per_cm", 0}, {"picks_per_cm", 1}}), HasSubstr("'ends_per_cm' = 0: need a number of threads from 0.01 to 1000 per cm"));
    // 1e-300 gave a repeat of "inf cm" and a weight of "-nan g/m2".
    EXPECT_THAT(error({{"ends_per_cm", 1e-300}, {"picks_per_cm", 1}}), HasSubstr("'ends_per_cm' = 1e-300: need a number of threads from 0.01"));
    EXPECT_THAT(error({{"ends_per_cm", 8}, {"picks_per_cm", -1}}), HasSubstr("'picks_per_cm' = -1"));
    EXPECT_THAT(error({{"ends_per_cm", "8"}, {"picks_per_cm", 1}}), HasSubstr("'ends_per_cm' = \"8\""));
    EXPECT_THAT(error({{"ends_per_cm", 8}, {"ends_per_inch", 20}, {"picks_per_cm", 1}}),
                HasSubstr("'ends_per_cm' and 'ends_per_inch' both give the ends"));
    EXPECT_THAT(error({{"ends_per_cm", 8}, {"picks_per_cm", 8}, {"weft_count", "12 furlongs"}}),
                HasSubstr("'weft_count' = \"12 furlongs\": 'furlongs' is no yarn count unit"));
    EXPECT_THAT(error({{"ends_per_cm", 8}, {"picks_per_cm", 8}, {"weft_count", "0 tex"}}), HasSubstr("'weft_count' = \"0 tex\""));
    EXPECT_THAT(error({{"ends_per_cm", 8}, {"picks_per_cm", 8}, {"weft_count", "-20 Nm"}}), HasSubstr("'weft_count' = \"-20 Nm\""));
    EXPECT_THAT(error({{"ends_per_cm", 8}, {"picks_per_cm", 8}, {"warp_count", 20}}), HasSubstr("'warp_count' = 20: need a number and a unit"));
    EXPECT_THAT(error({{"ends_per_cm", 8}, {"picks_per_cm", 8}, {"warp_count", "20 tex"}, {"warp_width", 0.5}}),
                HasSubstr("'warp_count' and 'warp_width' both set the yarn's width"));
    EXPECT_THAT(error({{"ends_per_cm", 8}, {"picks_per_cm", 8}, {"repeat", 4}}), HasSubstr("'ends_per_cm' and 'repeat' both set the repeat"));
    EXPECT_THAT(error({{"ends_per_cm", 8}, {"picks_per_cm", 8}, {"fibre", "mohair"}}),
                HasSubstr("'fibre' = \"mohair\" is none of woven's fibres: cotton, linen"));
}

TEST(FabricLibrary, PresetsAndTheirOverrides) {
    const MaterialJson denim = read({{"preset", "denim"}});
    EXPECT_EQ(*denim.threadsPerCm, glm::vec2(25, 16));
    EXPECT_EQ(denim.params.tile.size(), 4u);  // the draft's 3/1 twill
    EXPECT_NE(denim.wif.find("drafts/denim.wif"), std::string::npos);
    // A key replaces what set the same thing: 'repeat' the thread counts, 'yarn_width' the weft count.
    const MaterialJson repeat = read({{"preset", "denim"}, {"repeat", {10, 20}}, {"yarn_width", 0.3}});
    EXPECT_FALSE(repeat.threadsPerCm);
    EXPECT_EQ(repeat.params.repeat, glm::vec2(10, 20));
    EXPECT_FLOAT_EQ(repeat.params.yarn_width, 0.3f);
    EXPECT_FLOAT_EQ(repeat.params.warp_width, denim.params.warp_width);  // as the fabric's count gave it
    const MaterialJson inches = read({{"preset", "denim"}, {"ends_per_inch", 50.8}});
    EXPECT_FLOAT_EQ(inches.threadsPerCm->x, 20.0f);
    EXPECT_FLOAT_EQ(inches.threadsPerCm->y, 16.0f);
    EXPECT_THAT(error({{"preset", "denimm"}}), HasSubstr("'preset': \"denimm\" is no fabric in"));
    EXPECT_THAT(error({{"preset", "denimm"}}), HasSubstr("the library has canvas, chambray, denim"));
    EXPECT_THAT(error({{"preset", "../drafts/denim"}}), HasSubstr("'preset' = \"../drafts/denim\": need a fabric's name"));
    // Two keys given that contradict each other are refused with a preset as without one: a
    // given key replaces only the preset's keys, never another given key.
    EXPECT_THAT(error({{"preset", "denim"}, {"yarn_width", 0.3}, {"weft_count", "20 tex"}}),
                HasSubstr("'weft_count' and 'yarn_width' both set the yarn's width"));
    EXPECT_THAT(error({{"preset", "denim"}, {"ends_per_cm", 20}, {"ends_per_inch", 50}}),
                HasSubstr("'ends_per_cm' and 'ends_per_inch' both give the ends"));
    EXPECT_THAT(error({{"preset", "denim"}, {"repeat", {10, 20}}, {"ends_per_cm", 20}, {"picks_per_cm", 16}}),
                HasSubstr("'ends_per_cm' and 'repeat' both set the repeat"));
}

// A weave given beside a draft replaces the draft's weave, its threads keeping their colours by
// position; a side's colour given beside per-thread colours replaces them (docs/SCENE_FORMAT.md).
TEST(FabricLibrary, AGivenWeaveOrColourReplacesTheDraftsOrPresets) {
    const MaterialJson denim = read({{"preset", "denim"}});
    const MaterialJson satin = read({{"preset", "denim"}, {"pattern", {1, 4, 2}}});
    EXPECT_TRUE(satin.params.tile.empty());
    EXPECT_EQ(satin.params.pattern, glm::ivec3(1, 4, 2));
    EXPECT_EQ(satin.params.warp_color, denim.params.warp_color);  // indigo ends, ecru picks still
    EXPECT_EQ(satin.params.weft_color, denim.params.weft_color);
    EXPECT_EQ(*satin.threadsPerCm, glm::vec2(25, 16));
    EXPECT_EQ(satin.wif, denim.wif);
    // The same beside a draft named in the material itself.
    const MaterialJson drafted =
        read({{"wif", std::string(WOVEN_ASSETS_DIR) + "/drafts/gingham.wif"}, {"pattern", {1, 2, 1}}});
    EXPECT_TRUE(drafted.params.tile.empty());
    EXPECT_FALSE(drafted.params.warp_colors.empty());  // the gingham's checks stay
    // A tile given replaces the draft's tile too.
    const MaterialJson tiled = read({{"preset", "denim"}, {"tile", {"-|", "|-"}}});
    EXPECT_EQ(tiled.params.tile, (std::vector<std::string>{"-|", "|-"}));

    const MaterialJson tartan = read({{"preset", "tartan"}});
    ASSERT_FALSE(tartan.params.weft_colors.empty());
    const MaterialJson red = read({{"preset", "tartan"}, {"weft_color", {1, 0, 0}}});
    EXPECT_TRUE(red.params.weft_colors.empty());
    EXPECT_EQ(red.params.weft_color, glm::vec3(1, 0, 0));
    EXPECT_EQ(red.params.warp_colors, tartan.params.warp_colors);  // the other side keeps its sett
    // Per-thread colours given beside the side's colour win, as before.
    const MaterialJson lists = read({{"preset", "tartan"}, {"weft_color", {1, 0, 0}}, {"weft_colors", {{0, 1, 0}}}});
    EXPECT_EQ(lists.params.weft_colors, (std::vector<glm::vec3>{{0, 1, 0}}));
}

TEST(FabricLibrary, AFabricFilesMistakeNamesTheFile) {
    test::TempDir dir;
    std::ofstream(dir.file("bad.json")) << R"({"name": "bad", "title": "t", "source": "s",
                                               "material": {"ends_per_cm": 0, "picks_per_cm": 8}})";
    std::ofstream(dir.file("misnamed.json")) << R"({"name": "other", "title": "t", "source": "s", "material": {}})";
    ASSERT_EQ(setenv("WOVEN_FABRIC_DIR", dir.path().c_str(), 1), 0);
    const std::string bad = error({{"preset", "bad"}}), misnamed = error({{"preset", "misnamed"}});
    unsetenv("WOVEN_FABRIC_DIR");
    EXPECT_EQ(bad, dir.file("bad.json") + ": 'ends_per_cm' = 0: need a number of threads from 0.01 to 1000 per cm (0.0254 to 2540 per inch)");
    EXPECT_EQ(misnamed, dir.file("misnamed.json") + ": 'name' is \"other\", not its file's name");
}

TEST(FabricLibrary, EveryFabricShadesThroughItsPreset) {
    const std::vector<std::string> names = fabricNames();
    EXPECT_GE(names.size(), 12u);
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        const Fabric fabric = readFabric(name);
        EXPECT_FALSE(fabric.source.empty());
        std::vector<std::string> warnings;
        const MaterialJson m = read({{"preset", name}}, &warnings);
        EXPECT_TRUE(warnings.empty()) << warnings.front();  // no jammed yarns in the library
        ASSERT_TRUE(m.threadsPerCm);
        const FabricMeasures f = measureMaterial(m).value();
        EXPECT_FALSE(f.weightFromWidths);  // every fabric gives its yarn counts
        // Woven cloth from voile to canvas: 20 to 600 g/m2.
        EXPECT_GT(f.gramsPerSquareMetre, 20.0);
        EXPECT_LT(f.gramsPerSquareMetre, 600.0);
        // A patch of a few threads shades: some yarn is seen.
        const WovenMaterial material(m.params);
        int yarn = 0;
        for (int i = 0; i < 64; ++i) {
            ShadingInput in;
            in.uv = glm::dvec2((i % 8 + 0.5) / 8.0, (i / 8 + 0.5) / 8.0);
            yarn += material.shade(in).has_value();
        }
        EXPECT_GT(yarn, 0);
    }
    // The voile is sheer by its gaps: well under the 0.85 to 0.97 of the dense cloths.
    EXPECT_LT(measureMaterial(read({{"preset", "voile"}}))->clothCover, 0.6);
}

TEST(FabricsCommand, JsonListsEveryFabricWithItsCountsAndSource) {
    const test::RunResult r = test::runWoven("fabrics --json");
    ASSERT_EQ(r.exitCode, 0);
    const json all = json::parse(r.out);
    ASSERT_TRUE(all.is_array());
    EXPECT_GE(all.size(), 12u);
    for (const json& f : all) {
        SCOPED_TRACE(f.dump());
        for (const char* key : {"name", "source", "title", "warp_count", "weft_count"}) EXPECT_TRUE(f.at(key).is_string());
        for (const char* key : {"ends_per_cm", "picks_per_cm", "ends_per_inch", "picks_per_inch", "weight_g_per_m2"})
            EXPECT_GT(f.at(key).get<double>(), 0.0);
        EXPECT_NEAR(f["ends_per_inch"].get<double>(), f["ends_per_cm"].get<double>() * kCmPerInch, 1e-9);
    }
    const test::RunResult text = test::runWoven("fabrics");
    EXPECT_EQ(text.exitCode, 0);
    EXPECT_THAT(text.out, HasSubstr("denim                25 x 16"));
}

TEST(FabricsCommand, PatternOfAMaterialPrintsItsMeasures) {
    const test::RunResult r = test::runWoven("pattern --material '{\"preset\": \"denim\"}'");
    ASSERT_EQ(r.exitCode, 0);
    // The draft's 3/1 twill, then 4 threads at 25 ends and 16 picks per cm.
    EXPECT_THAT(r.out, HasSubstr("|||-\n-|||\n|-||\n||-|\n25 x 16 threads/cm (63.5 x 40.64 per inch), repeat 4 x 4 threads = "
                                 "0.16 x 0.25 cm"));
    const test::RunResult bad = test::runWovenCommand("pattern --material '{\"ends_per_cm\": -2, \"picks_per_cm\": 2}'");
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_THAT(bad.out, HasSubstr("--material: 'ends_per_cm' = -2"));
}

TEST(FabricsCommand, BsdfEvalTakesAUvUnitAsAMetre) {
    // Voile's 28 ends and 26 picks per cm: 0.1 mm from the origin is in the gap of its first
    // cell (0.28 and 0.26 of a thread), 0.18 mm across its middle (0.50 and 0.47), on a yarn.
    test::TempDir dir;
    std::ofstream(dir.file("q.jsonl")) << R"({"material": {"preset": "voile"}, "uv": [0.0001, 0.0001], "wi": [0, 0, 1], "wo": [0, 0.3, 1]}
{"material": {"preset": "voile"}, "uv": [0.00018, 0.00018], "wi": [0, 0, 1], "wo": [0, 0.3, 1]}
)";
    const test::RunResult r = test::runWoven("bsdf-eval < '" + dir.file("q.jsonl") + "'");
    ASSERT_EQ(r.exitCode, 0);
    EXPECT_THAT(r.out, HasSubstr("\"yarn\":\"gap\"}\n{"));
    EXPECT_THAT(r.out, ::testing::EndsWith("\"yarn\":\"weft\"}\n"));
}

}  // namespace
}  // namespace woven
