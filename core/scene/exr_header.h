#pragma once
// A check of an OpenEXR file's headers before OpenEXR reads them: OpenEXR 3.1 allocates the
// size an attribute claims before reading it, so a 76-byte file could take 2 GiB, and a line
// buffer for the data window as it opens the file. Only the attribute sizes are checked here,
// and each part's claimed size is returned for woven's image limits; OpenEXR checks the rest.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace woven {

// What a part's header claims: its data window's size and its channels (0 where the header
// has no dataWindow or channels attribute, which OpenEXR refuses).
struct ExrPartSize {
    int64_t width = 0, height = 0;
    int channels = 0;
};

// Throws ImageError naming `name` when an attribute claims more bytes than the file holds after
// it, a value's size disagrees with what OpenEXR will read of it, or a header is cut short.
std::vector<ExrPartSize> checkExrHeaders(const unsigned char* data, size_t size, const std::string& name);

}  // namespace woven
