#include "png_decoding.h"

#include <png.h>

#include <csetjmp>
#include <cstring>

#include "image_checks.h"
#include "image_io.h"

namespace woven {

namespace {

// The file's bytes, read by libpng through readBytes; libpng's errors return by longjmp (its C
// frames cannot be unwound by an exception) with its message, and its warnings are not printed.
struct Reader {
    const unsigned char* data = nullptr;
    size_t size = 0;
    size_t position = 0;
    std::jmp_buf jump;
    char message[256] = "";
};

[[noreturn]] void onError(png_structp png, png_const_charp message) {
    auto* reader = static_cast<Reader*>(png_get_error_ptr(png));
    std::strncpy(reader->message, message, sizeof reader->message - 1);
    std::longjmp(reader->jump, 1);
}

void onWarning(png_structp, png_const_charp) {}

void readBytes(png_structp png, png_bytep out, size_t n) {
    auto* reader = static_cast<Reader*>(png_get_io_ptr(png));
    if (n > reader->size - reader->position) png_error(png, "the file ends early");
    std::memcpy(out, reader->data + reader->position, n);
    reader->position += n;
}

// libpng's state. The functions that call setjmp hold no C++ object that a longjmp could leave
// indeterminate: the pixels are the caller's.
struct Decompressor {
    Reader reader;
    png_structp png = nullptr;
    png_infop info = nullptr;

    Decompressor(const unsigned char* data, size_t size) {
        reader.data = data;
        reader.size = size;
        png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reader, onError, onWarning);
        if (png) info = png_create_info_struct(png);
    }
    ~Decompressor() { png_destroy_read_struct(&png, &info, nullptr); }
    Decompressor(const Decompressor&) = delete;
    Decompressor& operator=(const Decompressor&) = delete;
};

// The header, and the expansions woven asks for: 8 or 16 bits, 1 to 4 channels.
bool readHeader(Decompressor& d) {
    if (setjmp(d.reader.jump)) return false;
    png_set_read_fn(d.png, &d.reader, readBytes);
    png_read_info(d.png, d.info);
    png_set_expand(d.png);  // palettes to RGB, grey below 8 bits to 8, tRNS to alpha
    if (png_get_bit_depth(d.png, d.info) == 16) png_set_swap(d.png);  // PNG is big-endian
    png_set_interlace_handling(d.png);
    png_read_update_info(d.png, d.info);
    return true;
}

bool readRows(Decompressor& d, png_bytepp rows) {
    if (setjmp(d.reader.jump)) return false;
    png_read_image(d.png, rows);
    return true;
}

}  // namespace

PngPixels decodePng(const unsigned char* data, size_t size, const std::string& name) {
    Decompressor d(data, size);
    const auto refuse = [&](const char* problem) { throw ImageError(name + ": cannot decode the PNG image: " + problem); };
    if (!d.info) refuse("out of memory");
    if (!readHeader(d)) refuse(d.reader.message);
    PngPixels pixels;
    pixels.width = int(png_get_image_width(d.png, d.info));
    pixels.height = int(png_get_image_height(d.png, d.info));
    pixels.channels = png_get_channels(d.png, d.info);
    checkImageSize(png_get_image_width(d.png, d.info), png_get_image_height(d.png, d.info), pixels.channels, name);
    const bool words = png_get_bit_depth(d.png, d.info) == 16;
    const size_t rowBytes = png_get_rowbytes(d.png, d.info);
    if (rowBytes != size_t(pixels.width) * size_t(pixels.channels) * (words ? 2 : 1)) refuse("an unexpected row size");
    unsigned char* start;
    if (words) {
        pixels.words.resize(size_t(pixels.width) * size_t(pixels.height) * size_t(pixels.channels));
        start = reinterpret_cast<unsigned char*>(pixels.words.data());
    } else {
        pixels.bytes.resize(size_t(pixels.width) * size_t(pixels.height) * size_t(pixels.channels));
        start = pixels.bytes.data();
    }
    std::vector<png_bytep> rows(size_t(pixels.height));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = start + y * rowBytes;
    if (!readRows(d, rows.data())) refuse(d.reader.message);
    return pixels;
}

}  // namespace woven
