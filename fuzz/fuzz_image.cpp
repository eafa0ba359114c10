// Image decoding on any bytes: readImage (textures and environment maps from files) and
// decodeTexture (textures embedded in a glTF buffer).
#include "fuzz_input.h"
#include "image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const woven::fuzz::FuzzDir dir;
    const std::string path = dir.write("input.image", data, size);
    woven::fuzz::refusalsAreFine([&] { woven::readImage(path, woven::ChannelEncoding::Srgb); });
    woven::fuzz::refusalsAreFine([&] { woven::decodeTexture(data, size, "input"); });
    return 0;
}
