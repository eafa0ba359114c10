#include "seed_files.h"

#include <stb_image_write.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "draft.h"
#include "draco_grid.h"
#include "gltf_builder.h"
#include "frame_io.h"
#include "image_io.h"
#include "temp_dir.h"
#include "wif_writer.h"

namespace woven::fuzz {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

// JPEG and Radiance HDR, which woven reads but does not write: stb_image_write's.
void writeJpeg(const fs::path& path, int width, int height, const std::vector<unsigned char>& rgb) {
    if (!stbi_write_jpg(path.c_str(), width, height, 3, rgb.data(), 90)) throw std::runtime_error("cannot write " + path.string());
}
void writeHdr(const fs::path& path, int width, int height, const std::vector<float>& rgb) {
    if (!stbi_write_hdr(path.c_str(), width, height, 3, rgb.data())) throw std::runtime_error("cannot write " + path.string());
}

// A 16-bit grey PNG, which stb_image_write does not write: the signature, IHDR, one IDAT of
// unfiltered rows and IEND, each chunk with its CRC-32 (zlib's).
void writeGrey16Png(const fs::path& path, int width, int height, const std::vector<uint16_t>& grey) {
    const auto bigEndian = [](uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16 & 255), char(v >> 8 & 255), char(v & 255)};
    };
    std::string png = "\x89PNG\r\n\x1a\n";
    const auto chunk = [&](const std::string& type, const std::string& data) {
        const std::string body = type + data;
        png += bigEndian(uint32_t(data.size())) + body +
               bigEndian(uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
    };
    chunk("IHDR", bigEndian(uint32_t(width)) + bigEndian(uint32_t(height)) + std::string{16, 0, 0, 0, 0});  // 16-bit grey
    std::string rows;
    for (int y = 0; y < height; ++y) {
        rows += '\0';  // no filter
        for (int x = 0; x < width; ++x) rows += bigEndian(grey[size_t(y * width + x)]).substr(2);
    }
    uLongf size = compressBound(uLong(rows.size()));
    std::string compressed(size, '\0');
    if (compress(reinterpret_cast<Bytef*>(compressed.data()), &size, reinterpret_cast<const Bytef*>(rows.data()), uLong(rows.size())) != Z_OK)
        throw std::runtime_error("cannot compress " + path.string());
    compressed.resize(size);
    chunk("IDAT", compressed);
    chunk("IEND", "");
    writeText(path, png);
}

TextureImage checker() {
    TextureImage t;
    t.name = "checker";
    t.width = t.height = 2;
    t.bytes = {{200, 30, 20, 255}, {20, 20, 20, 128}, {20, 20, 20, 255}, {200, 30, 20, 0}};
    return t;
}

