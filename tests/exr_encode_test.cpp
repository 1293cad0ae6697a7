// The browser build's EXR writer (core/exr_encode.h), read back by OpenImageIO: sizes, channel
// names and every value exact, whatever the channel count or range.
#include "core/exr_encode.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
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

struct ReadBack {
    int width = 0, height = 0;
    std::vector<std::string> names;
    std::vector<float> pixels;
};

// Writes the bytes to a file and reads it with OpenImageIO, an independent reader.
ReadBack writeAndRead(std::vector<std::uint8_t> const& bytes, std::string const& name) {
    fs::path const path = fs::temp_directory_path() / ("gbl_exr_encode_" + name + ".exr");
    {
        std::ofstream file(path, std::ios::binary);
        file.write(reinterpret_cast<char const*>(bytes.data()), std::streamsize(bytes.size()));
    }
    ReadBack r;
    auto in = OIIO::ImageInput::open(path.string());
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return r;
    OIIO::ImageSpec const& spec = in->spec();
    r.width = spec.width;
    r.height = spec.height;
    r.names = spec.channelnames;
    EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(spec.get_string_attribute("compression"), "none");
    r.pixels.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, r.pixels.data())) << in->geterror();
    in->close();
    fs::remove(path);
    return r;
}

void expectChannels(ReadBack const& r, FloatImage const& image, int first, int count) {
    ASSERT_EQ(r.width, image.width);
    ASSERT_EQ(r.height, image.height);
    ASSERT_EQ(r.pixels.size(), std::size_t(image.width) * std::size_t(image.height) * std::size_t(count));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < count; ++c) {
                float const read =
                    r.pixels[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * std::size_t(count) +
                             std::size_t(c)];
                // Bit for bit: float in, float out, nothing rounded.
                ASSERT_EQ(std::bit_cast<std::uint32_t>(read), std::bit_cast<std::uint32_t>(image.at(x, y, first + c)))
                    << "pixel (" << x << ", " << y << ") channel " << c << ": " << read;
            }
}

}  // namespace

TEST(ExrEncode, EveryChannelCountReadsBackExactly) {
    std::vector<std::vector<std::string>> const names = {{"Y"}, {"R", "G"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
    for (int channels = 1; channels <= 4; ++channels) {
        SCOPED_TRACE(channels);
        // Not square and odd-sized: a swapped width and height or a row stride off by one shows.
        FloatImage const image = testImage(7, 5, channels);
        auto const bytes = encodeExr(image);
        ASSERT_TRUE(bytes);
        ReadBack const r = writeAndRead(*bytes, std::to_string(channels));
        EXPECT_EQ(r.names, names[std::size_t(channels - 1)]);  // as OpenImageIO names its own files
        expectChannels(r, image, 0, channels);
    }
}

TEST(ExrEncode, WritesTheChosenChannelRange) {
    FloatImage const image = testImage(3, 4, 4);
    auto const bytes = encodeExr(image, 1, 2);  // G and B of an RGBA image
    ASSERT_TRUE(bytes);
    ReadBack const r = writeAndRead(*bytes, "range");
    EXPECT_EQ(r.names, (std::vector<std::string>{"R", "G"}));
    expectChannels(r, image, 1, 2);
    // Count 0: from `first` to the last channel.
    auto const rest = encodeExr(image, 3);
    ASSERT_TRUE(rest);
    expectChannels(writeAndRead(*rest, "rest"), image, 3, 1);
}

TEST(ExrEncode, FileSizeIsHeaderOffsetsAndRawRows) {
    // Uncompressed: each row is its y, its byte count and width * channels floats, and the
    // offset table has one 8-byte entry per row; only the header's size is not fixed by the image.
    FloatImage const small = testImage(2, 3, 4), large = testImage(10, 3, 4);
    auto const a = encodeExr(small), b = encodeExr(large);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(b->size() - a->size(), std::size_t(3 * (10 - 2) * 4 * 4));
    FloatImage const taller = testImage(2, 5, 4);
    auto const c = encodeExr(taller);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->size() - a->size(), std::size_t(2 * (8 + 8 + 2 * 4 * 4)));
}

TEST(ExrEncode, RefusesWhatItCannotWrite) {
    std::string why;
    EXPECT_FALSE(encodeExr(FloatImage{}, 0, 0, &why));
    EXPECT_EQ(why, "the image is empty");
    FloatImage const image = testImage(2, 2, 3);
    EXPECT_FALSE(encodeExr(image, 2, 2, &why));
    EXPECT_EQ(why, "channel range out of bounds");
    EXPECT_FALSE(encodeExr(image, -1, 1, &why));
    EXPECT_FALSE(encodeExr(image, 3, 0, &why));
    FloatImage shortImage = image;
    shortImage.pixels.pop_back();
    EXPECT_FALSE(encodeExr(shortImage, 0, 0, &why));
    EXPECT_EQ(why, "the image has fewer values than its size needs");
}
