#pragma once
// Small valid inputs, written by woven's own writers (WIF, PNG, EXR), stb_image_write (JPEG,
// HDR), a few lines of this file's (16-bit PNG) and the tests' GltfBuilder, so that no file the
// fuzzers start from is someone else's.
#include <string>

namespace woven::fuzz {

// The files fuzzed inputs may name, written into `dir`: tri.gltf with its buffer tri.bin (a
// triangle with a woven material, a camera and a light), tri.glb (the same with a PNG texture),
// twill.wif and sky.hdr.
void writeCompanionFiles(const std::string& dir);

// The seed corpus of every target, one folder each: `dir`/gltf, scene_file, wif, image, exr,
// bsdf_eval (the targets' names without "fuzz_").
void writeSeedCorpora(const std::string& dir);

}  // namespace woven::fuzz
