// `woven bsdf-eval` on any bytes: each line answered as the command answers it, one BsdfEval
// per input, so repeated materials take the cached path.
#include <string_view>

#include "bsdf_eval.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    woven::BsdfEval eval;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    while (!text.empty()) {
        const size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end);
        text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
        woven::fuzz::refusalsAreFine([&] { eval.answer(line); });
    }
    return 0;
}