// One triangle in a scene with a woven material, a camera and a point light; with a PNG texture
// in its buffer when `textured`.
test::GltfBuilder triangle(bool textured) {
    test::GltfBuilder b;
    const int position = b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int normal = b.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int uv = b.addVec2({{0, 0}, {1, 0}, {0, 1}});
    const int indices = b.addIndices({0, 1, 2});
    json material = {{"name", "Cloth"},
                     {"pbrMetallicRoughness", {{"baseColorFactor", {0.55, 0.12, 0.1, 1}}, {"roughnessFactor", 0.6}}},
                     {"extensions", {{"WOVEN_fabric", {{"pattern", {1, 2, 1}}, {"repeat", {120, 120}}, {"ex", 100}, {"ey", 2}}}}}};
    b.useExtension("WOVEN_fabric");
    if (textured) {
        const std::vector<unsigned char> png = encodeTexturePng(checker());
        b.json()["images"] = {{{"bufferView", b.addView(png.data(), png.size())}, {"mimeType", "image/png"}}};
        b.json()["textures"] = {{{"source", 0}}};
        material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    }
    b.addMaterial(material);
    const int mesh = b.addMesh({{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}},
                                {"indices", indices},
                                {"material", 0}},
                               "Triangle");
    b.json()["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.01}, {"aspectRatio", 1.5}}}}};
    b.useExtension("KHR_lights_punctual");
    b.json()["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 100}, {"color", {1, 0.9, 0.8}}}};
    b.setScene({b.addNode({{"mesh", mesh}, {"name", "Cloth node"}}),
                b.addNode({{"camera", 0}, {"translation", {0.3, 0.3, 3}}}),
                b.addNode({{"translation", {0, 2, 2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}})});
    return b;
}

IndexSet setOf(std::initializer_list<int> members) {
    IndexSet s;
    for (int m : members) s.set(size_t(m));
    return s;
}

// 2/2 twill by tie-up and treadling with per-thread colours, spacing and thickness (liftPlan
// false), or plain weave by a lift plan with colours only.
Draft smallDraft(bool liftPlan) {
    Draft d;
    d.title = liftPlan ? "plain" : "twill";
    d.shafts = liftPlan ? 2 : 4;
    d.palette = {{0.9f, 0.9f, 0.85f}, {0.05f, 0.05f, 0.1f}};
    d.warp.count = d.weft.count = 8;
    for (int i = 0; i < 8; ++i) {
        d.threading.push_back(setOf({i % d.shafts}));
        d.warp.colors.push_back(d.palette[0]);
        d.weft.colors.push_back(d.palette[size_t(i / 4 % 2)]);
        if (liftPlan) d.liftplan.push_back(setOf({i % 2}));
        else d.treadling.push_back(setOf({i % 4}));
    }
    if (!liftPlan) {
        d.treadles = 4;
        for (int t = 0; t < 4; ++t) d.tieup.push_back(setOf({t, (t + 1) % 4}));
        for (DraftThreads* side : {&d.warp, &d.weft}) {
            side->spacing.assign(8, 0.05f);
            side->thickness.assign(8, 0.04f);
        }
    }
    return d;
}

ExrImage render(bool withSamples) {
    ExrImage exr;
    exr.image.width = 3;
    exr.image.height = 2;
    exr.image.pixels = {{0.1f, 0.2f, 0.3f}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 6, 7}, {0, 0, 0}};
    if (withSamples) {
        exr.sampleCount.assign(6, 4.0f);
        for (const glm::vec3& p : exr.image.pixels)
            for (int c = 0; c < 3; ++c) {
                ExactSum sum;
                for (int s = 0; s < 4; ++s) sum.add(p[c]);
                exr.sampleSums.push_back(sum);
            }
        exr.samples = SampleRange{16, 4};
        exr.frame = FrameIdentity{"0123456789abcdef", 7, "auto: bdpt", 8, false, "sobol"};
    }
    return exr;
}

void writeSkyHdr(const fs::path& path) {
    const std::vector<float> sky = {0.5f, 0.6f, 0.9f, 0.4f, 0.5f, 0.8f, 3, 3, 2.5f, 0.3f, 0.3f, 0.3f,
                                    0.2f, 0.2f, 0.2f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.2f, 0.2f, 0.2f};
    writeHdr(path, 4, 2, sky);
}

void copyInto(const fs::path& from, const fs::path& folder) {
    fs::copy_file(from, folder / from.filename(), fs::copy_options::overwrite_existing);
}

}  // namespace

void writeCompanionFiles(const std::string& dir) {
    const fs::path d(dir);
    triangle(false).writeGltf((d / "tri.gltf").string());  // and tri.bin
    triangle(true).writeGlb((d / "tri.glb").string());
    writeText(d / "twill.wif", formatWif(smallDraft(false), "twill.wif"));
    writeSkyHdr(d / "sky.hdr");
}

