#include "exr_header.h"

#include <cstdint>

#include "image_io.h"

namespace woven {

namespace {

constexpr uint32_t kMultiPartFlag = 0x1000;  // version field: more than one header follows

class HeaderReader {
public:
    HeaderReader(const unsigned char* data, size_t size, const std::string& name)
        : data_(data), size_(size), name_(name) {}

    bool atEnd() const { return at_ >= size_; }
    unsigned char peek() const { return data_[at_]; }
    void skip(size_t n) { at_ += n; }
    size_t left() const { return size_ - at_; }

    // A null-terminated string (an attribute's name or type).
    std::string text() {
        const size_t start = at_;
        while (at_ < size_ && data_[at_] != 0) ++at_;
        if (at_ >= size_) cutShort();
        return std::string(reinterpret_cast<const char*>(data_ + start), at_++ - start);
    }

    uint32_t u32() {
        if (left() < 4) cutShort();
        const uint32_t v = uint32_t(data_[at_]) | uint32_t(data_[at_ + 1]) << 8 | uint32_t(data_[at_ + 2]) << 16 |
                           uint32_t(data_[at_ + 3]) << 24;
        at_ += 4;
        return v;
    }

    [[noreturn]] void cutShort() const { throw ImageError(name_ + ": the OpenEXR header is cut short"); }

private:
    const unsigned char* data_;
    size_t size_, at_ = 0;
    const std::string& name_;
};

}  // namespace

void checkExrAttributeSizes(const unsigned char* data, size_t size, const std::string& name) {
    HeaderReader in(data, size, name);
    in.u32();  // the magic number, already recognised
    const bool multiPart = in.u32() & kMultiPartFlag;
    for (;;) {
        // Attributes until an empty name, each: name, type, size (int32), value.
        for (std::string attribute = in.text(); !attribute.empty(); attribute = in.text()) {
            in.text();
            const int32_t bytes = int32_t(in.u32());
            if (bytes < 0 || size_t(bytes) > in.left())
                throw ImageError(name + ": the OpenEXR attribute '" + attribute + "' claims " + std::to_string(bytes) +
                                 " bytes, but the file has " + std::to_string(in.left()) + " left");
            in.skip(size_t(bytes));
        }
        // A multi-part file's headers end with an empty header.
        if (!multiPart) return;
        if (in.atEnd()) in.cutShort();
        if (in.peek() == 0) return;
    }
}

}  // namespace woven
