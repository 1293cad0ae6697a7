// image_io.h through stb_image, stb_image_write and tinyexr: the browser build's image files, where
// OpenImageIO does not build. tests/image_io_stb_test.cpp compiles it natively against files that
// OpenImageIO wrote.
#include "image/image_io.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>

namespace gbl {

namespace {

bool isExr(std::span<std::uint8_t const> head) {
    static constexpr std::uint8_t kMagic[] = {0x76, 0x2f, 0x31, 0x01};
    return head.size() >= 4 && std::memcmp(head.data(), kMagic, 4) == 0;
}

// tinyexr's error string, freed.
std::string exrError(char const* err, char const* fallback) {
    std::string out = err ? err : fallback;
    if (err) FreeEXRErrorMessage(err);
    return out;
}

bool usableSize(std::size_t maxPixels, DecodedPixels& out) {
    if (out.width <= 0 || out.height <= 0 || out.channels <= 0) {
        out.overLimit = true;
        out.error = "the image has no usable pixels";
        return false;
    }
    if (std::size_t(out.width) * std::size_t(out.height) > maxPixels || out.width > kMaxImageSide ||
        out.height > kMaxImageSide) {
        out.overLimit = true;
        out.error = "the image is " + std::to_string(out.width) + " x " + std::to_string(out.height) +
                    " pixels, more than the limit";
        return false;
    }
    return true;
}

// Where channel `name` goes: R, G, B, A first (as OpenImageIO orders them), the rest after, in file order.
int channelRank(std::string const& name) {
    static constexpr std::array<char const*, 4> kFirst = {"R", "G", "B", "A"};
    for (std::size_t i = 0; i < kFirst.size(); ++i)
        if (name == kFirst[i]) return int(i);
    return int(kFirst.size());
}

struct ExrHeader {
    EXRHeader h;
    ExrHeader() { InitEXRHeader(&h); }
    ~ExrHeader() { FreeEXRHeader(&h); }
    ExrHeader(ExrHeader const&) = delete;
    ExrHeader& operator=(ExrHeader const&) = delete;
};
struct ExrImage {
    EXRImage i;
    ExrImage() { InitEXRImage(&i); }
    ~ExrImage() { FreeEXRImage(&i); }
    ExrImage(ExrImage const&) = delete;
    ExrImage& operator=(ExrImage const&) = delete;
};

// A single-part scanline EXR: every channel as float (half converted, uint scaled as OpenImageIO does).
void readExr(std::vector<std::uint8_t> const& file, std::size_t maxPixels, DecodedPixels& out) {
    EXRVersion version;
    if (ParseEXRVersionFromMemory(&version, file.data(), file.size()) != TINYEXR_SUCCESS) {
        out.error = "not a readable EXR file";
        return;
    }
    if (version.multipart || version.non_image || version.tiled) {
        out.error = "multi-part, deep and tiled EXR files are not read here (scanline files are)";
        return;
    }
    ExrHeader header;
    char const* err = nullptr;
    if (ParseEXRHeaderFromMemory(&header.h, &version, file.data(), file.size(), &err) != TINYEXR_SUCCESS) {
        out.error = exrError(err, "the EXR header is corrupt");
        return;
    }
    EXRBox2i const& window = header.h.data_window;
    out.width = window.max_x - window.min_x + 1;
    out.height = window.max_y - window.min_y + 1;
    out.channels = header.h.num_channels;
    int const first = header.h.num_channels > 0 ? header.h.pixel_types[0] : -1;
    bool const same = std::all_of(header.h.pixel_types, header.h.pixel_types + header.h.num_channels,
                                  [&](int t) { return t == first; });
    out.storage = !same                              ? SampleStorage::Other
                  : first == TINYEXR_PIXELTYPE_HALF  ? SampleStorage::Half
                  : first == TINYEXR_PIXELTYPE_FLOAT ? SampleStorage::Float
                                                     : SampleStorage::Other;
    if (!usableSize(maxPixels, out)) return;
    for (int c = 0; c < header.h.num_channels; ++c)
        if (header.h.pixel_types[c] == TINYEXR_PIXELTYPE_HALF)
            header.h.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
    ExrImage image;
    if (LoadEXRImageFromMemory(&image.i, &header.h, file.data(), file.size(), &err) != TINYEXR_SUCCESS) {
        out.error = exrError(err, "the EXR pixels are corrupt");
        return;
    }
    if (image.i.width != out.width || image.i.height != out.height || !image.i.images) {
        out.error = "the EXR pixels do not match its header";
        return;
    }
    std::vector<int> order(static_cast<std::size_t>(out.channels));
    for (int c = 0; c < out.channels; ++c) order[std::size_t(c)] = c;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return channelRank(header.h.channels[a].name) < channelRank(header.h.channels[b].name);
    });
    std::size_t const pixels = std::size_t(out.width) * std::size_t(out.height);
    out.floats.resize(pixels * std::size_t(out.channels));
    for (int slot = 0; slot < out.channels; ++slot) {
        int const c = order[std::size_t(slot)];
        unsigned char const* plane = image.i.images[c];
        bool const isUint = header.h.requested_pixel_types[c] == TINYEXR_PIXELTYPE_UINT;
        for (std::size_t p = 0; p < pixels; ++p) {
            float v;
            if (isUint) {
                std::uint32_t u;
                std::memcpy(&u, plane + p * 4, 4);
                v = float(double(u) / double(std::numeric_limits<std::uint32_t>::max()));
            } else {
                std::memcpy(&v, plane + p * 4, 4);
            }
            out.floats[p * std::size_t(out.channels) + std::size_t(slot)] = v;
        }
    }
}

