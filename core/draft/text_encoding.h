#pragma once
// Text from WIF files, which predate UTF-8: programs write Windows-1252 (Latin-1 with printable
// characters in 0x80-0x9F) or, lately, UTF-8.
#include <string>
#include <string_view>

namespace woven {

// UTF-8 text as it is; anything else read as Windows-1252 and converted. Control characters
// (tabs included) become spaces, so the text fits on one line of a file or a window.
std::string textToUtf8(std::string_view text);

}  // namespace woven
