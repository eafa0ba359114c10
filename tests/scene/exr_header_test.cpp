// OpenEXR files that fuzz/fuzz_exr found harmful, made here: headers checked before OpenEXR
// reads them (a 76-byte file whose attribute claimed 1.9 GB took 2.3 GB and 2 s in OpenEXR
// 3.1; a box2i of the wrong size, 1.6 GB), and a line offset of -1 (OpenImageIO's memory reader,
// which woven read through before, copied from before the file's bytes; the asan preset catches
// such a read).
#include "exr_header.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <vector>

#include "frame_io.h"
#include "image_io.h"
#include "temp_dir.h"

namespace woven {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using Bytes = std::vector<unsigned char>;

void put(Bytes& b, const std::string& text) { b.insert(b.end(), text.begin(), text.end() + 1); }  // with its null
void put32(Bytes& b, uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back((unsigned char)(v >> (8 * i)));
}

// Magic, version 2 with `flags`, then one attribute of the given type whose size field says
// `claimed` while `actual` bytes follow.
Bytes exrWithAttribute(uint32_t flags, uint32_t claimed, size_t actual) {
    Bytes b = {0x76, 0x2f, 0x31, 0x01};
    put32(b, 2 | flags);
    put(b, "capDate");
    put(b, "string");
    put32(b, claimed);
    b.insert(b.end(), actual, 'x');
    b.push_back(0);  // end of the header
    return b;
}

std::string refusal(const Bytes& b) {
    try {
        checkExrHeaders(b.data(), b.size(), "sky.exr");
    } catch (const ImageError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(ExrHeader, AnAttributeLargerThanTheFileIsRefusedByName) {
    EXPECT_EQ(refusal(exrWithAttribute(0, 1979711507, 19)),
              "sky.exr: the OpenEXR attribute 'capDate' claims 1979711507 bytes, but the file has 20 left");
    EXPECT_THAT(refusal(exrWithAttribute(0, 0x80000000u, 19)), HasSubstr("claims -2147483648 bytes"));
    EXPECT_EQ(refusal(exrWithAttribute(0, 19, 19)), "(accepted)");
}

// OpenEXR reads a channel list or a preview by its contents and goes on from there: one whose
// contents end elsewhere than its size says would have OpenEXR read the next attribute's size
// from other bytes (the fuzzer's 1.9 GB string). Found by fuzz/fuzz_exr.
Bytes exrWithValue(const std::string& type, const Bytes& value, uint32_t claimed) {
    Bytes b = {0x76, 0x2f, 0x31, 0x01};
    put32(b, 2);
    put(b, "attr");
    put(b, type);
    put32(b, claimed);
    b.insert(b.end(), value.begin(), value.end());
    b.insert(b.end(), 8, 'x');  // room beyond the value, so only the contents can disagree
    b.push_back(0);
    return b;
}

TEST(ExrHeader, ChannelListsAndPreviewsMustEndWhereTheirSizeSays) {
    Bytes channels;
    put(channels, "R");
    channels.insert(channels.end(), 16, 0);
    channels.push_back(0);  // the list's end: 19 bytes in all
    EXPECT_EQ(refusal(exrWithValue("chlist", channels, 19)).find("does not end"), std::string::npos);
    EXPECT_THAT(refusal(exrWithValue("chlist", channels, 23)),
                HasSubstr("'attr' (chlist) does not end where its size of 23 bytes says"));
    Bytes preview;
    put32(preview, 2);
    put32(preview, 1);
    preview.insert(preview.end(), 8, 255);  // 2 x 1 RGBA pixels
    EXPECT_EQ(refusal(exrWithValue("preview", preview, 16)).find("does not end"), std::string::npos);
    Bytes huge;
    put32(huge, 100000);
    put32(huge, 100000);  // 4e10 bytes of pixels claimed in a 16-byte value
    huge.insert(huge.end(), 8, 0);
    EXPECT_THAT(refusal(exrWithValue("preview", huge, 16)), HasSubstr("(preview) does not end"));
}

// OpenEXR reads a fixed-size value as its type's size whatever the attribute says: fuzz/fuzz_exr's
// box2i dataWindow of 40 bytes had it read the next attribute from inside the value and allocate
// 1.6 GB. A string vector's strings must end with the value.
TEST(ExrHeader, FixedSizeValuesMustHaveTheirTypesSize) {
    const Bytes box(16, 0);
    // The 8 bytes exrWithValue puts after the value cut the header short: refusals of 'attr' count.
    EXPECT_THAT(refusal(exrWithValue("box2i", box, 16)), Not(HasSubstr("'attr'")));
    Bytes longer = box;
    longer.resize(40, 0);
    EXPECT_EQ(refusal(exrWithValue("box2i", longer, 40)),
              "sky.exr: the OpenEXR attribute 'attr' (box2i) has a size of 40 bytes, but a box2i has 16");
    EXPECT_THAT(refusal(exrWithValue("compression", Bytes{1, 0}, 2)), HasSubstr("but a compression has 1"));
    EXPECT_THAT(refusal(exrWithValue("someStudioType", longer, 40)), Not(HasSubstr("'attr'")));  // opaque: read by its size
}

TEST(ExrHeader, StringVectorsMustEndWhereTheirSizeSays) {
    Bytes strings;
    put32(strings, 2);
    strings.push_back('a');
    strings.push_back('b');
    EXPECT_THAT(refusal(exrWithValue("stringvector", strings, 6)), Not(HasSubstr("'attr'")));
    Bytes huge;
    put32(huge, 1600000000);  // a string of 1.6 GB claimed in a 6-byte value
    huge.push_back('a');
    huge.push_back('b');
    EXPECT_THAT(refusal(exrWithValue("stringvector", huge, 6)), HasSubstr("(stringvector) does not end"));
}

// OpenEXR allocates a part's line buffers as it opens the file, from its data window and
// channels: fuzz/fuzz_exr's header of 1.2 KB claiming a wide window took 663 MB there. woven's
// image limits are checked on the header first.
TEST(ExrHeader, TheDataWindowMeetsWovensLimitsBeforeOpenExrOpensTheFile) {
    const auto header = [](int32_t xMax, int32_t yMax) {
        Bytes b = {0x76, 0x2f, 0x31, 0x01};
        put32(b, 2);
        put(b, "channels");
        put(b, "chlist");
        put32(b, 19);
        put(b, "R");
        b.insert(b.end(), 16, 0);
        b.push_back(0);
        put(b, "dataWindow");
        put(b, "box2i");
        put32(b, 16);
        for (const int32_t v : {0, 0, xMax, yMax}) put32(b, uint32_t(v));
        b.push_back(0);
        return b;
    };
    const std::vector<ExrPartSize> parts = checkExrHeaders(header(99, 49).data(), header(99, 49).size(), "a.exr");
    ASSERT_EQ(parts.size(), 1u);
    EXPECT_EQ(parts[0].width, 100);
    EXPECT_EQ(parts[0].height, 50);
    EXPECT_EQ(parts[0].channels, 1);
    const test::TempDir dir;
    const std::string path = dir.file("wide.exr");
    const Bytes wide = header(2147483647, 0);  // 2^31 pixels wide
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(wide.data()), std::streamsize(wide.size()));
    try {
        readImage(path);
        ADD_FAILURE() << "accepted";
    } catch (const ImageError& e) {
        EXPECT_THAT(e.what(), HasSubstr(path + ": the image is 2147483648 x 1, more than woven reads"));
    }
}

TEST(ExrHeader, CutShortHeadersAreRefused) {
    Bytes b = exrWithAttribute(0, 4, 4);
    b.pop_back();  // no end of header: the next name never ends
    EXPECT_EQ(refusal(b), "sky.exr: the OpenEXR header is cut short");
    b.resize(20);  // inside the type name
    EXPECT_EQ(refusal(b), "sky.exr: the OpenEXR header is cut short");
    // A multi-part file's headers end with an empty one, which is missing here.
    EXPECT_EQ(refusal(exrWithAttribute(0x1000, 4, 4)), "sky.exr: the OpenEXR header is cut short");
}

TEST(ExrHeader, EveryPartOfAMultiPartFileIsChecked) {
    Bytes b = exrWithAttribute(0x1000, 4, 4);
    put(b, "name");
    put(b, "string");
    put32(b, 1000);
    b.push_back(0);
    EXPECT_THAT(refusal(b), HasSubstr("'name' claims 1000 bytes"));
}

TEST(ExrHeader, ReadExrAndReadImageRefuseTheFileQuickly) {
    const test::TempDir dir;
    const std::string path = dir.file("part.exr");
    const Bytes b = exrWithAttribute(0, 1979711507, 19);
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
    EXPECT_THROW(
        try { readExr(path); } catch (const ImageError& e) {
            EXPECT_THAT(e.what(), HasSubstr(path + ": the OpenEXR attribute 'capDate' claims"));
            throw;
        },
        ImageError);
    EXPECT_THROW(readImage(path), ImageError);
}

TEST(ExrChunks, ANegativeLineOffsetIsRefused) {
    const test::TempDir dir;
    ExrImage exr;
    exr.image.width = 3;
    exr.image.height = 2;
    exr.image.pixels.assign(6, glm::vec3(0.5f));
    writeExr(dir.file("part.exr"), exr);
    std::ifstream in(dir.file("part.exr"), std::ios::binary);
    Bytes b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // One chunk a line (frame files are RLE-compressed), so the offset table is two 64-bit
    // offsets, the first pointing just past the table.
    size_t table = 0;
    for (size_t at = 8; at + 8 <= b.size() && !table; ++at) {
        uint64_t v = 0;
        for (int i = 7; i >= 0; --i) v = v << 8 | b[at + size_t(i)];
        if (v == at + 2 * 8) table = at;
    }
    ASSERT_NE(table, 0u);
    std::fill(b.begin() + long(table), b.begin() + long(table) + 8, 0xff);
    std::ofstream(dir.file("part.exr"), std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
    EXPECT_THROW(readExr(dir.file("part.exr")), ImageError);
}

TEST(ExrHeader, FilesWovenWritesPass) {
    const test::TempDir dir;
    ExrImage exr;
    exr.image.width = 2;
    exr.image.height = 1;
    exr.image.pixels = {{1, 2, 3}, {4, 5, 6}};
    exr.sampleCount = {1, 2};
    writeExr(dir.file("a.exr"), exr, ExrPrecision::Float);
    EXPECT_EQ(readExr(dir.file("a.exr")).sampleCount, exr.sampleCount);
}

}  // namespace
}  // namespace woven
