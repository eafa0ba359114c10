#include "exr_file.h"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfPartType.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cstring>
#include <thread>

#include "atomic_file.h"
#include "exr_header.h"
#include "image_checks.h"
#include "image_io.h"

namespace woven {

namespace {

[[noreturn]] void fail(const std::string& name, const std::string& problem) {
    throw ImageError(name + ": " + problem);
}

// OpenEXR compresses and decompresses lines on its own thread pool, every hardware thread as
// OpenImageIO, which woven read EXR files through before, had it.
int exrThreads() {
    static const int threads = [] {
        const int n = int(std::max(1u, std::thread::hardware_concurrency()));
        Imf::setGlobalThreadCount(n);
        return n;
    }();
    return threads;
}

// The bytes of a file already read (within kMaxImageFileBytes), as OpenEXR reads a file. A read
// or seek outside them is OpenEXR's error, never a read outside the buffer.
class MemoryStream : public Imf::IStream {
public:
    MemoryStream(const unsigned char* data, size_t size, const std::string& name)
        : Imf::IStream(name.c_str()), data_(data), size_(size) {}
    bool read(char c[], int n) override {
        if (n < 0 || uint64_t(n) > size_ - position_) throw Iex::InputExc("the file ends early");
        std::memcpy(c, data_ + position_, size_t(n));
        position_ += uint64_t(n);
        return position_ < size_;
    }
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override {
        if (position > size_) throw Iex::InputExc("an offset past the file's end");
        position_ = position;
    }

private:
    const unsigned char* data_;
    uint64_t size_;
    uint64_t position_ = 0;
};

Imf::PixelType pixelType(ExrChannelType type) {
    switch (type) {
        case ExrChannelType::Half: return Imf::HALF;
        case ExrChannelType::Float: return Imf::FLOAT;
        case ExrChannelType::Uint: return Imf::UINT;
    }
    return Imf::FLOAT;
}

ExrAttribute attributeValue(const Imf::Attribute& attribute) {
    if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&attribute)) return i->value();
    if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&attribute)) return s->value();
    return ExrOtherAttribute{attribute.typeName()};
}

ExrFile readPixels(Imf::InputFile& input, const std::string& name) {
    const Imf::Header& header = input.header();
    if (header.hasType() && Imf::isDeepData(header.type())) fail(name, "deep OpenEXR images are not supported");
    const Imath::Box2i window = header.dataWindow();
    const int64_t width = int64_t(window.max.x) - window.min.x + 1, height = int64_t(window.max.y) - window.min.y + 1;
    int channels = 0;
    for (auto c = header.channels().begin(); c != header.channels().end(); ++c) ++channels;
    checkImageSize(width, height, channels, name);

    ExrFile file;
    file.width = int(width);
    file.height = int(height);
    const size_t count = size_t(width) * size_t(height);
    file.channels.reserve(size_t(channels));
    Imf::FrameBuffer frame;
    for (auto c = header.channels().begin(); c != header.channels().end(); ++c) {
        if (c.channel().xSampling != 1 || c.channel().ySampling != 1)
            fail(name, std::string("the channel ") + c.name() + " is subsampled, which woven does not read");
        ExrChannel& channel = file.channels.emplace_back();
        channel.name = c.name();
        if (c.channel().type == Imf::UINT) {
            channel.type = ExrChannelType::Uint;
            channel.words.resize(count);
            frame.insert(c.name(), Imf::Slice::Make(Imf::UINT, channel.words.data(), window));
        } else {
            // OpenEXR turns halves into floats as it reads them.
            channel.type = c.channel().type == Imf::HALF ? ExrChannelType::Half : ExrChannelType::Float;
            channel.values.resize(count);
            frame.insert(c.name(), Imf::Slice::Make(Imf::FLOAT, channel.values.data(), window));
        }
    }
    input.setFrameBuffer(frame);
    input.readPixels(window.min.y, window.max.y);
    for (auto a = header.begin(); a != header.end(); ++a) file.attributes.emplace(a.name(), attributeValue(a.attribute()));
    return file;
}

}  // namespace

const ExrChannel* ExrFile::channel(const std::string& name) const {
    for (const ExrChannel& c : channels)
        if (c.name == name) return &c;
    return nullptr;
}

ExrFile readExrFile(const unsigned char* data, size_t size, const std::string& name) {
    if (detectImageFormat(data, size, name) != ImageFormat::Exr) fail(name, "not an OpenEXR file");
    // OpenEXR allocates what the headers claim, and a part's line buffers, as it opens the file:
    // the limits come first.
    for (const ExrPartSize& part : checkExrHeaders(data, size, name))
        if (part.channels > 0) checkImageSize(part.width, part.height, part.channels, name);
    try {
        MemoryStream stream(data, size, name);
        Imf::InputFile input(stream, exrThreads());
        return readPixels(input, name);
    } catch (const ImageError&) {
        throw;
    } catch (const std::exception& e) {
        fail(name, std::string("cannot decode the OpenEXR image: ") + e.what());
    }
}

void writeExrFile(const std::string& path, const ExrFile& file) {
    const size_t count = size_t(std::max(file.width, 0)) * size_t(std::max(file.height, 0));
    if (count == 0) fail(path, "cannot write an empty image");
    Imf::Header header(file.width, file.height);
    // RLE: of a 640x480 frame's 95 channels, ZIP took 4.2 s to write on the 2-core VM for 38 MB,
    // RLE 0.7 s for 50 MB (PIZ 2.1 s, 50 MB): the render, not the file, should take the time.
    header.compression() = Imf::RLE_COMPRESSION;
    for (const auto& [name, value] : file.attributes) {
        if (const int* i = std::get_if<int>(&value)) header.insert(name, Imf::IntAttribute(*i));
        else if (const std::string* s = std::get_if<std::string>(&value)) header.insert(name, Imf::StringAttribute(*s));
        else fail(path, "cannot write the attribute " + name + " (woven writes ints and strings)");
    }
    // Halves rounded here, as Imath rounds a float to the nearest half; floats and words as they are.
    std::vector<std::vector<half>> halves;
    halves.reserve(file.channels.size());
    Imf::FrameBuffer frame;
    const Imath::Box2i window = header.dataWindow();
    for (const ExrChannel& c : file.channels) {
        const bool words = c.type == ExrChannelType::Uint;
        if ((words ? c.words.size() : c.values.size()) != count)
            fail(path, "the channel " + c.name + " does not match the image size");
        header.channels().insert(c.name, Imf::Channel(pixelType(c.type)));
        if (c.type == ExrChannelType::Half) {
            std::vector<half>& h = halves.emplace_back(c.values.begin(), c.values.end());
            frame.insert(c.name, Imf::Slice::Make(Imf::HALF, h.data(), window));
        } else if (words) {
            frame.insert(c.name, Imf::Slice::Make(Imf::UINT, c.words.data(), window));
        } else {
            frame.insert(c.name, Imf::Slice::Make(Imf::FLOAT, c.values.data(), window));
        }
    }
    writeFileAtomically(path, [&](const std::string& tmp) {
        try {
            Imf::OutputFile out(tmp.c_str(), header, exrThreads());
            out.setFrameBuffer(frame);
            out.writePixels(file.height);
        } catch (const std::exception& e) {
            throw ImageError(std::string("cannot write the OpenEXR data: ") + e.what());
        }
    });
}

}  // namespace woven
