// The browser build's image files (renderer/image/image_io_stb.cpp: stb_image, stb_image_write and
// tinyexr over zlib), compiled natively and checked against OpenImageIO, an independent reader and
// writer: EXR written here reads back in OpenImageIO bit for bit, and ZIP-compressed EXR, half EXR and
// PNG that OpenImageIO wrote (as a natively exported G-buffer folder holds) read back here exactly.
#include "image/image_io.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace gbl;
namespace fs = std::filesystem;

namespace {

// Values no two pixels or channels share, including ones an encoder could lose: negative, tiny
// (denormal), huge, infinite.
FloatImage testImage(int width, int height, int channels) {
    FloatImage image{width, height, channels, {}};
    for (int i = 0; i < width * height * channels; ++i) image.pixels.push_back(float(i) * 0.37f - 5.0f);
    image.pixels[1] = std::numeric_limits<float>::denorm_min();
    image.pixels[2] = -std::numeric_limits<float>::infinity();
    image.pixels[image.pixels.size() - 1] = 3.0e38f;
    return image;
}

std::string tempPath(std::string const& name) {
    return (fs::temp_directory_path() / ("gbl_image_io_stb_" + name)).string();
}

struct ReadBack {
    int width = 0, height = 0;
    std::vector<std::string> names;
    std::string compression;
    std::vector<float> pixels;
};

// Reads a file with OpenImageIO.
ReadBack readWithOiio(std::string const& path) {
    ReadBack r;
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return r;
    OIIO::ImageSpec const& spec = in->spec();
    r.width = spec.width;
    r.height = spec.height;
    r.names = spec.channelnames;
    r.compression = spec.get_string_attribute("compression");
    EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT);
    r.pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, r.pixels.data())) << in->geterror();
    in->close();
    return r;
}

// Writes `values` (width x height x names.size(), interleaved) with OpenImageIO in `format`.
void writeWithOiio(std::string const& path, int width, int height, std::vector<std::string> const& names,
                   std::vector<float> const& values, OIIO::TypeDesc format, char const* compression = nullptr) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(width, height, int(names.size()), format);
    spec.channelnames = names;
    if (compression) spec.attribute("compression", compression);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, values.data())) << out->geterror();
    out->close();
}

void expectBits(float read, float expected, std::string const& where) {
    // Bit for bit: float in, float out, nothing rounded.
    ASSERT_EQ(std::bit_cast<std::uint32_t>(read), std::bit_cast<std::uint32_t>(expected)) << where << ": " << read;
}

void expectChannels(std::vector<float> const& pixels, FloatImage const& image, int first, int count) {
    ASSERT_EQ(pixels.size(), std::size_t(image.width) * std::size_t(image.height) * std::size_t(count));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < count; ++c)
                expectBits(pixels[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * std::size_t(count) +
                                  std::size_t(c)],
                           image.at(x, y, first + c),
                           "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " + std::to_string(c));
}

}  // namespace

// ---- writing: read back by OpenImageIO ----------------------------------------------------------

