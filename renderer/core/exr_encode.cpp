// OpenEXR's file layout (openexr.com, "OpenEXR File Layout"): magic and version, the header's
// attributes (name, type, size, value; ended by an empty name), one offset per scanline block,
// then the blocks. Uncompressed, a block is one scanline: its y, its byte count, and each
// channel's row of values in turn, channels in the header's (alphabetical) order. Little endian.
#include "core/exr_encode.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace gbl {

namespace {

class Bytes {
public:
    std::vector<std::uint8_t> out;

    void u8(std::uint8_t v) { out.push_back(v); }
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
    }
    void i32(std::int32_t v) { u32(std::uint32_t(v)); }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) out.push_back(std::uint8_t(v >> (8 * i)));
    }
    void f32(float v) {
        std::uint32_t bits = 0;  // std::bit_cast: not in Emscripten 3.1.6's libc++
        std::memcpy(&bits, &v, sizeof bits);
        u32(bits);
    }
    void text(std::string const& s) {  // with its terminating zero
        out.insert(out.end(), s.begin(), s.end());
        out.push_back(0);
    }
    // An attribute's name, type and size; its value follows.
    void attribute(std::string const& name, std::string const& type, std::uint32_t size) {
        text(name);
        text(type);
        u32(size);
    }
    void patchU64(std::size_t at, std::uint64_t v) {
        for (int i = 0; i < 8; ++i) out[at + std::size_t(i)] = std::uint8_t(v >> (8 * i));
    }
};

constexpr std::int32_t kPixelFloat = 2;  // PixelType FLOAT
constexpr std::uint8_t kNoCompression = 0;
constexpr std::uint8_t kIncreasingY = 0;  // LineOrder: the first row on top

std::vector<std::string> channelNames(int count) {
    if (count == 1) return {"Y"};
    std::array<char const*, 4> const rgba = {"R", "G", "B", "A"};
    std::vector<std::string> names;
    for (int c = 0; c < count; ++c) names.push_back(c < 4 ? rgba[std::size_t(c)] : "channel" + std::to_string(c));
    return names;
}

}  // namespace

std::optional<std::vector<std::uint8_t>> encodeExr(FloatImage const& image, int first, int count, std::string* error) {
    auto fail = [&](std::string const& why) -> std::optional<std::vector<std::uint8_t>> {
        if (error) *error = why;
        return std::nullopt;
    };
    if (image.width <= 0 || image.height <= 0) return fail("the image is empty");
    if (count <= 0) count = image.channels - first;
    if (first < 0 || count <= 0 || first + count > image.channels) return fail("channel range out of bounds");
    std::size_t const width = std::size_t(image.width), height = std::size_t(image.height);
    if (image.pixels.size() < width * height * std::size_t(image.channels))
        return fail("the image has fewer values than its size needs");

    // The header lists channels sorted by name and the scanlines store them in that order; each
    // keeps the image's channel it comes from.
    std::vector<std::string> const names = channelNames(count);
    std::vector<int> order;
    for (int c = 0; c < count; ++c) order.push_back(c);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return names[std::size_t(a)] < names[std::size_t(b)]; });

    Bytes b;
    for (std::uint8_t const m : {0x76, 0x2f, 0x31, 0x01}) b.u8(m);
    b.u32(2);  // version 2, no flags: single-part scanline, names of at most 31 bytes

    std::uint32_t chlistSize = 1;
    for (std::string const& n : names) chlistSize += std::uint32_t(n.size() + 1 + 16);
    b.attribute("channels", "chlist", chlistSize);
    for (int const c : order) {
        b.text(names[std::size_t(c)]);
        b.i32(kPixelFloat);
        b.u32(0);  // pLinear and three reserved bytes
        b.i32(1);  // xSampling
        b.i32(1);  // ySampling
    }
    b.u8(0);
    b.attribute("compression", "compression", 1);
    b.u8(kNoCompression);
    for (char const* window : {"dataWindow", "displayWindow"}) {
        b.attribute(window, "box2i", 16);
        b.i32(0);
        b.i32(0);
        b.i32(image.width - 1);
        b.i32(image.height - 1);
    }
    b.attribute("lineOrder", "lineOrder", 1);
    b.u8(kIncreasingY);
    b.attribute("pixelAspectRatio", "float", 4);
    b.f32(1.0f);
    b.attribute("screenWindowCenter", "v2f", 8);
    b.f32(0.0f);
    b.f32(0.0f);
    b.attribute("screenWindowWidth", "float", 4);
    b.f32(1.0f);
    b.u8(0);  // end of the header

    std::size_t const table = b.out.size();
    b.out.resize(table + 8 * height);  // the offsets, filled in below
    std::uint32_t const rowBytes = std::uint32_t(width * std::size_t(count) * 4);
    b.out.reserve(b.out.size() + height * (8 + rowBytes));
    for (std::size_t y = 0; y < height; ++y) {
        b.patchU64(table + 8 * y, b.out.size());
        b.i32(std::int32_t(y));
        b.u32(rowBytes);
        for (int const c : order)
            for (std::size_t x = 0; x < width; ++x)
                b.f32(image.pixels[(y * width + x) * std::size_t(image.channels) + std::size_t(first + c)]);
    }
    return std::move(b.out);
}

}  // namespace gbl
