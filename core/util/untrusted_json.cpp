#include "untrusted_json.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

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

namespace {

// "key" as JSON writes it, so that a key holding quotes or control characters reads unambiguously.
std::string quotedKey(const std::string& key) { return nlohmann::json(key).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); }

// The parser's callback: each object's keys so far, one set a nesting level, to find a key
// written twice; and every key and string checked for U+0000.
class AsWrittenCheck {
public:
    bool operator()(int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using Event = nlohmann::json::parse_event_t;
        if (event == Event::object_start) {
            keys_.emplace_back();
        } else if (event == Event::object_end) {
            keys_.pop_back();
        } else if (event == Event::key) {
            const std::string& key = parsed.get_ref<const std::string&>();
            if (key.find('\0') != std::string::npos)
                throw JsonAsWrittenError("the key " + quotedKey(key) + " holds the character U+0000, which woven reads in no name");
            if (!keys_.empty() && !keys_.back().insert(key).second)
                throw JsonAsWrittenError("the key " + quotedKey(key) + " appears twice in one object (which one is meant?)");
            lastKey_ = key;
        } else if (event == Event::value && parsed.is_string() &&
                   parsed.get_ref<const std::string&>().find('\0') != std::string::npos) {
            throw JsonAsWrittenError("the string " + quotedKey(parsed.get<std::string>()) +
                                     (lastKey_.empty() ? "" : " (near the key " + quotedKey(lastKey_) + ")") +
                                     " holds the character U+0000, where a name or file name would end");
        }
        return true;
    }

private:
    std::vector<std::set<std::string>> keys_;
    std::string lastKey_;
};

}  // namespace

nlohmann::json parseUntrustedJson(std::string_view text) {
    if (const size_t depth = jsonDepth(text); depth > kMaxJsonDepth)
        throw JsonAsWrittenError("JSON nested " + std::to_string(depth) + " deep, more than the " +
                                 std::to_string(kMaxJsonDepth) + " woven reads");
    if (const size_t nul = text.find('\0'); nul != std::string_view::npos)
        throw JsonAsWrittenError("a NUL byte at byte " + std::to_string(nul) + ": JSON text holds none (the parser would stop there)");
    try {
        return nlohmann::json::parse(text, AsWrittenCheck());
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