TEST(ImageIoStb, ExrOfEveryChannelCountReadsBackExactlyInOpenImageIo) {
    std::vector<std::vector<std::string>> const names = {{"Y"}, {"R", "G"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
    for (int channels = 1; channels <= 4; ++channels) {
        SCOPED_TRACE(channels);
        // Not square and odd-sized: a swapped width and height or a row stride off by one shows.
        FloatImage const image = testImage(7, 5, channels);
        std::string const path = tempPath(std::to_string(channels) + ".exr");
        ASSERT_EQ(writeExr(path, image), std::nullopt);
        ReadBack const r = readWithOiio(path);
        EXPECT_EQ(r.names, names[std::size_t(channels - 1)]);  // as OpenImageIO names its own files
        EXPECT_EQ(r.compression, "zip");                       // as OpenImageIO writes its own
        ASSERT_EQ(r.width, 7);
        ASSERT_EQ(r.height, 5);
        expectChannels(r.pixels, image, 0, channels);
        fs::remove(path);
    }
}

TEST(ImageIoStb, ExrHoldsTheChosenChannelRange) {
    FloatImage const image = testImage(3, 4, 4);
    std::string const path = tempPath("range.exr");
    ASSERT_EQ(writeExr(path, image, 1, 2), std::nullopt);  // G and B of an RGBA image
    ReadBack const r = readWithOiio(path);
    EXPECT_EQ(r.names, (std::vector<std::string>{"R", "G"}));
    expectChannels(r.pixels, image, 1, 2);
    // Count 0: from `first` to the last channel.
    ASSERT_EQ(writeExr(path, image, 3), std::nullopt);
    expectChannels(readWithOiio(path).pixels, image, 3, 1);
    fs::remove(path);
}

TEST(ImageIoStb, RefusesWhatItCannotWrite) {
    std::string const path = tempPath("refused.exr");
    EXPECT_EQ(writeExr(path, FloatImage{}), "cannot write " + path + ": the image is empty");
    FloatImage const image = testImage(2, 2, 3);
    EXPECT_EQ(writeExr(path, image, 2, 2), "cannot write " + path + ": channel range out of bounds");
    EXPECT_EQ(writeExr(path, image, -1, 1), "cannot write " + path + ": channel range out of bounds");
    EXPECT_EQ(writeExr(path, image, 3, 0), "cannot write " + path + ": channel range out of bounds");
    FloatImage shortImage = image;
    shortImage.pixels.pop_back();
    EXPECT_EQ(writeExr(path, shortImage), "cannot write " + path + ": the image has fewer values than its size needs");
    EXPECT_EQ(writePng(path, FloatImage{}), "cannot write " + path + ": the image is empty");
    EXPECT_FALSE(fs::exists(path));
    std::string const noFolder = tempPath("no_such_folder") + "/x.exr";
    std::optional<std::string> const why = writeExr(noFolder, image);
    ASSERT_TRUE(why);
    EXPECT_TRUE(why->starts_with("cannot write " + noFolder + ": ")) << *why;
}

TEST(ImageIoStb, PngRoundsAsOpenImageIoDoes) {
    // RGB: OpenImageIO would premultiply a grey+alpha PNG on reading.
    FloatImage const image{2, 1, 3, {0.0f, 1.0f, 0.5f, -2.0f, 0.2f, 7.0f}};
    std::string const path = tempPath("round.png");
    ASSERT_EQ(writePng(path, image), std::nullopt);
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in) << OIIO::geterror();
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
    std::vector<std::uint8_t> bytes(6);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data()));
    // Clamped to [0, 1], then the nearest of 255 steps: 0.5 -> 127.5 rounds up, 0.2 -> 51.
    EXPECT_EQ(bytes, (std::vector<std::uint8_t>{0, 255, 128, 0, 51, 255}));
    in->close();
    fs::remove(path);
}

// ---- reading: files OpenImageIO wrote -----------------------------------------------------------

TEST(ImageIoStb, ReadsZipCompressedFloatExrExactly) {
    for (int channels : {1, 3, 4}) {
        SCOPED_TRACE(channels);
        FloatImage const image = testImage(9, 21, channels);  // 21 rows: ZIP's 16-row blocks and a partial one
        std::vector<std::string> const names = channels == 1   ? std::vector<std::string>{"Y"}
                                               : channels == 3 ? std::vector<std::string>{"R", "G", "B"}
                                                               : std::vector<std::string>{"R", "G", "B", "A"};
        std::string const path = tempPath("zip" + std::to_string(channels) + ".exr");
        writeWithOiio(path, image.width, image.height, names, image.pixels, OIIO::TypeDesc::FLOAT, "zip");
        ASSERT_EQ(readWithOiio(path).compression, "zip");
        DecodedPixels const read = readImageFile(path, 1 << 20);
        ASSERT_TRUE(read.ok()) << read.error;
        EXPECT_EQ(read.width, 9);
        EXPECT_EQ(read.height, 21);
        EXPECT_EQ(read.channels, channels);
        EXPECT_EQ(read.storage, SampleStorage::Float);
        // R, G, B, A in that order, though the file lists them A, B, G, R.
        expectChannels(read.floats, image, 0, channels);
        fs::remove(path);
    }
}

TEST(ImageIoStb, ReadsHalfExrAndOtherCompressions) {
    // Values a half holds exactly, so the conversion back to float is exact too.
    std::vector<float> const values = {0.0f, 1.0f, -2.5f, 0.125f, 1024.0f, 65504.0f};
    for (char const* compression : {"zip", "zips", "rle", "none", "piz"}) {
        SCOPED_TRACE(compression);
        std::string const path = tempPath(std::string("half_") + compression + ".exr");
        writeWithOiio(path, 3, 2, {"Y"}, values, OIIO::TypeDesc::HALF, compression);
        DecodedPixels const read = readImageFile(path, 1 << 20);
        ASSERT_TRUE(read.ok()) << read.error;
        EXPECT_EQ(read.storage, SampleStorage::Half);
        ASSERT_EQ(read.channels, 1);
        EXPECT_EQ(read.floats, values);
        fs::remove(path);
    }
}

