#include "jpeg_decoding.h"

// jpeglib.h needs FILE and size_t declared first.
#include <cstdio>
#include <csetjmp>
#include <jpeglib.h>

#include <cmath>

#include "image_checks.h"
#include "image_io.h"

namespace woven {

namespace {

// libjpeg's errors return here by longjmp (its C frames cannot be unwound by an exception), with
// its message; its warnings (a corrupt but readable file) are not printed.
struct ErrorManager {
    jpeg_error_mgr base;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void onError(j_common_ptr info) {
    auto* errors = reinterpret_cast<ErrorManager*>(info->err);
    (*info->err->format_message)(info, errors->message);
    std::longjmp(errors->jump, 1);
}

void onMessage(j_common_ptr) {}

// Adobe's CMYK JPEGs store 1 - x: the product of a channel and K is the RGB value, as OpenImageIO
// converted them.
void cmykToRgb(JpegPixels& pixels) {
    const size_t count = size_t(pixels.width) * size_t(pixels.height);
    for (size_t i = 0; i < count; ++i) {
        const unsigned char* cmyk = &pixels.bytes[4 * i];
        for (int c = 0; c < 3; ++c)
            pixels.bytes[3 * i + size_t(c)] = (unsigned char)std::lround(cmyk[c] / 255.0f * (cmyk[3] / 255.0f) * 255.0f);
    }
    pixels.channels = 3;
    pixels.bytes.resize(3 * count);
}

// libjpeg's state. The functions that call setjmp hold no C++ object that a longjmp could leave
// indeterminate: the pixels are the caller's.
struct Decompressor {
    jpeg_decompress_struct info{};
    ErrorManager errors{};
    bool cmyk = false;

    Decompressor() {
        info.err = jpeg_std_error(&errors.base);
        errors.base.error_exit = onError;
        errors.base.output_message = onMessage;
        jpeg_create_decompress(&info);
    }
    ~Decompressor() { jpeg_destroy_decompress(&info); }
    Decompressor(const Decompressor&) = delete;
    Decompressor& operator=(const Decompressor&) = delete;
};

// The header, and what woven asks of the decoder: grey, RGB, or CMYK to convert.
bool readHeader(Decompressor& d, const unsigned char* data, size_t size) {
    if (setjmp(d.errors.jump)) return false;
    jpeg_mem_src(&d.info, data, (unsigned long)size);
    jpeg_read_header(&d.info, TRUE);
    d.cmyk = d.info.jpeg_color_space == JCS_CMYK || d.info.jpeg_color_space == JCS_YCCK;
    d.info.out_color_space = d.cmyk ? JCS_CMYK : d.info.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_calc_output_dimensions(&d.info);
    return true;
}

bool readLines(Decompressor& d, unsigned char* out, size_t stride) {
    if (setjmp(d.errors.jump)) return false;
    jpeg_start_decompress(&d.info);
    while (d.info.output_scanline < d.info.output_height) {
        JSAMPROW row = out + d.info.output_scanline * stride;
        jpeg_read_scanlines(&d.info, &row, 1);
    }
    jpeg_finish_decompress(&d.info);
    return true;
}

}  // namespace

JpegPixels decodeJpeg(const unsigned char* data, size_t size, const std::string& name) {
    Decompressor d;
    const auto refuse = [&] { throw ImageError(name + ": cannot decode the JPEG image: " + d.errors.message); };
    if (!readHeader(d, data, size)) refuse();
    checkImageSize(d.info.output_width, d.info.output_height, d.info.out_color_components, name);
    JpegPixels pixels;
    pixels.width = int(d.info.output_width);
    pixels.height = int(d.info.output_height);
    pixels.channels = d.info.out_color_components;
    const size_t stride = size_t(pixels.width) * size_t(pixels.channels);
    pixels.bytes.resize(stride * size_t(pixels.height));
    if (!readLines(d, pixels.bytes.data(), stride)) refuse();
    if (d.cmyk) cmykToRgb(pixels);
    return pixels;
}

}  // namespace woven