// PNG, JPEG, HDR, ... through stb_image: HDR as floats, the rest through 16 bits to 0..1.
void readStb(std::vector<std::uint8_t> const& file, std::size_t maxPixels, DecodedPixels& out) {
    int const size = int(file.size());
    if (!stbi_info_from_memory(file.data(), size, &out.width, &out.height, &out.channels)) {
        out.error = stbi_failure_reason();
        return;
    }
    bool const hdr = stbi_is_hdr_from_memory(file.data(), size) != 0;
    out.storage = hdr                                             ? SampleStorage::Float
                  : stbi_is_16_bit_from_memory(file.data(), size) ? SampleStorage::Uint16
                                                                  : SampleStorage::Uint8;
    if (!usableSize(maxPixels, out)) return;
    int w = 0, h = 0, c = 0;
    std::size_t const count = std::size_t(out.width) * std::size_t(out.height) * std::size_t(out.channels);
    if (hdr) {
        std::unique_ptr<float, void (*)(void*)> data(stbi_loadf_from_memory(file.data(), size, &w, &h, &c, 0),
                                                     stbi_image_free);
        if (!data) {
            out.error = stbi_failure_reason();
            return;
        }
        out.floats.assign(data.get(), data.get() + count);
        return;
    }
    std::unique_ptr<std::uint16_t, void (*)(void*)> data(stbi_load_16_from_memory(file.data(), size, &w, &h, &c, 0),
                                                         stbi_image_free);
    if (!data) {
        out.error = stbi_failure_reason();
        return;
    }
    out.floats.resize(count);
    for (std::size_t i = 0; i < count; ++i) out.floats[i] = float(data.get()[i]) / 65535.0f;
}

}  // namespace

DecodedPixels readImageFile(std::string const& path, std::size_t maxPixels, int firstChannel, int channelCount) {
    DecodedPixels out;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        out.missing = true;
        out.error = "no such file, or no permission";
        return out;
    }
    std::vector<std::uint8_t> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (file.size() > std::size_t(std::numeric_limits<int>::max())) {
        out.error = "the file is too large";
        return out;
    }
    if (isExr(file))
        readExr(file, maxPixels, out);
    else
        readStb(file, maxPixels, out);
    out.fileChannels = out.channels;
    if (!out.ok()) {
        out.floats.clear();
        return out;
    }
    if (channelCount > 0 && out.channels > 0) {  // the decoders give every channel: keep the asked ones
        int const first = std::clamp(firstChannel, 0, out.channels - 1);
        int const count = std::clamp(channelCount, 1, out.channels - first);
        std::size_t const pixels = std::size_t(out.width) * std::size_t(out.height);
        std::vector<float> kept(pixels * std::size_t(count));
        for (std::size_t p = 0; p < pixels; ++p)
            for (int c = 0; c < count; ++c) kept[p * count + c] = out.floats[p * out.channels + first + c];
        out.floats = std::move(kept);
        out.firstChannel = first;
        out.channels = count;
    }
    return out;
}

DecodedPixels probeImageFile(std::string const& path) {
    DecodedPixels out = readImageFile(path, std::numeric_limits<std::size_t>::max());
    out.floats.clear();
    return out;
}

