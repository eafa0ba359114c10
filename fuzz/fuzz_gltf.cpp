// The glTF loader on any bytes: a .glb when they start with its magic "glTF", else a .gltf
// (JSON), beside tri.bin and tri.glb for the buffers and images a file may name.
#include <cstring>

#include "fuzz_input.h"
#include "scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const woven::fuzz::FuzzDir dir;
    const bool glb = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const std::string path = dir.write(glb ? "input.glb" : "input.gltf", data, size);
    woven::fuzz::refusalsAreFine([&] { woven::loadScene(path); });
    return 0;
}
