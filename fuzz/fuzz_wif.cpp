// The WIF reader on any bytes, and what the model takes from a draft it accepts.
#include <string>
#include <string_view>
#include <vector>

#include "draft_tile.h"
#include "fuzz_input.h"
#include "wif_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    woven::fuzz::refusalsAreFine([&] {
        std::vector<std::string> warnings;
        const woven::Draft draft =
            woven::parseWif(std::string_view(reinterpret_cast<const char*>(data), size), "input.wif", warnings);
        woven::draftTile(draft, "input.wif");
    });
    return 0;
}
