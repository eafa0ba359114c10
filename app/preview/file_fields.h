#pragma once
// The panel's file-name fields: ImGui's text fields edit fixed buffers, and what a file is, the
// panel tells by its name's extension.
#include <cstdio>
#include <string>

namespace woven {

template <size_t N>
void copyToBuffer(char (&buffer)[N], const std::string& text) {
    std::snprintf(buffer, N, "%s", text.c_str());
}

inline bool hasExtension(const std::string& path, const char* ext) {
    const size_t n = std::char_traits<char>::length(ext);
    return path.size() >= n && path.compare(path.size() - n, n, ext) == 0;
}

}  // namespace woven
