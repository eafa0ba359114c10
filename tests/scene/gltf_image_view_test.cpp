// An image whose buffer view lies past its buffer: tinygltf handed woven &buffer[byteOffset]
// with byteLength unchecked, and woven copied from beyond the buffer (fuzz/fuzz_gltf found it:
// a heap-buffer-overflow in a .glb of 1.7 KB). Now a SceneError names the image and the view.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "gltf_builder.h"
#include "scene_loader.h"
#include "temp_dir.h"
#include "../common/load_error.h"

namespace woven {
namespace {

using test::loadError;

using ::testing::HasSubstr;

// A triangle textured by an image held in buffer view `view`, whose byteLength is then set to
// `claimedLength` (the view's real bytes are 16).
test::GltfBuilder texturedTriangle(int* view) {
    test::GltfBuilder b;
    const int position = b.addPositions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int uv = b.addVec2({{0, 0}, {1, 0}, {0, 1}});
    const unsigned char notYetDecoded[16] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    *view = b.addView(notYetDecoded, sizeof notYetDecoded);
    b.json()["images"] = {{{"bufferView", *view}, {"mimeType", "image/png"}}};
    b.json()["textures"] = {{{"source", 0}}};
    b.addMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    const int mesh = b.addMesh({{"attributes", {{"POSITION", position}, {"TEXCOORD_0", uv}}}, {"material", 0}});
    b.setScene({b.addNode({{"mesh", mesh}})});
    return b;
}

TEST(GltfImageView, AViewPastItsBufferIsRefusedInGlbAndGltf) {
    const test::TempDir dir;
    for (const auto& [offset, length] : {std::pair<int, int>{0, 1000}, {4000, 16}, {0, 0x7fffffff}}) {
        int view = 0;
        test::GltfBuilder b = texturedTriangle(&view);
        b.json()["bufferViews"][size_t(view)]["byteLength"] = length;
        if (offset) b.json()["bufferViews"][size_t(view)]["byteOffset"] = offset;
        b.writeGlb(dir.file("scene.glb"));
        b.writeGltf(dir.file("scene.gltf"), test::GltfBuilder::Storage::DataUri);
        for (const std::string name : {"scene.glb", "scene.gltf"}) {
            const std::string error = loadError(dir.file(name));
            EXPECT_THAT(error, HasSubstr(dir.file(name) + ": "));
            EXPECT_THAT(error, HasSubstr("image 0: bufferView " + std::to_string(view))) << error;
            EXPECT_THAT(error, HasSubstr("lies outside buffer 0")) << error;
        }
    }
}

}  // namespace
}  // namespace woven
