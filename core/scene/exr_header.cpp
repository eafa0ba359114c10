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
    size_t at() const { return at_; }
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

// OpenEXR reads a channel list, a preview and a string vector by their own contents, not by the size the
// attribute claims, and goes on from where that reading stopped: a value whose contents end
// elsewhere than its size says would have OpenEXR read the next attribute from other bytes (the
// fuzzer found a string size read from the middle of a name, 1.9 GB), and a preview allocates
// width x height x 4 bytes, a string vector each string's claimed length. Such values must end
// exactly where their size says.
bool selfDelimited(const std::string& type) { return type == "chlist" || type == "preview" || type == "stringvector"; }

// OpenEXR reads a value of a fixed-size type as that many bytes whatever the attribute's size
// says (the fuzzer's box2i of 40 bytes had OpenEXR read the next attribute from the middle of
// this one's value, and allocate 1.6 GB for it). The sizes of the OpenEXR file layout's
// predefined types.
struct FixedSizeType {
    const char* name;
    int32_t bytes;
};
constexpr FixedSizeType kFixedSizeTypes[] = {
    {"box2i", 16},  {"box2f", 16},   {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
    {"double", 8},  {"envmap", 1},   {"float", 4},           {"int", 4},         {"keycode", 28},
    {"lineOrder", 1}, {"m33f", 36},  {"m33d", 72},           {"m44f", 64},       {"m44d", 128},
    {"rational", 8}, {"tiledesc", 9}, {"timecode", 8},       {"v2i", 8},         {"v2f", 8},
    {"v2d", 16},    {"v3i", 12},     {"v3f", 12},            {"v3d", 24},
};

// The size a value of `type` must have, or -1 for a type whose values vary in size.
int32_t fixedSize(const std::string& type) {
    for (const FixedSizeType& t : kFixedSizeTypes)
        if (type == t.name) return t.bytes;
    return -1;
}

// Where the value starting at `in`'s position ends by its own contents, reading no further than
// `end`; throws (cut short) past it.
size_t contentsEnd(HeaderReader& in, const std::string& type, size_t end) {
    if (type == "preview") {
        const uint64_t width = in.u32(), height = in.u32();
        const uint64_t room = end - in.at();  // bytes left in the value for the RGBA pixels
        if (width != 0 && height > room / 4 / width) return end + 1;  // more pixels than bytes: no product overflows
        return in.at() + size_t(width * height * 4);
    }
    if (type == "stringvector") {
        // Strings of an int32 length and that many bytes, until the value's end; a length past
        // it would be allocated before it is read.
        while (in.at() < end) {
            const uint32_t length = in.u32();
            if (length > end - in.at()) return end + 1;
            in.skip(length);
        }
        return in.at();
    }
    // chlist: entries of a name and 16 bytes (type, pLinear, 3 reserved, x and y sampling), then
    // an empty name.
    while (!in.text().empty()) {
        if (in.at() + 16 > end) in.cutShort();
        in.skip(16);
    }
    return in.at();
}

int32_t readInt32(const unsigned char* p) {
    return int32_t(uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24);
}

// The channels of a channel list already checked by contentsEnd.
int countChannels(const unsigned char* data, size_t start, size_t end) {
    HeaderReader in(data, end, "");
    in.skip(start);
    int channels = 0;
    for (; !in.text().empty(); ++channels) in.skip(16);
    return channels;
}

}  // namespace

std::vector<ExrPartSize> checkExrHeaders(const unsigned char* data, size_t size, const std::string& name) {
    HeaderReader in(data, size, name);
    in.u32();  // the magic number, already recognised
    const bool multiPart = in.u32() & kMultiPartFlag;
    std::vector<ExrPartSize> parts;
    for (;;) {
        ExrPartSize& part = parts.emplace_back();
        // Attributes until an empty name, each: name, type, size (int32), value.
        for (std::string attribute = in.text(); !attribute.empty(); attribute = in.text()) {
            const std::string type = in.text();
            const int32_t bytes = int32_t(in.u32());
            if (bytes < 0 || size_t(bytes) > in.left())
                throw ImageError(name + ": the OpenEXR attribute '" + attribute + "' claims " + std::to_string(bytes) +
                                 " bytes, but the file has " + std::to_string(in.left()) + " left");
            const size_t start = in.at(), end = start + size_t(bytes);
            if (const int32_t fixed = fixedSize(type); fixed >= 0 && bytes != fixed)
                throw ImageError(name + ": the OpenEXR attribute '" + attribute + "' (" + type + ") has a size of " +
                                 std::to_string(bytes) + " bytes, but a " + type + " has " + std::to_string(fixed));
            if (selfDelimited(type)) {
                HeaderReader value(data, end, name);
                value.skip(start);
                if (contentsEnd(value, type, end) != end)
                    throw ImageError(name + ": the OpenEXR attribute '" + attribute + "' (" + type +
                                     ") does not end where its size of " + std::to_string(bytes) + " bytes says");
            }
            if (type == "box2i" && attribute == "dataWindow") {
                const unsigned char* box = data + start;  // xMin, yMin, xMax, yMax
                part.width = int64_t(readInt32(box + 8)) - readInt32(box) + 1;
                part.height = int64_t(readInt32(box + 12)) - readInt32(box + 4) + 1;
            }
            if (type == "chlist" && attribute == "channels") part.channels = countChannels(data, start, end);
            in.skip(size_t(bytes));
        }
        // A multi-part file's headers end with an empty header.
        if (!multiPart) return parts;
        if (in.atEnd()) in.cutShort();
        if (in.peek() == 0) return parts;
    }
}

}  // namespace woven
