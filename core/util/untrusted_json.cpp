#include "untrusted_json.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace woven {

size_t jsonDepth(std::string_view text) {
    size_t depth = 0, deepest = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;  // the escaped character cannot end the string
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

nlohmann::json parseUntrustedJson(std::string_view text) {
    if (const size_t depth = jsonDepth(text); depth > kMaxJsonDepth)
        throw std::invalid_argument("JSON nested " + std::to_string(depth) + " deep, more than the " +
                                    std::to_string(kMaxJsonDepth) + " woven reads");
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw std::invalid_argument(std::string("not valid JSON: ") + e.what());
    }
}

}  // namespace woven