DecodedPixels decodeImage8(std::span<std::uint8_t const> bytes, std::string_view, std::size_t maxPixels) {
    DecodedPixels out;
    if (bytes.empty()) {
        out.error = "the image data is empty";
        return out;
    }
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max())) {
        out.error = "the image data is too large";
        return out;
    }
    int const size = int(bytes.size());
    if (!stbi_info_from_memory(bytes.data(), size, &out.width, &out.height, &out.channels)) {
        out.error = std::string("the image could not be decoded (") + stbi_failure_reason() + ")";
        return out;
    }
    out.storage = SampleStorage::Uint8;
    if (!usableSize(maxPixels, out)) return out;
    out.channels = std::clamp(out.channels, 1, 4);
    int w = 0, h = 0, c = 0;
    std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load_from_memory(bytes.data(), size, &w, &h, &c, out.channels),
                                                   stbi_image_free);
    if (!data) {
        out.error = std::string("the image data is corrupt (") + stbi_failure_reason() + ")";
        return out;
    }
    out.bytes.assign(data.get(),
                     data.get() + std::size_t(out.width) * std::size_t(out.height) * std::size_t(out.channels));
    return out;
}

std::optional<std::string> writePng(std::string const& path, FloatImage const& image, int channels) {
    if (auto const why = checkWritable(image, 0, channels)) return "cannot write " + path + ": " + *why;
    if (channels <= 0) channels = image.channels;
    if (channels > 4) return "cannot write " + path + ": channel range out of bounds";
    // As OpenImageIO converts float to 8 bits: clamped to [0, 1], rounded to the nearest step.
    std::size_t const pixels = std::size_t(image.width) * std::size_t(image.height);
    std::vector<std::uint8_t> bytes(pixels * std::size_t(channels));
    for (std::size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < channels; ++c) {
            float const v = std::clamp(image.pixels[p * std::size_t(image.channels) + std::size_t(c)], 0.0f, 1.0f);
            bytes[p * std::size_t(channels) + std::size_t(c)] = std::uint8_t(std::lround(v * 255.0f));
        }
    if (!stbi_write_png(path.c_str(), image.width, image.height, channels, bytes.data(), image.width * channels))
        return "cannot write " + path + ": the file could not be written";
    return std::nullopt;
}

std::optional<std::string> writeExr(std::string const& path, FloatImage const& image, int first, int count) {
    if (auto const why = checkWritable(image, first, count)) return "cannot write " + path + ": " + *why;
    if (count <= 0) count = image.channels - first;
    if (count > 4) return "cannot write " + path + ": more than 4 channels";
    // OpenEXR lists channels sorted by name (A, B, G, R); each is one plane of floats.
    static constexpr std::array<char const*, 4> kRgba = {"R", "G", "B", "A"};
    std::vector<std::string> names;
    for (int c = 0; c < count; ++c) names.push_back(count == 1 ? "Y" : kRgba[std::size_t(c)]);
    std::vector<int> order(static_cast<std::size_t>(count));
    for (int c = 0; c < count; ++c) order[std::size_t(c)] = c;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return names[std::size_t(a)] < names[std::size_t(b)]; });
    std::size_t const pixels = std::size_t(image.width) * std::size_t(image.height);
    std::size_t const planeCount = std::size_t(count);
    std::vector<std::vector<float>> planes(planeCount, std::vector<float>(pixels));
    std::vector<unsigned char*> planePointers;
    std::vector<EXRChannelInfo> infos(planeCount);
    std::vector<int> types(planeCount, TINYEXR_PIXELTYPE_FLOAT);
    for (int slot = 0; slot < count; ++slot) {
        int const c = order[std::size_t(slot)];
        std::vector<float>& plane = planes[std::size_t(slot)];
        for (std::size_t p = 0; p < pixels; ++p)
            plane[p] = image.pixels[p * std::size_t(image.channels) + std::size_t(first + c)];
        planePointers.push_back(reinterpret_cast<unsigned char*>(plane.data()));
        std::string const& name = names[std::size_t(c)];
        std::memset(&infos[std::size_t(slot)], 0, sizeof(EXRChannelInfo));
        std::memcpy(infos[std::size_t(slot)].name, name.c_str(), name.size() + 1);
    }
    EXRImage exr;
    InitEXRImage(&exr);
    exr.images = planePointers.data();
    exr.width = image.width;
    exr.height = image.height;
    exr.num_channels = count;
    EXRHeader header;
    InitEXRHeader(&header);
    header.num_channels = count;
    header.channels = infos.data();
    header.pixel_types = types.data();
    header.requested_pixel_types = types.data();
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
    char const* err = nullptr;
    // Not FreeEXRHeader/FreeEXRImage: every pointer in them is owned by the vectors above.
    if (SaveEXRImageToFile(&exr, &header, path.c_str(), &err) != TINYEXR_SUCCESS)
        return "cannot write " + path + ": " + exrError(err, "the file could not be written");
    return std::nullopt;
}

}  // namespace gbl
