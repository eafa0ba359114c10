// `woven export -o FABRIC.u3ma` as a user runs it on the library's denim and satin and on a WIF
// draft's fabric (the houndstooth): the .u3m checked against U3M 1.1's schema for every field
// woven writes (u3m1.1/spec/u3m_schema.json: required keys, types, ranges and enums, paths that
// are in the archive, no keys the schema does not list), the weight within 2 % of `woven
// fabrics`, the construction the weave is, each map a whole number of repeats in mm with its dpi
// matching its pixels; the archive as U3MA restricts ZIP; the folder form; bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "../common/run_woven.h"
#include "file_reading.h"
#include "image_io.h"
#include "u3m_export.h"
#include "u3ma_archive.h"
#include "weave_construction.h"

namespace woven {
namespace {

using nlohmann::json;
using test::runWoven;
using test::runWovenCommand;

// ---- The schema's checks, for what woven writes -------------------------------------------

struct SchemaCheck {
    std::map<std::string, std::vector<unsigned char>> files;  // the archive's
    std::vector<std::string> problems;

    void fail(const std::string& where, const std::string& what) { problems.push_back(where + ": " + what); }
    bool keys(const json& j, const std::string& where, const std::set<std::string>& required) {
        if (!j.is_object()) return fail(where, "not an object"), false;
        for (const std::string& k : required)
            if (!j.contains(k)) fail(where, "lacks '" + k + "'");
        for (const auto& [k, v] : j.items())
            if (!required.count(k)) fail(where, "has '" + k + "', which the schema does not allow");
        return true;
    }
    void number(const json& j, const std::string& where, double lo = -INFINITY, double hi = INFINITY) {
        if (!j.is_number()) return fail(where, "not a number");
        if (j.get<double>() < lo || j.get<double>() > hi) fail(where, j.dump() + " outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    void image(const json& j, const std::string& where, bool repeat) {
        std::set<std::string> k = {"width", "height", "dpi", "path"};
        if (repeat) k.insert("repeat");
        if (!keys(j, where, k)) return;
        number(j["width"], where + ".width", 0), number(j["height"], where + ".height", 0);
        if (keys(j["dpi"], where + ".dpi", {"x", "y"})) number(j["dpi"]["x"], where + ".dpi.x", 0), number(j["dpi"]["y"], where + ".dpi.y", 0);
        if (repeat && keys(j["repeat"], where + ".repeat", {"rotation", "mode"})) {
            number(j["repeat"]["rotation"], where + ".repeat.rotation");
            if (j["repeat"]["mode"] != "normal") fail(where, "repeat.mode is not normal");
        }
        // The spec's portable names: no "..", ".", "~" part, nothing outside [0-9A-Za-z._-/].
        const std::string path = j["path"].is_string() ? j["path"].get<std::string>() : "";
        if (!std::regex_match(path, std::regex("([0-9A-Za-z_-][0-9A-Za-z._-]*/)*[0-9A-Za-z_-][0-9A-Za-z._-]*[0-9A-Za-z_-]")))
            return fail(where, "path '" + path + "' is not a portable relative path");
        const auto file = files.find(path);
        if (file == files.end()) return fail(where, "path '" + path + "' is not in the archive");
        // Dpi in material and images should match (u3m_additional_spec_u3m.txt).
        const TextureImage t = decodeTexture(file->second.data(), file->second.size(), path);
        if (std::abs(j["dpi"]["x"].get<double>() * j["width"].get<double>() / 25.4 - t.width) > 0.01 ||
            std::abs(j["dpi"]["y"].get<double>() * j["height"].get<double>() / 25.4 - t.height) > 0.01)
            fail(where, "its dpi and size do not give the image's " + std::to_string(t.width) + " x " + std::to_string(t.height) + " pixels");
    }
    // texture_and_number_*: a constant and a scalar texture or null.
    void scalar(const json& j, const std::string& where, double lo, double hi) {
        if (!keys(j, where, {"constant", "texture"})) return;
        number(j["constant"], where + ".constant", lo, hi);
        if (j["texture"].is_null()) return;
        if (!keys(j["texture"], where + ".texture", {"factor", "offset", "image"})) return;
        number(j["texture"]["factor"], where + ".texture.factor"), number(j["texture"]["offset"], where + ".texture.offset");
        image(j["texture"]["image"], where + ".texture.image", true);
        // The constant stands for the map: its mean value after factor and offset (u3m_additional_spec_u3m.txt).
        const auto file = files.find(j["texture"]["image"].value("path", ""));
        if (file == files.end() || !j["constant"].is_number() || !j["texture"]["factor"].is_number()) return;
        const TextureImage t = decodeTexture(file->second.data(), file->second.size(), file->first);
        double sum = 0.0;
        for (const glm::u8vec4& b : t.bytes) sum += (b.r + b.g + b.b) / 765.0;
        const double mean = j["texture"]["offset"].get<double>() + j["texture"]["factor"].get<double>() * sum / double(t.bytes.size());
        if (std::abs(j["constant"].get<double>() - mean) > 0.01 * std::max(1.0, std::abs(mean)))
            fail(where, "constant " + j["constant"].dump() + " is not its map's mean " + std::to_string(mean));
    }
    void color(const json& j, const std::string& where) {
        if (!keys(j, where, {"r", "g", "b"})) return;
        for (const char* c : {"r", "g", "b"}) number(j[c], where + "." + c, 0, 1);
    }
    void normal(const json& j, const std::string& where) {
        if (!keys(j, where, {"constant", "texture"})) return;
        if (keys(j["constant"], where + ".constant", {"x", "y", "z"}))
            for (const char* c : {"x", "y", "z"}) number(j["constant"][c], where + ".constant." + c, -1, 1);
        if (j["texture"].is_null() || !keys(j["texture"], where + ".texture", {"scale", "image"})) return;
        number(j["texture"]["scale"], where + ".texture.scale");
        image(j["texture"]["image"], where + ".texture.image", true);
    }
    void colorTexture(const json& j, const std::string& where) {
        if (!keys(j, where, {"constant", "texture"})) return;
        color(j["constant"], where + ".constant");
        if (j["texture"].is_null() || !keys(j["texture"], where + ".texture", {"mode", "factor", "image"})) return;
        static const std::set<std::string> modes = {"add", "subtract", "multiply", "divide", "max", "min", "overlay"};
        if (!j["texture"]["mode"].is_string() || !modes.count(j["texture"]["mode"])) fail(where, "texture.mode is none of the schema's");
        color(j["texture"]["factor"], where + ".texture.factor");
        image(j["texture"]["image"], where + ".texture.image", true);
    }
    void visualisation(const json& v, const std::string& where) {
        if (v.is_null()) return;
        if (!keys(v, where, {"alpha", "anisotropy_value", "anisotropy_rotation", "clearcoat_value", "clearcoat_normal",
                             "clearcoat_roughness", "ior", "metalness", "normal", "displacement", "roughness", "sheen_value",
                             "sheen_tint", "specular_value", "specular_tint", "subsurface_radius", "subsurface_value",
                             "transmission", "basecolor", "subsurface_color", "shader", "preview"}))
            return;
        for (const char* k : {"alpha", "anisotropy_rotation", "metalness", "transmission"}) scalar(v[k], where + "." + k, 0, 1);
        for (const char* k : {"anisotropy_value", "clearcoat_value", "clearcoat_roughness", "ior", "displacement", "roughness",
                              "sheen_value", "sheen_tint", "specular_value", "specular_tint", "subsurface_radius", "subsurface_value"})
            scalar(v[k], where + "." + k, -INFINITY, INFINITY);
        normal(v["normal"], where + ".normal"), normal(v["clearcoat_normal"], where + ".clearcoat_normal");
        colorTexture(v["basecolor"], where + ".basecolor"), colorTexture(v["subsurface_color"], where + ".subsurface_color");
        if (v["shader"] != "principled") fail(where, "shader is not principled");
        if (!v["preview"].is_null()) image(v["preview"], where + ".preview", false);
    }
    void enumerated(const json& j, const std::string& where, const std::set<std::string>& types) {
        if (j.is_null() || !keys(j, where, {"type", "name"})) return;
        if (!j["type"].is_string() || !types.count(j["type"])) fail(where, "type " + j["type"].dump() + " is none of the schema's I check");
        if (j["type"] == "other" ? !j["name"].is_string() : !j["name"].is_null()) fail(where, "name must be a string for 'other' and null else");
    }
    void physics(const json& p) {
        if (p.is_null() || !keys(p, "physics", {"thickness", "weight", "composition", "devices", "material_type", "construction"})) return;
        number(p["thickness"], "physics.thickness", 0), number(p["weight"], "physics.weight", 0);
        if (keys(p["devices"], "physics.devices", {"fab"}) && !p["devices"]["fab"].is_string()) fail("physics.devices.fab", "not a string");
        if (!p["composition"].is_null() && keys(p["composition"], "physics.composition", {"parts"})) {
            double sum = 0.0;
            for (const json& part : p["composition"]["parts"]) {
                enumerated(json{{"type", part.value("type", json())}, {"name", part.value("name", json())}}, "physics.composition.parts",
                           {"Cotton", "Linen", "Wool", "Silk", "Rayon", "Polyester", "Nylon", "Acrylic", "other"});
                if (keys(part, "physics.composition.parts", {"ratio", "type", "name"})) number(part["ratio"], "ratio", 0, 1), sum += part["ratio"].get<double>();
            }
            if (p["composition"]["parts"].empty() || std::abs(sum - 1.0) > 1e-9) fail("physics.composition", "the ratios do not sum to 1");
        }
        enumerated(p["material_type"], "physics.material_type", {"Woven"});
        enumerated(p["construction"], "physics.construction",
                   {"Plain weave", "Twill - left hand (S)", "Twill - right hand (Z)", "Satin", "Dobby", "Jacquard"});
    }
    void document(const json& d) {
        if (!keys(d, "", {"schema", "material", "custom"})) return;
        if (d["schema"] != "1.1") fail("schema", "not 1.1");
        if (!d["custom"].is_object() && !d["custom"].is_null()) fail("custom", "neither an object nor null");
        const json& m = d["material"];
        if (!keys(m, "material", {"name", "id", "created", "modified", "front", "back", "side", "physics", "metadata", "description"})) return;
        const std::regex uuid4("[0-9a-fA-F]{8}-[0-9a-fA-F]{4}-4[0-9a-fA-F]{3}-[89abAB][0-9a-fA-F]{3}-[0-9a-fA-F]{12}");
        if (!m["id"].is_string() || !std::regex_match(m["id"].get<std::string>(), uuid4)) fail("material.id", "not a UUID4");
        if (!m["name"].is_string() || m["name"].get<std::string>().empty()) fail("material.name", "not a non-empty string");
        if (!m["description"].is_string()) fail("material.description", "not a string");
        const std::regex dateTime("\\d{4}-\\d{2}-\\d{2}T\\d{2}:\\d{2}:\\d{2}(\\.\\d+)?(Z|[+-]\\d{2}:\\d{2})");
        for (const char* t : {"created", "modified"})
            if (!m[t].is_string() || !std::regex_match(m[t].get<std::string>(), dateTime)) fail(std::string("material.") + t, "not an RFC 3339 date-time");
        visualisation(m["front"], "front"), visualisation(m["back"], "back"), visualisation(m["side"], "side");
        physics(m["physics"]);
        if (!m["metadata"].is_null() && !m["metadata"].is_object()) fail("material.metadata", "neither an object nor null");
    }
};

struct Archive {
    std::map<std::string, std::vector<unsigned char>> files;
    json u3m;
};

Archive readArchive(const std::string& path) {
    Archive a;
    std::string u3mName;
    for (ArchiveEntry& e : unpackU3ma(readRegularFile(path, size_t(1) << 30), path, size_t(1) << 30)) {
        if (e.name.find('/') == std::string::npos && e.name.size() > 4 && e.name.substr(e.name.size() - 4) == ".u3m") u3mName = e.name;
        a.files[e.name] = std::move(e.bytes);
    }
    EXPECT_FALSE(u3mName.empty()) << path << ": no .u3m at the archive's root";
    if (!u3mName.empty()) a.u3m = json::parse(a.files[u3mName].begin(), a.files[u3mName].end());
    return a;
}

// ---- The library's fabrics ------------------------------------------------------------------

json fabricsLibrary() {
    const test::RunResult r = runWoven("fabrics --json 2>/dev/null");
    EXPECT_EQ(r.exitCode, 0);
    json byName;
    for (const json& f : json::parse(r.out)) byName[f["name"].get<std::string>()] = f;
    return byName;
}

class U3mCommandTest : public test::CommandTest {
protected:
    // A scene file: the bundled drape in the library's fabric `preset`.
    std::string drapeIn(const std::string& preset) {
        const std::string path = file(preset + "_scene.json");
        std::ofstream(path) << json{{"gltf", std::string(WOVEN_ASSETS_DIR) + "/cloth_drape.glb"},
                                    {"materials", {{"Cloth", {{"preset", preset}}}}}}.dump();
        return path;
    }
};

TEST_F(U3mCommandTest, LibraryFabricsPassTheSchemaWithTheirWeightConstructionAndWholeRepeats) {
    const json library = fabricsLibrary();
    // denim: the library's 3/1 twill from assets/drafts/denim.wif, which draws it rising to
    // the left (docs/DRAFTS.md's orientation); houndstooth: a WIF draft's 2/2 twill with colour
    // stripes; satin: the 5-end warp satin, regular (1, 4, 2).
    const std::map<std::string, std::string> constructions = {
        {"denim", "Twill - left hand (S)"}, {"satin_charmeuse", "Satin"}, {"houndstooth", "Twill - left hand (S)"}};
    const std::map<std::string, std::string> fibres = {{"denim", "Cotton"}, {"satin_charmeuse", "Silk"}, {"houndstooth", "Wool"}};
    for (const auto& [name, expected] : constructions) {
        SCOPED_TRACE(name);
        const std::string out = file(name + ".u3ma");
        const test::RunResult r = runWovenCommand("export '" + drapeIn(name) + "' -o '" + out + "' --size 64 --preview-size 24 --preview-spp 1");
        ASSERT_EQ(r.exitCode, 0) << r.out;
        const Archive a = readArchive(out);
        SchemaCheck check{a.files, {}};
        check.document(a.u3m);
        for (const std::string& p : check.problems) ADD_FAILURE() << p;

        const json& fabric = library[name];
        const json& m = a.u3m["material"];
        const json& physics = m["physics"];
        EXPECT_NEAR(physics["weight"].get<double>(), fabric["weight_g_per_m2"].get<double>(), 0.02 * fabric["weight_g_per_m2"].get<double>());
        EXPECT_EQ(physics["construction"]["type"], expected);
        EXPECT_EQ(physics["material_type"]["type"], "Woven");
        EXPECT_EQ(physics["composition"]["parts"][0]["type"], fibres.at(name));
        EXPECT_GT(physics["thickness"].get<double>(), 0.05);
        EXPECT_LT(physics["thickness"].get<double>(), 3.0);
        // Every map of both faces: a whole number of the weave's repeats at the real thread count.
        const double repeatMm[2] = {10.0 * fabric["repeat_threads"][0].get<double>() / fabric["ends_per_cm"].get<double>(),
                                    10.0 * fabric["repeat_threads"][1].get<double>() / fabric["picks_per_cm"].get<double>()};
        int maps = 0;
        for (const char* face : {"front", "back"})
            for (const auto& [key, value] : m[face].items()) {
                if (!value.is_object() || !value.contains("texture") || !value["texture"].is_object()) continue;
                const json& image = value["texture"]["image"];
                const double repeats[2] = {image["width"].get<double>() / repeatMm[0], image["height"].get<double>() / repeatMm[1]};
                for (double n : repeats) EXPECT_NEAR(n, std::round(n), 1e-9) << face << "." << key;
                EXPECT_GE(std::round(repeats[0]), 1.0);
                ++maps;
            }
        EXPECT_GE(maps, 2 * 6);  // base colour, alpha, normal, roughness, anisotropy's value and rotation
        // Denim (25 x 16 per cm, 4 x 4 threads) has repeats of 1.6 x 2.5 mm, the figure.
        if (name == "denim") {
            EXPECT_NEAR(m["front"]["basecolor"]["texture"]["image"]["width"].get<double>(), 1.6, 1e-9);
        }
        // What woven reads back: its parameters at the real thread count.
        EXPECT_EQ(a.u3m["custom"]["woven"]["material"]["ends_per_cm"], fabric["ends_per_cm"]);
        EXPECT_FALSE(m["front"]["preview"].is_null());
    }
}

// A WIF draft given bare (woven's drape at the draft's threads per cm) exports as its library fabric
// does: the schema, the construction, the same maps in mm; its weight is the one from the yarn widths
// (the draft names no yarn counts), which `woven fabrics` cannot print for it.
TEST_F(U3mCommandTest, ABareWifDraftExportsAsItsLibraryFabric) {
    const std::string draft = file("draft.u3ma"), library = file("library.u3ma");
    for (const auto& [input, out] : {std::pair{std::string(WOVEN_ASSETS_DIR) + "/drafts/houndstooth.wif", draft}, std::pair{drapeIn("houndstooth"), library}}) {
        const test::RunResult r = runWovenCommand("export '" + input + "' -o '" + out + "' --size 64 --preview-size 24 --preview-spp 1");
        ASSERT_EQ(r.exitCode, 0) << r.out;
    }
    const Archive a = readArchive(draft), b = readArchive(library);
    SchemaCheck check{a.files, {}};
    check.document(a.u3m);
    for (const std::string& p : check.problems) ADD_FAILURE() << p;
    EXPECT_EQ(a.u3m["material"]["name"], "houndstooth");
    EXPECT_EQ(a.u3m["material"]["physics"]["construction"], b.u3m["material"]["physics"]["construction"]);
    for (const char* side : {"width", "height"})
        EXPECT_EQ(a.u3m["material"]["front"]["basecolor"]["texture"]["image"][side], b.u3m["material"]["front"]["basecolor"]["texture"]["image"][side]);
    EXPECT_GT(a.u3m["material"]["physics"]["weight"].get<double>(), 0.0);
}

// A warp-faced cloth shows its warp on the front and its weft on the back: denim's indigo and ecru.
TEST_F(U3mCommandTest, TheBackIsTheWeaveTurnedOver) {
    const std::string out = file("denim.u3ma");
    ASSERT_EQ(runWovenCommand("export '" + drapeIn("denim") + "' -o '" + out + "' --size 64 --preview-size 0").exitCode, 0);
    const Archive a = readArchive(out);
    const auto blueness = [&](const char* face) {
        const json& c = a.u3m["material"][face]["basecolor"]["constant"];
        return c["b"].get<double>() - c["r"].get<double>();
    };
    // The mean colours' blue minus red (sRGB): +0.053 on the front, -0.020 on the back at this bake.
    EXPECT_GT(blueness("front"), 0.0);
    EXPECT_LT(blueness("back"), 0.0);
    EXPECT_GT(blueness("front") - blueness("back"), 0.05);
    EXPECT_TRUE(a.u3m["material"]["front"]["preview"].is_null());  // --preview-size 0
}

TEST_F(U3mCommandTest, TheFolderFormWritesTheU3mBesideItsTextures) {
    const std::string out = file("satin.u3m");
    ASSERT_EQ(runWovenCommand("export '" + drapeIn("satin_charmeuse") + "' -o '" + out + "' --size 64 --preview-size 0").exitCode, 0);
    std::ifstream in(out);
    const json u3m = json::parse(in);
    SchemaCheck check;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir_))
        if (entry.is_regular_file())
            check.files[std::filesystem::relative(entry.path(), dir_).string()] = readRegularFile(entry.path().string(), size_t(1) << 30);
    check.document(u3m);
    for (const std::string& p : check.problems) ADD_FAILURE() << p;
    // woven reads the folder form back as it reads the archive.
    const std::string scene = file("read.json");
    std::ofstream(scene) << json{{"gltf", std::string(WOVEN_ASSETS_DIR) + "/cloth_drape.glb"}, {"materials", {{"Cloth", {{"u3m", "satin.u3m"}}}}}}.dump();
    const test::RunResult listed = runWovenCommand("render '" + scene + "' --list");
    EXPECT_EQ(listed.exitCode, 0) << listed.out;
}

TEST_F(U3mCommandTest, BadInputIsRefusedByNameAndLeavesNoFile) {
    const std::string scene = drapeIn("denim");
    struct Case {
        std::string args, message;
    };
    const std::vector<Case> cases = {
        {"-o '" + file("x.u3mz") + "'", "must end in .glb or .gltf (glTF), .u3ma or .u3m (U3M)"},
        {"-o '" + file("x.u3ma") + "' --material Curtain", "--material 'Curtain' is no woven material"},
        {"-o '" + file("nofolder/x.u3ma") + "'", "nofolder"},
    };
    for (const Case& c : cases) {
        const test::RunResult r = runWovenCommand("export '" + scene + "' " + c.args + " --size 64 --preview-size 0");
        EXPECT_NE(r.exitCode, 0) << c.args;
        EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << ": " << r.out;
    }
    EXPECT_FALSE(std::filesystem::exists(file("x.u3ma")));
    const test::RunResult plain = runWovenCommand("export '" + std::string(WOVEN_ASSETS_DIR) + "/lampshade.gltf' -o '" + file("x.u3ma") + "'");
    EXPECT_NE(plain.exitCode, 0);
    EXPECT_NE(plain.out.find("no part of the scene is woven"), std::string::npos) << plain.out;
}

// ---- The archive ----------------------------------------------------------------------------

uint32_t u16(const std::vector<unsigned char>& b, size_t at) { return uint32_t(b[at]) | uint32_t(b[at + 1]) << 8; }
uint32_t u32(const std::vector<unsigned char>& b, size_t at) { return u16(b, at) | u16(b, at + 2) << 16; }

TEST(U3maArchive, WritesOnlyWhatTheSubsetAllowsAndReadsItBack) {
    std::vector<unsigned char> text(5000, 'a'), noise(3000);
    for (size_t i = 0; i < noise.size(); ++i) noise[i] = uint8_t((i * 2654435761u) >> 13);
    const std::vector<ArchiveEntry> entries = {{"cloth.u3m", text}, {"cloth_textures/noise.png", noise}};
    const std::vector<unsigned char> zip = packU3ma(entries, 1796623200);  // 2026-12-07 06:00 UTC
    // Local header: signature, version 0x14, flags bit 11 alone, deflate for the text, no extra field.
    EXPECT_EQ(u32(zip, 0), 0x04034b50u);
    EXPECT_EQ(u16(zip, 4), 0x14u);
    EXPECT_EQ(u16(zip, 6), 0x0800u);
    EXPECT_EQ(u16(zip, 8), 8u);
    EXPECT_EQ(u16(zip, 28), 0u);
    // The end record is the last 22 bytes; the central headers: made by 0x003F, no attributes.
    const size_t end = zip.size() - 22;
    EXPECT_EQ(u32(zip, end), 0x06054b50u);
    EXPECT_EQ(u16(zip, end + 10), 2u);
    const size_t central = u32(zip, end + 16);
    EXPECT_EQ(u32(zip, central), 0x02014b50u);
    EXPECT_EQ(u16(zip, central + 4), 0x003Fu);
    EXPECT_EQ(u32(zip, central + 38), 0u);
    // The time in MS-DOS form, UTC: 06:00:00 on 2026-12-07.
    EXPECT_EQ(u16(zip, 10), (6u << 11));
    EXPECT_EQ(u16(zip, 12), ((2026u - 1980u) << 9) | (12u << 5) | 7u);

    const std::vector<ArchiveEntry> back = unpackU3ma(zip, "test.u3ma", 1 << 20);
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].name, "cloth.u3m");
    EXPECT_EQ(back[0].bytes, text);
    EXPECT_EQ(back[1].bytes, noise);

    std::vector<unsigned char> damaged = zip;
    damaged[central - 1] ^= 1;  // the last byte of the noise, stored (it does not deflate) just before the central directory
    EXPECT_THROW(unpackU3ma(damaged, "test.u3ma", 1 << 20), ArchiveError);
    EXPECT_THROW(unpackU3ma(zip, "test.u3ma", 100), ArchiveError);  // larger than the caller reads
    std::vector<unsigned char> notZip(100, 0);
    EXPECT_THROW(unpackU3ma(notZip, "test.u3ma", 1 << 20), ArchiveError);
    EXPECT_THROW(packU3ma({{"../escape", text}}, 0), ArchiveError);
}