void writeSeedCorpora(const std::string& dir) {
    const fs::path root(dir);
    for (const char* target : {"gltf", "scene_file", "wif", "image", "exr", "bsdf_eval", "options", "converge"})
        fs::create_directories(root / target);
    const test::TempDir companions;
    writeCompanionFiles(companions.path().string());

    // glTF: an external buffer (tri.bin, which the target's folder holds), a data URI, a .glb.
    copyInto(companions.path() / "tri.gltf", root / "gltf");
    copyInto(companions.path() / "tri.glb", root / "gltf");
    triangle(true).writeGltf((root / "gltf" / "tri_embedded.gltf").string(), test::GltfBuilder::Storage::DataUri);
    // EXT_meshopt_compression's decoder: gltf-transform's meshopt cloth (the tests' file).
    copyInto(fs::path(WOVEN_TEST_DATA_DIR) / "cloth_meshopt.glb", root / "gltf");
    // KHR_draco_mesh_compression's decoder: the tests' grid through draco::Encoder.
    test::writeDracoGrid((root / "gltf" / "grid_draco.glb").string(), test::Grid());
    // EXT_mesh_gpu_instancing: the triangle placed three times, one copy mirrored.
    test::GltfBuilder instanced = triangle(false);
    instanced.useExtension("EXT_mesh_gpu_instancing", true);
    const int t = instanced.addVec3({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}), sc = instanced.addVec3({{1, 1, 1}, {-1, 1, 1}, {1, 2, 1}});
    instanced.json()["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"] = {{"attributes", {{"TRANSLATION", t}, {"SCALE", sc}}}};
    instanced.writeGlb((root / "gltf" / "tri_instanced.glb").string());

    // Scene files naming the companion files, with every key.
    const json everyKey = {
        {"gltf", "tri.gltf"},
        {"materials", {{"*", {{"repeat", {120, 120}}}}, {"Cloth", {{"pattern", {1, 2, 1}}, {"ex", 100}, {"ey", 2}}}}},
        {"environment", {{"color", {0.6, 0.7, 0.8}}, {"image", "sky.hdr"}, {"rotation", 90}}},
        {"lights", {{{"type", "point"}, {"position", {0, 3, 0}}, {"color", {1, 0.9, 0.8}}, {"intensity", 20}},
                    {{"type", "spot"}, {"position", {2, 3, 0}}, {"direction", {-1, -1, 0}}, {"intensity", 50},
                     {"inner_cone_degrees", 15}, {"outer_cone_degrees", 30}},
                    {{"type", "directional"}, {"direction", {0, -1, -1}}, {"intensity", 2}}}},
        {"camera", {{"position", {0, 1.5, 3}}, {"target", {0, 0.5, 0}}, {"up", {0, 1, 0}}, {"yfov_degrees", 40}}},
        {"render", {{"width", 64}, {"height", 48}, {"spp", 4}, {"integrator", "bdpt"}}}};
    writeText(root / "scene_file" / "every_key.json", everyKey.dump(1));
    const json draft = {{"gltf", "tri.glb"},
                        {"materials", {{"node:Cloth*", {{"wif", "twill.wif"}, {"scale", "draft"}, {"noise", 0.2}}}}}};
    writeText(root / "scene_file" / "draft.json", draft.dump(1));

    writeText(root / "wif" / "twill.wif", formatWif(smallDraft(false), "twill.wif"));
    writeText(root / "wif" / "plain_liftplan.wif", formatWif(smallDraft(true), "plain_liftplan.wif"));

    // Images: 8-bit RGB and RGBA PNG, 16-bit grey PNG, JPEG, HDR, EXR.
    const fs::path images = root / "image";
    writePng((images / "rgb.png").string(), render(false).image);
    writeTexturePng((images / "rgba.png").string(), checker());
    const std::vector<uint16_t> grey = {0, 1000, 20000, 65535, 300, 40000};
    writeGrey16Png(images / "grey16.png", 3, 2, grey);
    std::vector<unsigned char> photo(16 * 8 * 3);
    for (size_t i = 0; i < photo.size(); ++i) photo[i] = (unsigned char)(i * 37 % 251);
    writeJpeg(images / "photo.jpg", 16, 8, photo);
    writeSkyHdr(images / "sky.hdr");
    writeExr((images / "linear.exr").string(), render(false));

    // EXR: a plain half-float image, and a render's part file with N, the sums and the range.
    writeExr((root / "exr" / "half.exr").string(), render(false), ExrPrecision::Half);
    writeExr((root / "exr" / "render_part.exr").string(), render(true), ExrPrecision::Float);

    // bsdf-eval: several queries per input, materials repeated so the cache is used.
    const json plain = {{"pattern", {1, 1, 1}}, {"repeat", {10, 10}}};
    const json rich = {{"tile", {"-|", "|-"}}, {"yarns", {{{"ex", 300}, {"ey", 5}}, {{"rs", 0.1}}}},
                       {"warp_yarns", {0, 1}}, {"weft_colors", {{0.9, 0.1, 0.1}, {0.1, 0.1, 0.9}}},
                       {"warp_spacing", {1, 2}}, {"crimp", 0.3}, {"noise", 0.2}, {"backing", 1}};
    std::string queries;
    for (const json& q : {json{{"material", plain}, {"uv", {0.03, 0.07}}, {"wi", {0, 0, 1}}, {"wo", {0.3, 0, 1}}},
                          json{{"material", plain}, {"wi", {1, 1, 0.2}}, {"wo", {0, -0.5, 1}}},
                          json{{"material", rich}, {"uv", {0.5, 0.25}}, {"wi", {0.2, 0.1, 1}}, {"wo", {0.1, 0.4, -1}}}})
        queries += q.dump() + "\n";
    writeText(root / "bsdf_eval" / "queries.jsonl", queries);

    // Command lines, their words joined by NUL bytes (fuzz_input.h): each command with options
    // of every kind (numbers, whole numbers, lists, flags, choices, repeated options).
    const auto commandLine = [](const std::vector<std::string>& words) {
        std::string line;
        for (size_t i = 0; i < words.size(); ++i) line += (i ? std::string(1, '\0') : "") + words[i];
        return line;
    };
    const std::vector<std::vector<std::string>> commands = {
        {"render", "scene.json", "--width", "64", "--height", "48", "--spp", "4", "--integrator", "bdpt", "--seed", "7",
         "--max-depth", "5", "--noise-threshold", "0.02", "--no-denoise", "--exposure", "1.5", "--tone-map", "aces",
         "--environment", "0.5", "--environment-rotation", "90", "--woven", "*={\"repeat\":[50,50]}", "--threads", "2",
         "--time", "1", "--first-sample", "16", "-o", "out.exr"},
        {"render", "scene.gltf", "--no-passes", "--camera", "auto", "--list"},
        {"preview", "scene.json", "--headless", "--screenshot", "shot.png", "--width", "32", "--height", "24", "--final"},
        {"merge", "a.exr", "b.exr", "-o", "merged.exr", "--expect-samples", "64"},
        {"submit", "scene_%04d.json", "--tasks", "4", "--spp", "64", "--job-dir", "job", "--frames", "0..3", "-o", "frame_%04d.exr"},
        {"export", "scene.json", "--size", "256", "-o", "out.glb"},
        {"bake", "scene.json", "--size", "64", "-o", "baked"},
        {"fit", "shot.json", "--target", "Cloth", "--time", "5", "--spp", "4", "-o", "fit.json"},
        {"pattern", "--pattern", "2,2,1", "--size", "16,8"},
        {"fabrics", "--json"},
        {"bsdf-plot", "--material", "{\"preset\":\"denim\"}", "--theta", "30", "--size", "64", "-o", "plot.png"},
        {"converge", "scene.json", "--budgets", "1,2,4", "--integrators", "path,bdpt", "--filter", "on,off",
         "--noise-thresholds", "0,0.02", "--denoise", "on", "--reference-time", "10", "--width", "64", "--height", "48"},
        {"render", "--help"},
        {"--version"},
    };
    for (size_t i = 0; i < commands.size(); ++i)
        writeText(root / "options" / ("command_" + std::to_string(i)), commandLine(commands[i]));
    // converge's own arguments (its target parses them without the command's name).
    writeText(root / "converge" / "every_option", commandLine(std::vector<std::string>(commands[11].begin() + 1, commands[11].end())));
    writeText(root / "converge" / "out_of_order", commandLine({"s.gltf", "--budgets", "8,0.5,2", "--noise-thresholds", "0.1,0,0.01",
                                                               "--integrators", "auto", "--out-dir", "out", "--threads", "0"}));
}

}  // namespace woven::fuzz
