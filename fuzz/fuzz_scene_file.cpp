// woven scene files (.json) on any bytes, beside the glTF, draft and sky files they may name.
#include "fuzz_input.h"
#include "scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const woven::fuzz::FuzzDir dir;
    const std::string path = dir.write("input.json", data, size);
    woven::fuzz::refusalsAreFine([&] { woven::loadScene(path); });
    return 0;
}
