// `woven bsdf-eval` on any bytes: each line parsed and answered as the command does, one
// material cache per input, so repeated materials take the cached path.
#include <string_view>

#include "bsdf_eval_line.h"
#include "fuzz_input.h"
#include "untrusted_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    woven::MaterialCache cache;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    while (!text.empty()) {
        const size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        woven::fuzz::refusalsAreFine([&] { woven::evalLine(cache, woven::parseUntrustedJson(line)).dump(); });
    }
    return 0;
}
