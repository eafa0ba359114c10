#pragma once
// A check of an OpenEXR file's headers before OpenEXR reads them: OpenEXR 3.1 allocates the
// size an attribute claims before reading it, so a 76-byte file could take 2 GiB. Only the
// attribute sizes are checked here; OpenEXR checks the rest.
#include <cstddef>
#include <string>

namespace woven {

// Throws ImageError naming `name` when an attribute claims more bytes than the file holds after
// it, or a header is cut short.
void checkExrAttributeSizes(const unsigned char* data, size_t size, const std::string& name);

}  // namespace woven