TEST(ImageIoStb, KeepsOtherChannelsAfterRgbaInFileOrder) {
    // A depth channel beside colour, as a renderer's EXR may hold: R, G, B first, then Z.
    std::vector<float> const values = {0.25f, 0.5f, 0.75f, 9.0f, 1.0f, 2.0f, 3.0f, 4.0f};
    std::string const path = tempPath("rgbz.exr");
    writeWithOiio(path, 2, 1, {"R", "G", "B", "Z"}, values, OIIO::TypeDesc::FLOAT, "zip");
    DecodedPixels const read = readImageFile(path, 1 << 20);
    ASSERT_TRUE(read.ok()) << read.error;
    ASSERT_EQ(read.channels, 4);
    EXPECT_EQ(read.floats, values);
    fs::remove(path);
}

TEST(ImageIoStb, ReadsPngOf8And16Bits) {
    std::vector<float> const values = {0.0f, 1.0f, 0.2f, 0.6f};
    std::string const path8 = tempPath("grey8.png"), path16 = tempPath("grey16.png");
    writeWithOiio(path8, 2, 2, {"Y"}, values, OIIO::TypeDesc::UINT8);
    writeWithOiio(path16, 2, 2, {"Y"}, values, OIIO::TypeDesc::UINT16);
    DecodedPixels const a = readImageFile(path8, 1 << 20), b = readImageFile(path16, 1 << 20);
    ASSERT_TRUE(a.ok() && b.ok()) << a.error << b.error;
    EXPECT_EQ(a.storage, SampleStorage::Uint8);
    EXPECT_EQ(b.storage, SampleStorage::Uint16);
    ASSERT_EQ(a.floats.size(), 4u);
    ASSERT_EQ(b.floats.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        // One 8-bit step (1/255) and one 16-bit step (1/65535) are what the files can hold.
        EXPECT_NEAR(a.floats[i], values[i], 0.5 / 255.0) << i;
        EXPECT_NEAR(b.floats[i], values[i], 0.5 / 65535.0) << i;
    }
    fs::remove(path8);
    fs::remove(path16);
}

TEST(ImageIoStb, RefusesMissingCorruptAndOversizedFiles) {
    DecodedPixels const missing = readImageFile(tempPath("nowhere.exr"), 1 << 20);
    EXPECT_TRUE(missing.missing);
    EXPECT_EQ(missing.error, "no such file, or no permission");

    std::string const path = tempPath("big.exr");
    writeWithOiio(path, 40, 30, {"Y"}, std::vector<float>(1200, 1.0f), OIIO::TypeDesc::FLOAT, "zip");
    DecodedPixels const big = readImageFile(path, 1000);
    EXPECT_TRUE(big.overLimit);
    EXPECT_EQ(big.width, 40);
    EXPECT_EQ(big.height, 30);
    EXPECT_TRUE(big.floats.empty());

    // The same file cut short: the header reads, the pixels do not.
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size() / 2));
    DecodedPixels const cut = readImageFile(path, 1 << 20);
    EXPECT_FALSE(cut.ok());
    EXPECT_FALSE(cut.missing);
    EXPECT_TRUE(cut.floats.empty());

    std::ofstream(path, std::ios::binary | std::ios::trunc) << "not an image";
    DecodedPixels const text = readImageFile(path, 1 << 20);
    EXPECT_FALSE(text.ok());
    EXPECT_FALSE(text.missing);
    std::string error;
    EXPECT_FALSE(readImage(path, &error));
    EXPECT_TRUE(error.starts_with("cannot read " + path + ": ")) << error;
    fs::remove(path);
}

TEST(ImageIoStb, DecodesPngFromMemoryAs8Bits) {
    FloatImage const image{2, 1, 4, {1.0f, 0.0f, 0.2f, 0.4f, 0.0f, 1.0f, 0.6f, 0.0f}};
    std::string const path = tempPath("mem.png");
    ASSERT_EQ(writePng(path, image), std::nullopt);
    std::ifstream in(path, std::ios::binary);
    std::vector<std::uint8_t> const bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    DecodedPixels const d = decodeImage8(bytes, "image/png", 1 << 20);
    ASSERT_TRUE(d.ok()) << d.error;
    EXPECT_EQ(d.channels, 4);
    // Straight alpha: the colour of the transparent pixel is kept, as glTF requires.
    EXPECT_EQ(d.bytes, (std::vector<std::uint8_t>{255, 0, 51, 102, 0, 255, 153, 0}));
    EXPECT_TRUE(decodeImage8(bytes, "image/png", 1).overLimit);
    EXPECT_FALSE(decodeImage8(std::span(bytes).first(20), "image/png", 1 << 20).ok());
    EXPECT_EQ(decodeImage8({}, "image/png", 1 << 20).error, "the image data is empty");
    fs::remove(path);
}
