#pragma once
// Parsing JSON that someone else wrote (glTF files, scene files, material files, bsdf-eval's
// stdin), read exactly as written. nlohmann::json parses, destroys and prints nested values by
// recursion, and tinygltf walks them the same way, so a file nested 20,000 deep overflows the
// stack: the depth is found first by a scan that never recurses, and refused beyond
// kMaxJsonDepth. nlohmann::json also reads a NUL byte as the end of the text (what follows was
// ignored), keeps the last of two equal keys, and hands on "\u0000" inside a string, which a
// file name then ends at: each of these is refused, naming the key.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>

namespace woven {

// Far deeper than any glTF, scene file or material needs (glTF's own nesting is under 10).
constexpr size_t kMaxJsonDepth = 256;

// The largest depth of [ and { outside strings (malformed text is left to the parser).
size_t jsonDepth(std::string_view text);

// What parseUntrustedJson() refuses that a JSON parser may accept: too deep a nesting, a NUL
// byte, a key twice in one object, a string holding U+0000.
struct JsonAsWrittenError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// Throws std::invalid_argument saying what is wrong: JsonAsWrittenError, or the parser's
// message in woven's words (jsonProblem()).
nlohmann::json parseUntrustedJson(std::string_view text);

// A JSON parser's message (nlohmann's, also as tinygltf passes it on) without the library's
// "[json.exception.parse_error.101]" tags, and its number overflow said as the number it is.
std::string jsonProblem(std::string message);

}  // namespace woven
