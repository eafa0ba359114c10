// readExr on any bytes: what `woven merge` reads of its parts (channel N, the sample sums, the
// sample range).
#include "fuzz_input.h"
#include "frame_io.h"
#include "image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const woven::fuzz::FuzzDir dir;
    const std::string path = dir.write("input.exr", data, size);
    woven::fuzz::refusalsAreFine([&] { woven::readExr(path); });
    return 0;
}
