// Image reading and writing: round trips through real PNG and EXR files, the sRGB transfer
// functions against their published constants, and that failed writes leave no file.
#include "frame_io.h"
#include "image_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "atomic_file.h"
#include "exr_file.h"
#include "temp_dir.h"

namespace woven {
namespace {

using test::TempDir;
namespace fs = std::filesystem;

Image gradient(int width, int height) {
    Image image;
    image.width = width;
    image.height = height;
    image.pixels.resize(size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = {x / float(width - 1), y / float(height - 1), 0.5f * (x + y) / float(width + height)};
    return image;
}

bool onlyFileIs(const TempDir& dir, const std::string& name) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(dir.path())) {
        if (entry.path().filename() != name) return false;
        ++count;
    }
    return count == 1;
}

TEST(Srgb, MatchesTheStandardsBreakpointsAndWhite) {
    // IEC 61966-2-1: the linear segment ends at 0.04045 encoded = 0.0031308 linear.
    EXPECT_NEAR(srgbToLinear(0.04045f), 0.04045f / 12.92f, 1e-7f);
    EXPECT_NEAR(srgbToLinear(1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(srgbToLinear(0.5f), 0.214041f, 1e-5f);  // the widely tabulated mid-grey
    EXPECT_NEAR(linearToSrgb(0.214041f), 0.5f, 1e-5f);
    EXPECT_NEAR(linearToSrgb(0.0031308f), 0.0031308f * 12.92f, 1e-6f);
}

TEST(Png, RoundTripIsWithinHalfAnEightBitStep) {
    TempDir dir;
    const Image original = gradient(37, 21);
    writePng(dir.file("g.png"), original, {0.0f, ToneMap::Clamp});
    const Image back = readImage(dir.file("g.png"), ChannelEncoding::Srgb);
    ASSERT_EQ(back.width, 37);
    ASSERT_EQ(back.height, 21);
    EXPECT_TRUE(onlyFileIs(dir, "g.png"));
    // Quantisation happens in sRGB space: the encoded value is within 0.5/255 of the exact one.
    for (size_t i = 0; i < original.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(linearToSrgb(back.pixels[i][c]), linearToSrgb(original.pixels[i][c]), 0.5f / 255.0f + 1e-5f);
}

TEST(Png, RowZeroIsTheTop) {
    TempDir dir;
    Image image;
    image.width = 2;
    image.height = 2;
    image.pixels = {{1, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 1}};
    writePng(dir.file("rows.png"), image, {0.0f, ToneMap::Clamp});
    const Image back = readImage(dir.file("rows.png"));
    EXPECT_EQ(back.at(0, 0), glm::vec3(1, 0, 0));
    EXPECT_EQ(back.at(1, 1), glm::vec3(0, 0, 1));
}

TEST(Png, ExposureAndToneMapping) {
    TempDir dir;
    Image image;
    image.width = 3;
    image.height = 1;
    image.pixels = {{0.25f, 0.25f, 0.25f}, {1.0f, 1.0f, 1.0f}, {-1.0f, std::nanf(""), 7.0f}};
    writePng(dir.file("e.png"), image, {1.0f, ToneMap::Clamp});
    Image back = readImage(dir.file("e.png"));
    EXPECT_NEAR(back.at(0, 0).r, 0.5f, 0.005f);  // one stop up doubles 0.25
    EXPECT_EQ(back.at(1, 0).r, 1.0f);            // 2.0 clips to white
    EXPECT_EQ(back.at(2, 0), glm::vec3(0.0f, 0.0f, 1.0f));  // negative and NaN are black

    writePng(dir.file("r.png"), image, {0.0f, ToneMap::Reinhard});
    back = readImage(dir.file("r.png"));
    EXPECT_NEAR(back.at(1, 0).r, 0.5f, 0.005f);    // 1 / (1 + 1)
    EXPECT_NEAR(back.at(2, 0).b, 0.875f, 0.006f);  // 7 / 8

    // ACES (Narkowicz): 1 -> 2.54 / 3.16 = 0.8038; 7 -> 0.9993. It is the default.
    writePng(dir.file("a.png"), image);
    back = readImage(dir.file("a.png"));
    EXPECT_NEAR(back.at(1, 0).r, 0.8038f, 0.006f);
    EXPECT_NEAR(back.at(2, 0).b, 0.9993f, 0.006f);
}

TEST(Frame, ExtensionPicksTheFormatAndExrKeepsFloatsAndCounts) {
    TempDir dir;
    ExrImage frame{gradient(5, 3), std::vector<float>(15, 7.0f)};
    frame.image.pixels[4] = glm::vec3(1.0f / 3.0f, 1e-7f, 12345.678f);  // not representable in half
    writeFrame(dir.file("f.EXR"), frame, {});
    const ExrImage back = readExr(dir.file("f.EXR"));
    EXPECT_EQ(back.image.pixels, frame.image.pixels);
    EXPECT_EQ(back.sampleCount, frame.sampleCount);

    writeFrame(dir.file("f.png"), frame, {0.0f, ToneMap::Clamp});
    EXPECT_EQ(readImage(dir.file("f.png")).width, 5);

    try {
        writeFrame(dir.file("f.tiff"), frame, {});
        FAIL() << "a .tiff name was accepted";
    } catch (const ImageError& e) {
        EXPECT_THAT(e.what(), testing::HasSubstr("f.tiff"));
        EXPECT_THAT(e.what(), testing::HasSubstr("expected .exr or .png"));
    }
    EXPECT_FALSE(fs::exists(dir.file("f.tiff")));
}

TEST(Png, LinearEncodingKeepsTheStoredValues) {
    TempDir dir;
    const unsigned char data[3] = {0, 128, 255};
    ASSERT_TRUE(stbi_write_png(dir.file("d.png").c_str(), 1, 1, 3, data, 3));
    const Image linear = readImage(dir.file("d.png"), ChannelEncoding::Linear);
    EXPECT_FLOAT_EQ(linear.at(0, 0).g, 128.0f / 255.0f);
    const Image srgb = readImage(dir.file("d.png"), ChannelEncoding::Srgb);
    EXPECT_NEAR(srgb.at(0, 0).g, 0.2158605f, 1e-5f);  // sRGB 128/255 decoded
}

TEST(Hdr, ReadIsLinear) {
    TempDir dir;
    const float data[6] = {0.5f, 4.0f, 100.0f, 0.0f, 1.0f, 0.25f};
    ASSERT_TRUE(stbi_write_hdr(dir.file("e.hdr").c_str(), 2, 1, 3, data));
    const Image back = readImage(dir.file("e.hdr"));
    ASSERT_EQ(back.width, 2);
    // Radiance RGBE keeps 8 bits of mantissa per channel relative to the largest: 1% is generous
    // for the largest channel; the others are checked against its quantum.
    EXPECT_NEAR(back.at(0, 0).b, 100.0f, 1.0f);
    EXPECT_NEAR(back.at(0, 0).g, 4.0f, 0.5f);
    EXPECT_NEAR(back.at(1, 0).g, 1.0f, 0.01f);
}

TEST(Hdr, AFirstLineOtherThanRadiancesIsRefusedByName) {
    TempDir dir;
    std::ofstream(dir.file("e.hdr")) << "#?RADIANCE but not a line of its own";
    EXPECT_THAT([&] { readImage(dir.file("e.hdr")); },
                testing::ThrowsMessage<ImageError>(testing::HasSubstr(dir.file("e.hdr") + ": cannot decode the Radiance HDR image")));
}

// JPEG is lossy: a flat colour comes back within a few levels, in colour and in grey.
TEST(Jpeg, ColourAndGreyDecodeAndTheirSizeIsCheckedFirst) {
    TempDir dir;
    const std::vector<unsigned char> rgb = [] {
        std::vector<unsigned char> p;
        for (int i = 0; i < 16 * 8; ++i) p.insert(p.end(), {200, 100, 50});
        return p;
    }();
    ASSERT_TRUE(stbi_write_jpg(dir.file("c.jpg").c_str(), 16, 8, 3, rgb.data(), 100));
    const Image colour = readImage(dir.file("c.jpg"), ChannelEncoding::Linear);
    ASSERT_EQ(colour.width, 16);
    ASSERT_EQ(colour.height, 8);
    EXPECT_NEAR(colour.at(5, 3).r, 200 / 255.0f, 3 / 255.0f);
    EXPECT_NEAR(colour.at(5, 3).g, 100 / 255.0f, 3 / 255.0f);
    EXPECT_NEAR(colour.at(5, 3).b, 50 / 255.0f, 3 / 255.0f);
    const std::vector<unsigned char> grey(16 * 8, 128);
    ASSERT_TRUE(stbi_write_jpg(dir.file("g.jpg").c_str(), 16, 8, 1, grey.data(), 100));
    const Image back = readImage(dir.file("g.jpg"), ChannelEncoding::Linear);
    EXPECT_NEAR(back.at(2, 2).r, 128 / 255.0f, 2 / 255.0f);
    EXPECT_EQ(back.at(2, 2).r, back.at(2, 2).b);

    // The same file claiming 60000 x 60000 (its SOF0 segment's height and width) is refused from
    // its header, before libjpeg allocates anything for it.
    std::ifstream in(dir.file("c.jpg"), std::ios::binary);
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const unsigned char sof[2] = {0xff, 0xc0};
    const auto at = std::search(bytes.begin(), bytes.end(), sof, sof + 2);
    ASSERT_NE(at, bytes.end());
    const size_t size = size_t(at - bytes.begin()) + 5;
    for (const size_t i : {size, size + 2}) {
        bytes[i] = 60000 >> 8;
        bytes[i + 1] = 60000 & 255;
    }
    EXPECT_THAT([&] { decodeImage(bytes.data(), bytes.size(), ChannelEncoding::Srgb, "huge.jpg"); },
                testing::ThrowsMessage<ImageError>(testing::HasSubstr("huge.jpg: the image is 60000 x 60000, more than woven reads")));
    const unsigned char corrupt[] = {0xff, 0xd8, 0xff, 0xe0, 0, 2, 0xff, 0xd9};
    EXPECT_THAT([&] { decodeTexture(corrupt, sizeof corrupt, "corrupt.jpg"); },
                testing::ThrowsMessage<ImageError>(testing::HasSubstr("corrupt.jpg: cannot decode the JPEG image")));
}

// OpenEXR images other than frames: Y alone is grey; a texture's alpha is its A channel.
TEST(Exr, GreyAndAlphaChannelsAreReadByName) {
    TempDir dir;
    ExrFile file;
    file.width = 2;
    file.height = 1;
    file.channels = {{"Y", ExrChannelType::Half, {0.25f, 3.0f}, {}}, {"A", ExrChannelType::Float, {0.5f, 1.0f}, {}}};
    writeExrFile(dir.file("y.exr"), file);
    const Image grey = readImage(dir.file("y.exr"));
    EXPECT_EQ(grey.at(1, 0), glm::vec3(3.0f));
    std::ifstream in(dir.file("y.exr"), std::ios::binary);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const TextureImage texture = decodeTexture(bytes.data(), bytes.size(), "y.exr");
    ASSERT_TRUE(texture.isFloat());
    EXPECT_EQ(texture.floats[0], glm::vec4(0.25f, 0.25f, 0.25f, 0.5f));

    file.channels = {{"Z", ExrChannelType::Float, {1.0f, 2.0f}, {}}};
    writeExrFile(dir.file("z.exr"), file);
    EXPECT_THAT([&] { readImage(dir.file("z.exr")); },
                testing::ThrowsMessage<ImageError>(testing::HasSubstr("z.exr: no R, G, B (or Y) channels")));
}

TEST(Exr, FloatRoundTripIsExactAndKeepsTheSampleCount) {
    TempDir dir;
    ExrImage exr;
    exr.image = gradient(13, 7);
    exr.image.at(3, 2) = {1e-8f, 12345.678f, 3.14159265f};
    for (size_t i = 0; i < exr.image.pixels.size(); ++i) exr.sampleCount.push_back(float(16 + 3 * i));
    writeExr(dir.file("f.exr"), exr, ExrPrecision::Float);
    EXPECT_TRUE(onlyFileIs(dir, "f.exr"));
    const ExrImage back = readExr(dir.file("f.exr"));
    ASSERT_EQ(back.image.width, 13);
    ASSERT_EQ(back.image.height, 7);
    EXPECT_EQ(back.image.pixels, exr.image.pixels);
    EXPECT_EQ(back.sampleCount, exr.sampleCount);
}

TEST(Exr, KeepsExactSampleSumsAndTheSampleRange) {
    TempDir dir;
    ExrImage exr;
    exr.image = gradient(6, 4);
    exr.sampleCount.assign(24, 5.0f);
    for (size_t i = 0; i < 3 * 24; ++i) {
        ExactSum sum;
        sum.add(float(i) * 0.37f - 3.0f);
        sum.add(1e-9f * float(i));
        exr.sampleSums.push_back(sum);
    }
    exr.samples = SampleRange{32, 5};
    writeExr(dir.file("s.exr"), exr, ExrPrecision::Float);
    const ExrImage back = readExr(dir.file("s.exr"));
    EXPECT_EQ(back.image.pixels, exr.image.pixels);
    EXPECT_EQ(back.sampleCount, exr.sampleCount);
    EXPECT_EQ(back.sampleSums, exr.sampleSums);
    ASSERT_TRUE(back.samples);
    EXPECT_EQ(back.samples->first, 32);
    EXPECT_EQ(back.samples->count, 5);

    // Without them, a file reads back without them.
    exr.sampleSums.clear();
    exr.samples.reset();
    writeExr(dir.file("plain.exr"), exr, ExrPrecision::Float);
    const ExrImage plain = readExr(dir.file("plain.exr"));
    EXPECT_TRUE(plain.sampleSums.empty());
    EXPECT_FALSE(plain.samples);
}

TEST(Exr, KeepsSampleRangesPast32BitsAndTheFrameIdentity) {
    TempDir dir;
    ExrImage exr;
    exr.image = gradient(3, 2);
    exr.sampleCount.assign(6, 3.0f);
    exr.sampleSums.assign(18, ExactSum());
    exr.frame = FrameIdentity{"0123456789abcdef", 0xfedcba9876543210ull, "auto: bdpt", 5, true, "independent"};
    for (const SampleRange range : {SampleRange{2147483647, 3}, SampleRange{4294967295, 1},
                                    SampleRange{kSampleIndexLimit - 7, 7}}) {
        exr.samples = range;
        writeExr(dir.file("p.exr"), exr, ExrPrecision::Float);
        const ExrImage back = readExr(dir.file("p.exr"));
        ASSERT_TRUE(back.samples);
        EXPECT_EQ(back.samples->first, range.first);
        EXPECT_EQ(back.samples->count, range.count);
        ASSERT_TRUE(back.frame);
        EXPECT_EQ(back.frame->scene, "0123456789abcdef");
        EXPECT_EQ(back.frame->seed, 0xfedcba9876543210ull);
        EXPECT_EQ(back.frame->integrator, "auto: bdpt");
        EXPECT_EQ(back.frame->maxDepth, 5);
        EXPECT_TRUE(back.frame->filterWeave);
        EXPECT_EQ(back.frame->sampler, "independent");
    }

    // A range past 2^62, which woven never writes, is refused by name.
    exr.samples = SampleRange{kSampleIndexLimit, 1};
    writeExr(dir.file("far.exr"), exr, ExrPrecision::Float);
    EXPECT_THAT([&] { readExr(dir.file("far.exr")); },
                testing::ThrowsMessage<ImageError>(testing::HasSubstr("not within samples 0 to 2^62")));
}

// Parts written before sample ranges were 64-bit and parts recorded their frame: int attributes,
// no identity. They read as they did.
TEST(Exr, ReadsTheIntSampleRangeOfEarlierParts) {
    TempDir dir;
    const std::string path = dir.file("old.exr");
    ExrFile file;
    file.width = 2;
    file.height = 1;
    file.channels = {{"R", ExrChannelType::Float, {0.1f, 0.4f}, {}},
                     {"G", ExrChannelType::Float, {0.2f, 0.5f}, {}},
                     {"B", ExrChannelType::Float, {0.3f, 0.6f}, {}}};
    file.attributes = {{"wovenFirstSample", 2147483646}, {"wovenSampleCount", 1}};
    writeExrFile(path, file);
    const ExrImage old = readExr(path);
    ASSERT_TRUE(old.samples);
    EXPECT_EQ(old.samples->first, 2147483646);
    EXPECT_EQ(old.samples->count, 1);
    EXPECT_FALSE(old.frame);

    // Some of the identity's attributes without the rest: not a file woven wrote.
    file.attributes["wovenSeed"] = std::string("7");
    writeExrFile(path, file);
    EXPECT_THAT([&] { readExr(path); },
                testing::ThrowsMessage<ImageError>(testing::HasSubstr("has only some of the attributes wovenScene")));
}

TEST(Exr, HalfRoundTripIsWithinHalfPrecision) {
    TempDir dir;
    ExrImage exr;
    exr.image = gradient(9, 5);
    writeExr(dir.file("h.exr"), exr, ExrPrecision::Half);
    const ExrImage back = readExr(dir.file("h.exr"));
    EXPECT_TRUE(back.sampleCount.empty());
    // Half has an 11-bit significand: relative error at most 2^-11 after rounding.
    for (size_t i = 0; i < exr.image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(back.image.pixels[i][c], exr.image.pixels[i][c], exr.image.pixels[i][c] * 0.00049f + 1e-7f);
    // readImage dispatches on the content, not the extension.
    fs::rename(dir.file("h.exr"), dir.file("h.png"));
    EXPECT_EQ(readImage(dir.file("h.png")).pixels, back.image.pixels);
}

TEST(ImageErrors, MissingAndCorruptFilesNameTheFile) {
    TempDir dir;
    const std::string missing = dir.file("nothere.png");
    try {
        readImage(missing);
        FAIL() << "no error for a missing file";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
    const std::string corrupt = dir.file("corrupt.png");
    std::ofstream(corrupt) << "\x89PNG\r\n\x1a\n this is not really a png";
    try {
        readImage(corrupt);
        FAIL() << "no error for a corrupt file";
    } catch (const ImageError& e) {
        EXPECT_NE(std::string(e.what()).find(corrupt), std::string::npos) << e.what();
    }
    std::ofstream(dir.file("corrupt.exr")) << "v/1\x01 and then garbage";
    EXPECT_THROW(readExr(dir.file("corrupt.exr")), ImageError);
}

TEST(AtomicWrite, FailureLeavesNoFileAndKeepsTheOldOne) {
    TempDir dir;
    const std::string path = dir.file("out.png");
    Image good = gradient(4, 4);
    writePng(path, good);
    const auto sizeBefore = fs::file_size(path);
    // A writer that fails after writing part of its output.
    try {
        writeFileAtomically(path, [](const std::string& tmp) {
            std::ofstream(tmp) << "half";
            throw std::runtime_error("disk full");
        });
        FAIL() << "no error";
    } catch (const FileWriteError& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("disk full"), std::string::npos);
    }
    EXPECT_TRUE(onlyFileIs(dir, "out.png"));
    EXPECT_EQ(fs::file_size(path), sizeBefore);
}

TEST(AtomicWrite, UnwritableDirectoryLeavesNothing) {
    TempDir dir;
    const std::string path = dir.file("no/such/dir/out.exr");
    ExrImage exr;
    exr.image = gradient(4, 4);
    EXPECT_THROW(writeExr(path, exr), FileWriteError);
    EXPECT_THROW(writePng(dir.file("no/such/dir/out.png"), exr.image), FileWriteError);
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(AtomicWrite, InconsistentImageIsRefusedBeforeWriting) {
    TempDir dir;
    Image bad;
    bad.width = 4;
    bad.height = 4;
    bad.pixels.resize(3);
    EXPECT_THROW(writePng(dir.file("bad.png"), bad), ImageError);
    EXPECT_TRUE(fs::is_empty(dir.path()));
}

}  // namespace
}  // namespace woven
