// image_io.h through OpenImageIO: the native build's image files.
#include "image/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>

namespace gbl {

namespace {

SampleStorage storageOf(OIIO::TypeDesc t) {
    return t == OIIO::TypeDesc::UINT8    ? SampleStorage::Uint8
           : t == OIIO::TypeDesc::UINT16 ? SampleStorage::Uint16
           : t == OIIO::TypeDesc::HALF   ? SampleStorage::Half
           : t == OIIO::TypeDesc::FLOAT  ? SampleStorage::Float
                                         : SampleStorage::Other;
}

// The size checks every read makes before decoding; false (with out.error set) refuses the image.
bool usableSize(OIIO::ImageSpec const& spec, std::size_t maxPixels, DecodedPixels& out) {
    out.width = spec.width;
    out.height = spec.height;
    out.channels = spec.nchannels;
    out.storage = storageOf(spec.format);
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.deep) {
        out.overLimit = true;
        out.error = "the image has no usable pixels";
        return false;
    }
    if (std::size_t(spec.width) * std::size_t(spec.height) > maxPixels || spec.width > kMaxImageSide ||
        spec.height > kMaxImageSide) {
        out.overLimit = true;
        out.error = "the image is " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                    " pixels, more than the limit";
        return false;
    }
    return true;
}

// The file name OpenImageIO sees picks the reader; signatures are more reliable than names.
std::string formatName(std::span<std::uint8_t const> b, std::string_view hint) {
    static constexpr std::uint8_t kPng[] = {0x89, 'P', 'N', 'G'};
    if (b.size() >= 4 && std::memcmp(b.data(), kPng, 4) == 0) return "image.png";
    if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return "image.jpg";
    if (hint.find("png") != std::string_view::npos) return "image.png";
    if (hint.find("jpeg") != std::string_view::npos || hint.find("jpg") != std::string_view::npos) return "image.jpg";
    auto const dot = hint.find_last_of('.');
    if (dot != std::string_view::npos && hint.size() - dot <= 6) return "image" + std::string(hint.substr(dot));
    return "image.png";
}

std::optional<std::string> write(std::string const& path, FloatImage const& image, int first, int count,
                                 OIIO::TypeDesc format) {
    if (auto const why = checkWritable(image, first, count)) return "cannot write " + path + ": " + *why;
    if (count <= 0) count = image.channels - first;
    // Pack the chosen channels contiguously.
    std::vector<float> packed(std::size_t(image.width) * image.height * count);
    for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p)
        for (int c = 0; c < count; ++c) packed[p * count + c] = image.pixels[p * image.channels + first + c];
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return "cannot write " + path + ": " + OIIO::geterror();
    OIIO::ImageSpec spec(image.width, image.height, count, format);
    // OpenImageIO's default for EXR, said here so both implementations visibly write the same.
    if (format == OIIO::TypeDesc::FLOAT) spec.attribute("compression", "zip");
    if (!out->open(path, spec)) return "cannot write " + path + ": " + out->geterror();
    bool const ok = out->write_image(OIIO::TypeDesc::FLOAT, packed.data());
    std::string err = ok ? "" : out->geterror();
    out->close();
    if (!ok) return "cannot write " + path + ": " + err;
    return std::nullopt;
}

}  // namespace

namespace {
// The file opened for reading. Alpha is data, never coverage (LearnOpenGL's gAlbedoSpec.png keeps specular
// in it): without UnassociatedAlpha OpenImageIO premultiplies a PNG's colour by its alpha.
std::unique_ptr<OIIO::ImageInput> openImage(std::string const& path, DecodedPixels& out) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        out.error = OIIO::geterror();
        if (!std::ifstream(path)) {
            out.missing = true;
            out.error = "no such file, or no permission";
        }
        if (out.error.empty()) out.error = "not an image file";
    }
    return in;
}
}  // namespace

DecodedPixels probeImageFile(std::string const& path) {
    DecodedPixels out;
    auto in = openImage(path, out);
    if (in) {
        usableSize(in->spec(), std::numeric_limits<std::size_t>::max(), out);
        out.fileChannels = out.channels;
    }
    return out;
}

DecodedPixels readImageFile(std::string const& path, std::size_t maxPixels, int firstChannel, int channelCount) {
    DecodedPixels out;
    auto in = openImage(path, out);
    if (!in) return out;
    if (!usableSize(in->spec(), maxPixels, out)) return out;
    out.fileChannels = out.channels;
    if (channelCount > 0) {
        out.firstChannel = std::clamp(firstChannel, 0, out.fileChannels - 1);
        out.channels = std::clamp(channelCount, 1, out.fileChannels - out.firstChannel);
    }
    out.floats.resize(std::size_t(out.width) * std::size_t(out.height) * std::size_t(out.channels));
    if (!in->read_image(0, 0, out.firstChannel, out.firstChannel + out.channels, OIIO::TypeDesc::FLOAT,
                        out.floats.data())) {
        out.error = in->geterror();
        if (out.error.empty()) out.error = "the image data is corrupt";
        out.floats.clear();
    }
    return out;
}

DecodedPixels decodeImage8(std::span<std::uint8_t const> bytes, std::string_view nameHint, std::size_t maxPixels) {
    DecodedPixels out;
    if (bytes.empty()) {
        out.error = "the image data is empty";
        return out;
    }
    OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
    OIIO::ImageSpec config;
    // glTF colours are straight alpha; OpenImageIO would otherwise premultiply PNGs.
    config.attribute("oiio:UnassociatedAlpha", 1);
    // The proxy also goes in the configuration: some 2.4 readers look for it only there.
    void* proxy = &reader;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto in = OIIO::ImageInput::open(formatName(bytes, nameHint), &config, &reader);
    if (!in) {
        std::string const e = OIIO::geterror();
        out.error = "the image could not be decoded" + (e.empty() ? std::string() : " (" + e + ")");
        return out;
    }
    if (!usableSize(in->spec(), maxPixels, out)) return out;
    out.channels = std::min(out.channels, 4);
    out.bytes.resize(std::size_t(out.width) * std::size_t(out.height) * std::size_t(out.channels));
    if (!in->read_image(0, 0, 0, out.channels, OIIO::TypeDesc::UINT8, out.bytes.data())) {
        std::string const e = in->geterror();
        out.error = "the image data is corrupt" + (e.empty() ? std::string() : " (" + e + ")");
        out.bytes.clear();
        return out;
    }
    in->close();
    return out;
}

std::optional<std::string> writePng(std::string const& path, FloatImage const& image, int channels) {
    return write(path, image, 0, channels, OIIO::TypeDesc::UINT8);
}

std::optional<std::string> writeExr(std::string const& path, FloatImage const& image, int first, int count) {
    return write(path, image, first, count, OIIO::TypeDesc::FLOAT);
}

}  // namespace gbl
