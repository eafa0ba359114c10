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
        throw std::invalid_argument("not valid JSON: " + jsonProblem(e.what()));
    }
}

std::string jsonProblem(std::string message) {
    static const std::string tag = "[json.exception.";
    for (size_t at; (at = message.find(tag)) != std::string::npos;) {
        const size_t close = message.find("] ", at);
        if (close == std::string::npos) break;
        message.erase(at, close + 2 - at);
    }
    static const std::string overflow = "number overflow parsing '";
    if (const size_t at = message.find(overflow); at != std::string::npos) {
        const size_t end = message.find('\'', at + overflow.size());
        const std::string number = message.substr(at + overflow.size(), end - at - overflow.size());
        message.replace(at, end == std::string::npos ? std::string::npos : end + 1 - at,
                        "the number " + number + " is beyond the range of a double (about 1.8e308)");
    }
    return message;
}

}  // namespace woven
