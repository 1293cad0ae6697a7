// Attachment files to floats: raw samples, OpenImageIO (stb_image in the browser).
#include "import/gbuffer_files.h"

#ifdef __EMSCRIPTEN__
#include <stb_image.h>
#else
#include <OpenImageIO/imageio.h>
#endif

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace gbl::detail {

std::string sizeText(int w, int h) {
    return std::to_string(w) + "x" + std::to_string(h);
}

namespace {

// IEEE 754 binary16 to float (raw half files; OpenImageIO converts its own formats).
float halfToFloat(std::uint16_t h) {
    std::uint32_t const sign = std::uint32_t(h & 0x8000u) << 16;
    std::uint32_t exp = (h >> 10) & 0x1fu;
    std::uint32_t mant = h & 0x3ffu;
    std::uint32_t bits;
    if (exp == 0) {
        if (mant == 0) {
            bits = sign;
        } else {  // subnormal: normalise
            exp = 127 - 15 + 1;
            while (!(mant & 0x400u)) {
                mant <<= 1;
                --exp;
            }
            bits = sign | (exp << 23) | ((mant & 0x3ffu) << 13);
        }
    } else if (exp == 31) {
        bits = sign | 0x7f800000u | (mant << 13);
    } else {
        bits = sign | ((exp + 127 - 15) << 23) | (mant << 13);
    }
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

std::optional<FileImage> readRaw(ImageRef const& ref, std::string* error) {
    RawFormat const& f = *ref.raw;
    std::ifstream in(ref.path, std::ios::binary);
    if (!in) {
        *error = ref.field + ".file " + ref.path + " cannot be read (no such file, or no permission)";
        return std::nullopt;
    }
    std::ostringstream s;
    s << in.rdbuf();
    std::string const bytes = s.str();
    std::size_t const bytesPer = f.type == RawType::Float ? 4 : f.type == RawType::Half ? 2 : 1;
    std::size_t const samples = std::size_t(f.width) * std::size_t(f.height) * std::size_t(f.channels);
    if (bytes.size() != samples * bytesPer) {
        *error = ref.field + ".raw does not match " + ref.path + ": " + sizeText(f.width, f.height) + " with " +
                 std::to_string(f.channels) + " " + std::string(kRawTypeNames[std::size_t(f.type)]) +
                 " channels needs " + std::to_string(samples * bytesPer) + " bytes, the file holds " +
                 std::to_string(bytes.size());
        return std::nullopt;
    }
    FileImage img{f.width, f.height, f.channels, 0, f.channels, SampleStorage::Float, std::vector<float>(samples)};
    for (std::size_t i = 0; i < samples; ++i) {
        if (f.type == RawType::Float) {
            std::memcpy(&img.pixels[i], bytes.data() + i * 4, 4);
        } else if (f.type == RawType::Half) {
            std::uint16_t h;
            std::memcpy(&h, bytes.data() + i * 2, 2);
            img.pixels[i] = halfToFloat(h);
        } else {
            img.pixels[i] = float(static_cast<unsigned char>(bytes[i])) / 255.0f;
        }
    }
    img.storage = f.type == RawType::Float  ? SampleStorage::Float
                  : f.type == RawType::Half ? SampleStorage::Half
                                            : SampleStorage::Uint8;
    return img;
}

}  // namespace

#ifdef __EMSCRIPTEN__
// The browser build reads PNG, JPEG and HDR files (8 or 16 bits, or float) through stb_image; EXR
// needs OpenImageIO and is refused with that reason.
std::optional<FileImage> readFile(ImageRef const& ref, ChannelRange, std::string* error) {
    if (ref.raw) return readRaw(ref, error);
    char const* path = ref.path.c_str();
    FileImage img;
    if (!stbi_info(path, &img.width, &img.height, &img.channels)) {
        std::ifstream probe(ref.path);
        std::string const reason = !probe                       ? "no such file, or no permission"
                                   : ref.path.ends_with(".exr") ? "EXR needs OpenImageIO, which the browser build lacks"
                                                                : stbi_failure_reason();
        *error = ref.field + ".file " + ref.path + " cannot be read (" + reason + ")";
        return std::nullopt;
    }
    if (img.width <= 0 || img.height <= 0 || img.channels <= 0 ||
        std::size_t(img.width) * std::size_t(img.height) > (std::size_t(1) << 28)) {
        *error = ref.field + ".file " + ref.path + " has no usable size (" + sizeText(img.width, img.height) + ")";
        return std::nullopt;
    }
    img.fileChannels = img.channels;
    std::size_t const count = std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels);
    img.pixels.resize(count);
    int w = 0, h = 0, c = 0;
    if (stbi_is_hdr(path)) {
        img.storage = SampleStorage::Float;
        float* data = stbi_loadf(path, &w, &h, &c, 0);
        if (data) std::copy(data, data + count, img.pixels.begin());
        stbi_image_free(data);
        if (!data) {
            *error = ref.field + ".file " + ref.path + " cannot be read (" + stbi_failure_reason() + ")";
            return std::nullopt;
        }
        return img;
    }
    bool const sixteen = stbi_is_16_bit(path) != 0;
    img.storage = sixteen ? SampleStorage::Uint16 : SampleStorage::Uint8;
    std::uint16_t* data = stbi_load_16(path, &w, &h, &c, 0);
    if (!data) {
        *error = ref.field + ".file " + ref.path + " cannot be read (" + stbi_failure_reason() + ")";
        return std::nullopt;
    }
    for (std::size_t i = 0; i < count; ++i) img.pixels[i] = float(data[i]) / 65535.0f;
    stbi_image_free(data);
    return img;
}
#else
std::optional<FileImage> readFile(ImageRef const& ref, ChannelRange range, std::string* error) {
    if (ref.raw) return readRaw(ref, error);
    // Alpha is data here (LearnOpenGL's gAlbedoSpec.png keeps specular in it), never coverage: without
    // this OpenImageIO premultiplies a PNG's colour by its alpha and the albedo comes out darkened.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(ref.path, &config);
    if (!in) {
        std::string reason = OIIO::geterror();
        std::ifstream probe(ref.path);
        if (!probe) reason = "no such file, or no permission";
        *error = ref.field + ".file " + ref.path + " cannot be read (" + reason + ")";
        return std::nullopt;
    }
    OIIO::ImageSpec const& spec = in->spec();
    FileImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.fileChannels = spec.nchannels;
    // Only the channels the manifest names are decoded (an RGBA file read for its alpha alone: one).
    img.firstChannel = std::clamp(range.first, 0, std::max(spec.nchannels - 1, 0));
    img.channels = std::clamp(range.last, img.firstChannel, std::max(spec.nchannels - 1, 0)) + 1 - img.firstChannel;
    OIIO::TypeDesc const t = spec.format;
    img.storage = t == OIIO::TypeDesc::UINT8    ? SampleStorage::Uint8
                  : t == OIIO::TypeDesc::UINT16 ? SampleStorage::Uint16
                  : t == OIIO::TypeDesc::HALF   ? SampleStorage::Half
                  : t == OIIO::TypeDesc::FLOAT  ? SampleStorage::Float
                                                : SampleStorage::Other;
    if (img.width <= 0 || img.height <= 0 || img.channels <= 0 ||
        std::size_t(img.width) * std::size_t(img.height) > (std::size_t(1) << 28)) {
        *error = ref.field + ".file " + ref.path + " has no usable size (" + sizeText(img.width, img.height) + ")";
        return std::nullopt;
    }
    img.pixels.resize(std::size_t(img.width) * std::size_t(img.height) * std::size_t(img.channels));
    if (!in->read_image(0, 0, img.firstChannel, img.firstChannel + img.channels, OIIO::TypeDesc::FLOAT,
                        img.pixels.data())) {
        *error = ref.field + ".file " + ref.path + " cannot be read (" + in->geterror() + ")";
        return std::nullopt;
    }
    return img;
}
#endif

}  // namespace gbl::detail