// ---- The construction ---------------------------------------------------------------------

TEST(WeaveConstruction, NamesTheWeave) {
    EXPECT_EQ(construction(WeavePattern::regular(1, 1, 1)), Construction::Plain);
    // Regular (i, j, k): row V + 1 is row V moved k to the left, a diagonal rising to the right for k = 1.
    EXPECT_EQ(construction(WeavePattern::regular(3, 1, 1)), Construction::TwillRight);
    EXPECT_EQ(construction(WeavePattern::regular(2, 2, 3)), Construction::TwillLeft);
    EXPECT_EQ(construction(WeavePattern::regular(1, 4, 2)), Construction::Satin);
    EXPECT_EQ(construction(WeavePattern::regular(4, 1, 3)), Construction::Satin);
    EXPECT_EQ(construction(WeavePattern::fromRows({"|-|-", "-|-|"})), Construction::Plain);  // drawn twice over
    // A herringbone (a 2/2 twill turning every 4 ends) is a dobby weave; a tile of 40 distinct ends a jacquard.
    std::vector<std::string> herringbone(4, std::string(8, '|'));
    for (int v = 0; v < 4; ++v)
        for (int u = 0; u < 8; ++u)
            if (((u < 4 ? u : 7 - u) + v) % 4 < 2) herringbone[size_t(v)][size_t(u)] = '-';
    EXPECT_EQ(construction(WeavePattern::fromRows(herringbone)), Construction::Dobby);
    std::vector<std::string> figured(40, std::string(40, '-'));
    for (int u = 0; u < 40; ++u)
        for (int v = 0; v <= u; ++v) figured[size_t(v)][size_t(u)] = '|';
    EXPECT_EQ(construction(WeavePattern::fromRows(figured)), Construction::Jacquard);
}

}  // namespace
}  // namespace woven
