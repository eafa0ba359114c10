// Files made by someone else, as they come: nested too deep, pointing outside their folder, at
// a FIFO or a directory, images of formats woven does not read, empty, truncated or claiming
// sizes they do not hold. Each gets a message naming the file and the problem, and none
// crashes, hangs or allocates what it claims.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <array>
#include <cmath>
#include <fstream>
#include <stb_image_write.h>

#include "gltf_builder.h"
#include "image_io.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "untrusted_json.h"
#include "../common/load_error.h"

namespace woven {
namespace {

using test::loadError;

using test::GltfBuilder;
using test::TempDir;
using ::testing::HasSubstr;
using json = nlohmann::json;

std::string nested(size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

TEST(UntrustedJson, DepthIsFoundWithoutRecursionAndRefused) {
    EXPECT_EQ(jsonDepth(R"({"a": [1, {"b": "[[[{"}]})"), 3u);  // brackets in strings do not count
    EXPECT_EQ(jsonDepth(R"(["\"[", [2]])"), 2u);                 // nor after an escaped quote
    EXPECT_NO_THROW(parseUntrustedJson(nested(kMaxJsonDepth)));
    EXPECT_THROW(parseUntrustedJson(nested(80000)), std::invalid_argument);
}

// JSON read exactly as written: a NUL byte (the parser stopped there), a key written twice (the
// last was kept), U+0000 in a string (a file name ended there) are refused, naming the key.
TEST(UntrustedJson, NulBytesDuplicateKeysAndU0000AreRefusedNamingTheKey) {
    using ::testing::ThrowsMessage;
    EXPECT_THAT([] { parseUntrustedJson(std::string("{\"a\": 1}\0 trailing", 18)); },
                ThrowsMessage<JsonAsWrittenError>(HasSubstr("a NUL byte at byte 8")));
    EXPECT_THAT([] { parseUntrustedJson(R"({"a": {"b": 1, "c": 2, "b": 3}})"); },
                ThrowsMessage<JsonAsWrittenError>(HasSubstr("the key \"b\" appears twice")));
    EXPECT_THAT([] { parseUntrustedJson(R"({"gltf": "cloth.gltf\u0000.missing"})"); },
                ThrowsMessage<JsonAsWrittenError>(HasSubstr("(near the key \"gltf\") holds the character U+0000")));
    EXPECT_THAT([] { parseUntrustedJson(R"({"a\u0000b": 1})"); }, ThrowsMessage<JsonAsWrittenError>(HasSubstr("U+0000")));
    EXPECT_THAT([] { parseUntrustedJson(R"({"a": 1} {"b": 2})"); }, ThrowsMessage<std::invalid_argument>(HasSubstr("not valid JSON")));
    // The same key in two objects, or in objects of an array, is no duplicate.
    EXPECT_NO_THROW(parseUntrustedJson(R"({"a": {"k": 1}, "b": {"k": 2}, "c": [{"k": 1}, {"k": 2}], "k": 0})"));
}

TEST(UntrustedJson, EveryFileWovenReadsIsReadAsWritten) {
    TempDir dir;
    GltfBuilder b;
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", b.addPositions(p)}}}})}})});
    b.writeGltf(dir.file("cloth.gltf"));
    std::ofstream(dir.file("nul.json"), std::ios::binary) << R"({"gltf": "cloth.gltf\u0000.missing"})";
    EXPECT_THAT(loadError(dir.file("nul.json")), HasSubstr("nul.json: the string \"cloth.gltf\\u0000.missing\""));
    std::ofstream(dir.file("after.json"), std::ios::binary) << std::string("{\"gltf\": \"cloth.gltf\"}\0{", 24);
    EXPECT_THAT(loadError(dir.file("after.json")), HasSubstr("after.json: a NUL byte at byte 22"));
    std::ofstream(dir.file("twice.json")) << R"({"gltf": "cloth.gltf", "gltf": "other.gltf"})";
    EXPECT_THAT(loadError(dir.file("twice.json")), HasSubstr("twice.json: the key \"gltf\" appears twice"));
    // glTF's JSON forbids duplicate keys: refused before tinygltf keeps one of them.
    std::ifstream in(dir.file("cloth.gltf"));
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.insert(text.rfind('}'), R"(, "scene": 0, "scene": 0)");
    std::ofstream(dir.file("twice.gltf")) << text;
    EXPECT_THAT(loadError(dir.file("twice.gltf")), HasSubstr("twice.gltf: the key \"scene\" appears twice"));
}

TEST(UntrustedGltf, ExtrasNestedDeepAreRefusedBeforeParsing) {
    TempDir dir;
    GltfBuilder b;
    b.setScene({b.addNode(json::object())});
    b.writeGltf(dir.file("deep.gltf"));
    std::ifstream in(dir.file("deep.gltf"));
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.insert(text.rfind('}'), ", \"extras\": " + nested(20000));
    std::ofstream(dir.file("deep.gltf")) << text;
    EXPECT_THAT(loadError(dir.file("deep.gltf")), HasSubstr("deep.gltf: JSON nested 20001 deep"));
}

TEST(UntrustedSceneFile, NestingAndNonFilesAreRefused) {
    TempDir dir;
    std::ofstream(dir.file("deep.json")) << "{\"gltf\": \"x.gltf\", \"render\": " << nested(5000) << "}";
    EXPECT_THAT(loadError(dir.file("deep.json")), HasSubstr("deep.json: JSON nested 5001 deep"));
    std::filesystem::create_directory(dir.file("folder.json"));
    EXPECT_THAT(loadError(dir.file("folder.json")), HasSubstr("folder.json: is a directory"));
}

// A triangle whose buffer is the file `uri`.
void writeWithBuffer(const std::string& path, const std::string& uri) {
    GltfBuilder b;
    const std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    b.setScene({b.addNode({{"mesh", b.addMesh({{"attributes", {{"POSITION", b.addPositions(p)}}}})}})});
    b.writeGltf(path);
    std::ifstream in(path);
    json doc = json::parse(in);
    doc["buffers"][0]["uri"] = uri;
    std::ofstream(path) << doc.dump();
}

TEST(UntrustedGltf, BuffersComeFromTheFilesFolderUnlessAllowed) {
    TempDir dir;
    std::filesystem::create_directories(dir.file("assets"));
    writeWithBuffer(dir.file("assets/a.gltf"), "a.bin");
    const std::string bin = dir.file("assets/a.bin");
    std::filesystem::copy_file(bin, dir.file("outside.bin"));
    EXPECT_EQ(loadError(dir.file("assets/a.gltf")), "(no error)");
    // The same buffer one folder up, by a relative and by an absolute path.
    writeWithBuffer(dir.file("assets/up.gltf"), "../outside.bin");
    EXPECT_THAT(loadError(dir.file("assets/up.gltf")), HasSubstr("is outside the glTF file's folder"));
    EXPECT_EQ(loadError(dir.file("assets/up.gltf"), LoadOptions{true}), "(no error)");
    // An absolute path is not read either (tinygltf looks for it below the file's folder).
    writeWithBuffer(dir.file("assets/abs.gltf"), dir.file("outside.bin"));
    EXPECT_THAT(loadError(dir.file("assets/abs.gltf")), HasSubstr("abs.gltf: cannot read glTF"));
}

TEST(UntrustedGltf, BuffersThatAreNotFilesAreRefusedAtOnce) {
    TempDir dir;
    writeWithBuffer(dir.file("dot.gltf"), ".");
    EXPECT_THAT(loadError(dir.file("dot.gltf")), HasSubstr("dot.gltf"));
    // A FIFO with no writer: reading it would block for ever.
    ASSERT_EQ(mkfifo(dir.file("pipe.bin").c_str(), 0600), 0);
    writeWithBuffer(dir.file("fifo.gltf"), "pipe.bin");
    EXPECT_THAT(loadError(dir.file("fifo.gltf")), HasSubstr("is not a regular file"));
}

TEST(UntrustedGltf, AnAccessorClaimingMoreThanItsBufferHoldsIsRefusedBeforeAllocating) {
    TempDir dir;
    writeWithBuffer(dir.file("big.gltf"), "big.bin");
    std::filesystem::copy_file(dir.file("big.bin"), dir.file("big.bin.keep"));
    std::ifstream in(dir.file("big.gltf"));
    json doc = json::parse(in);
    doc["accessors"][0]["count"] = 178956970;  // 2 GiB of vec3 floats, in a 36-byte buffer
    doc["accessors"][0].erase("min");
    doc["accessors"][0].erase("max");
    std::ofstream(dir.file("big.gltf")) << doc.dump();
    EXPECT_THAT(loadError(dir.file("big.gltf")), HasSubstr("big.gltf"));
}

TEST(UntrustedGltf, ASparseAccessorClaimingBillionsOfElementsIsRefusedBeforeAllocating) {
    TempDir dir;
    writeWithBuffer(dir.file("sparse.gltf"), "sparse.bin");
    std::ifstream in(dir.file("sparse.gltf"));
    json doc = json::parse(in);
    const json sparse = {{"count", 2147483647},
                         {"indices", {{"bufferView", 0}, {"componentType", 5125}}},
                         {"values", {{"bufferView", 0}}}};
    // Sparse entries in a 36-byte view: 2^31 - 1 indices and values it cannot hold.
    doc["accessors"][0]["sparse"] = sparse;
    std::ofstream(dir.file("sparse.gltf")) << doc.dump();
    EXPECT_THAT(loadError(dir.file("sparse.gltf")), HasSubstr("sparse indices"));
    // And with no view at all: zeros made sparse, 2^31 - 1 elements of nothing.
    doc["accessors"][0] = {{"componentType", 5126}, {"count", 2147483647}, {"type", "VEC3"}, {"sparse", sparse}};
    std::ofstream(dir.file("sparse.gltf")) << doc.dump();
    EXPECT_THAT(loadError(dir.file("sparse.gltf")), HasSubstr("claims 2147483647 elements"));
}

// A million coincident triangles rendered at about 440 rays/s (issue 21): every ray through them
// tested each copy. Exact copies, in any rotation of their corners, are dropped at load and
// counted in one line for the file; the reversed triangle is the other face and stays.
TEST(UntrustedGltf, CoincidentCopiesOfATriangleAreDroppedAndCountedInOneLine) {
    TempDir dir;
    GltfBuilder b;
    // Vertices 3 to 5 repeat 0 to 2 where they are: copies by index and by position alike.
    const int positions = b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    constexpr uint32_t kCopies = 200000;
    const std::array<uint32_t, 9> rotations = {0, 1, 2, 4, 5, 3, 2, 0, 1};
    std::vector<uint32_t> indices;
    for (uint32_t i = 0; i < kCopies; ++i)
        for (int k = 0; k < 3; ++k) indices.push_back(rotations[(i % 3) * 3 + k]);
    indices.insert(indices.end(), {0, 2, 1});  // the back face
    const int mesh = b.addMesh({{"attributes", {{"POSITION", positions}}}, {"indices", b.addIndices(indices)}}, "pile");
    // The same pile again on a second node: two primitives, still one line.
    b.setScene({b.addNode({{"mesh", mesh}, {"name", "a"}}), b.addNode({{"mesh", mesh}, {"name", "b"}})});
    b.writeGlb(dir.file("pile.glb"));
    const SceneDescription scene = loadScene(dir.file("pile.glb"));
    ASSERT_EQ(scene.meshes.size(), 2u);
    for (const Mesh& m : scene.meshes) EXPECT_EQ(m.triangles, (std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 1}}));
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "dropped 399998 duplicate triangles in 2 primitives ('a/pile/0', 'b/pile/0')");
}

// A million instances in one place hung a 32 x 24 render (every ray tests every copy): copies of
// another's placement are dropped in one warning, as coincident triangles are, also those a few
// rounding steps away (kCoincidentFraction: 2^-20 of the copy's size). A scale of 1e30 is no
// "zero scale": it is refused as past the coordinate limit.
TEST(UntrustedGltf, CoincidentInstancesAreDrawnOnceAndAHugeScaleIsNoZeroScale) {
    TempDir dir;
    const auto write = [&](const std::string& name, const nlohmann::json& attributes, GltfBuilder& b) {
        const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}}}, "leaf");
        b.useExtension("EXT_mesh_gpu_instancing", true);
        b.setScene({b.addNode({{"mesh", mesh}, {"name", "tree"}, {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", attributes}}}}}})});
        b.writeGlb(dir.file(name));
    };
    const auto instances = [&](const std::string& name) {
        const SceneDescription scene = loadScene(dir.file(name));
        EXPECT_EQ(scene.meshes.size(), 1u);
        return scene.meshes.empty() ? std::vector<glm::mat4>() : *scene.meshes[0].instances;
    };
    GltfBuilder pile;
    std::vector<glm::vec3> t(1000000, glm::vec3(0.0f));
    t[500000] = glm::vec3(5.0f, 0.0f, 0.0f);
    write("pile.glb", {{"TRANSLATION", pile.addVec3(t)}}, pile);
    const SceneDescription scene = loadScene(dir.file("pile.glb"));
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.meshes[0].instances->size(), 2u);
    EXPECT_EQ((*scene.meshes[0].instances)[1][3], glm::vec4(5.0f, 0.0f, 0.0f, 1.0f));
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_THAT(scene.warnings[0], HasSubstr("node 'tree': 999998 of its EXT_mesh_gpu_instancing instances repeat another's placement"));

    // A million copies moved and turned by less than the grid's spacing (2^-20 of the leaf's
    // diagonal, 1.41): each coordinate of the three placed corners that fix a flat leaf lies in at
    // most two cells, so at most 2^9 copies stay.
    GltfBuilder near;
    std::vector<glm::vec3> moved(1000000);
    std::vector<glm::vec4> turned(1000000);
    uint32_t state = 12345;
    const auto jitter = [&] {  // in [-1, 1)
        state = state * 1664525u + 1013904223u;
        return float(int32_t(state)) / 2147483648.0f;
    };
    const float step = std::ldexp(1.0f, -22);
    for (size_t i = 0; i < moved.size(); ++i) {
        moved[i] = glm::vec3(0.3f, 0.2f, 0.1f) + step * glm::vec3(jitter(), jitter(), jitter());
        turned[i] = glm::normalize(glm::vec4(0.5f * step * jitter(), 0.5f * step * jitter(), 0.5f * step * jitter(), 1.0f));
    }
    write("near.glb", {{"TRANSLATION", near.addVec3(moved)}, {"ROTATION", near.addVec4(turned)}}, near);
    const size_t kept = instances("near.glb").size();
    EXPECT_GE(kept, 1u);
    EXPECT_LE(kept, 512u);
    // Copies eight grid steps apart (8 x 2^-20 of their size) are distinct, all kept.
    GltfBuilder row;
    std::vector<glm::vec3> apart(1000);
    for (size_t i = 0; i < apart.size(); ++i) apart[i] = glm::vec3(0.3f + float(i) * 8.0f * std::ldexp(1.0f, -20), 0.2f, 0.1f);
    write("row.glb", {{"TRANSLATION", row.addVec3(apart)}}, row);
    EXPECT_EQ(instances("row.glb").size(), apart.size());

    GltfBuilder huge;
    write("huge.glb", {{"SCALE", huge.addVec3({glm::vec3(1e30f)})}}, huge);
    const std::string error = loadError(dir.file("huge.glb"));
    EXPECT_THAT(error, HasSubstr("huge.glb: node 'tree': EXT_mesh_gpu_instancing instance 0: "));
    EXPECT_THAT(error, ::testing::Not(HasSubstr("zero scale")));
}

// fuzz_gltf's find: a .glb one byte short, whose binary chunk then claims a byte past the file's
// end, had tinygltf copy past its buffer. Refused, naming the file, whether or not the header's
// total length was cut to match.
TEST(UntrustedGltf, ABinaryFileCutShortIsRefusedBeforeItsChunksAreRead) {
    TempDir dir;
    GltfBuilder b;
    const int mesh = b.addMesh({{"attributes", {{"POSITION", b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})}}}}, "tri");
    b.setScene({b.addNode({{"mesh", mesh}})});
    b.writeGlb(dir.file("whole.glb"));
    ASSERT_EQ(loadError(dir.file("whole.glb")), "(no error)");
    std::ifstream in(dir.file("whole.glb"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    bytes.pop_back();
    std::ofstream(dir.file("short.glb"), std::ios::binary) << bytes;
    EXPECT_THAT(loadError(dir.file("short.glb")), HasSubstr("short.glb: cannot read glTF binary: the file is cut short"));
    const uint32_t total = uint32_t(bytes.size());
    bytes.replace(8, 4, reinterpret_cast<const char*>(&total), 4);
    std::ofstream(dir.file("chunk.glb"), std::ios::binary) << bytes;
    EXPECT_THAT(loadError(dir.file("chunk.glb")), HasSubstr("chunk.glb: cannot read glTF binary: the chunk at byte"));
    EXPECT_THAT(loadError(dir.file("chunk.glb")), HasSubstr("past the file's end"));
}

std::string imageError(const std::string& bytes) {
    try {
        decodeTexture(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size(), "texture.x");
    } catch (const ImageError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(UntrustedImages, FormatsWovenDoesNotReadAreRefusedByName) {
    EXPECT_THAT(imageError("P6\n"), HasSubstr("texture.x: the image is PNM"));
    EXPECT_THAT(imageError("GIF89a....."), HasSubstr("is GIF"));
    EXPECT_THAT(imageError(std::string("\0\0\2\0\0\0\0\0\0\0\0\0\x40\0\x40\0\x20\0", 18) + std::string(40, 'x')),
                HasSubstr("TGA"));
    EXPECT_THAT(imageError("hello"), HasSubstr("woven reads PNG, JPEG, WebP, Radiance HDR (.hdr) and OpenEXR (.exr)"));
}

TEST(UntrustedImages, EmptyTruncatedAndOversizedImagesAreRefused) {
    // A Radiance header with no pixels.
    EXPECT_THAT(imageError("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 0\n"), HasSubstr("texture.x"));
    // A PNG cut after its header, and one whose header claims 100000 x 100000 pixels.
    TempDir dir;
    const unsigned char pixels[12] = {};
    ASSERT_TRUE(stbi_write_png(dir.file("p.png").c_str(), 2, 2, 3, pixels, 6));
    std::ifstream in(dir.file("p.png"), std::ios::binary);
    std::string png((std::istreambuf_iterator<char>(in)), {});
    EXPECT_THAT(imageError(png.substr(0, 40)), HasSubstr("texture.x: cannot decode"));
    std::string huge = png;
    const unsigned char side[4] = {0x00, 0x01, 0x86, 0xa0};  // 100000, big-endian, in IHDR
    huge.replace(16, 4, reinterpret_cast<const char*>(side), 4);
    huge.replace(20, 4, reinterpret_cast<const char*>(side), 4);
    const std::string message = imageError(huge);
    EXPECT_THAT(message, HasSubstr("texture.x"));
    EXPECT_THAT(message, ::testing::Not(HasSubstr("(no error)")));
}

}  // namespace
}  // namespace woven
