// Attachment files to floats: raw samples, or images through image/image_io.h.
#include "import/gbuffer_files.h"

#include "image/image_io.h"

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

std::optional<FileImage> readFile(ImageRef const& ref, ChannelRange range, std::string* error) {
    if (ref.raw) return readRaw(ref, error);
    // Only the channels the manifest names are decoded (an RGBA file read for its alpha alone: one).
    int const first = std::max(range.first, 0);
    DecodedPixels d = readImageFile(ref.path, std::size_t(1) << 28, first, std::max(range.last - first + 1, 1));
    if (!d.ok()) {
        *error = ref.field + ".file " + ref.path +
                 (d.overLimit ? " has no usable size (" + sizeText(d.width, d.height) + ")"
                              : " cannot be read (" + d.error + ")");
        return std::nullopt;
    }
    FileImage img;
    img.width = d.width;
    img.height = d.height;
    img.channels = d.channels;
    img.firstChannel = d.firstChannel;
    img.fileChannels = d.fileChannels;
    img.storage = d.storage;
    img.pixels = std::move(d.floats);
    return img;
}

}  // namespace gbl::detail
