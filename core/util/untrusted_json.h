#pragma once
// Parsing JSON that someone else wrote (glTF files, scene files, material files, bsdf-eval's
// stdin). nlohmann::json parses, destroys and prints nested values by recursion, and tinygltf
// walks them the same way, so a file nested 20,000 deep overflows the stack: the depth is found
// first by a scan that never recurses, and refused beyond kMaxJsonDepth.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace woven {

// Far deeper than any glTF, scene file or material needs (glTF's own nesting is under 10).
constexpr size_t kMaxJsonDepth = 256;

// The largest depth of [ and { outside strings (malformed text is left to the parser).
size_t jsonDepth(std::string_view text);

// Throws std::invalid_argument saying what is wrong: the depth, or the parser's message in
// woven's words (jsonProblem()).
nlohmann::json parseUntrustedJson(std::string_view text);

// A JSON parser's message (nlohmann's, also as tinygltf passes it on) without the library's
// "[json.exception.parse_error.101]" tags, and its number overflow said as the number it is.
std::string jsonProblem(std::string message);

}  // namespace woven
