// OpenImageIO decoding from memory, placeholder textures and CPU-baked specular maps.
#include "gltf/images.h"

#include "gltf/mapping.h"

#ifdef __EMSCRIPTEN__
#include <stb_image.h>  // the browser build has no OpenImageIO (compiled in app/web/tinygltf_impl.cpp)
#else
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace gbl {

#ifdef __EMSCRIPTEN__
DecodedImage decodeImage(std::span<std::uint8_t const> bytes, std::string name, std::string_view,
                         std::size_t maxPixels) {
    DecodedImage out;
    if (bytes.empty()) {
        out.error = "the image data is empty";
        return out;
    }
    if (bytes.size() > std::size_t(std::numeric_limits<int>::max())) {
        out.error = "the image data is too large";
        return out;
    }
    int width = 0, height = 0, fileChannels = 0;
    int const size = int(bytes.size());
    if (!stbi_info_from_memory(bytes.data(), size, &width, &height, &fileChannels)) {
        out.error = std::string("the image could not be decoded (") + stbi_failure_reason() + ")";
        return out;
    }
    std::size_t const pixels = std::size_t(width) * std::size_t(height);
    if (pixels > maxPixels || width > (1 << 16) || height > (1 << 16)) {
        out.overLimit = true;
        out.error = "an image is " + std::to_string(width) + " x " + std::to_string(height) +
                    " pixels, more than the limit of " + std::to_string(maxPixels) + " pixels";
        return out;
    }
    int const channels = std::clamp(fileChannels, 1, 4);
    stbi_uc* data = stbi_load_from_memory(bytes.data(), size, &width, &height, &fileChannels, channels);
    if (!data) {
        out.error = std::string("the image data is corrupt (") + stbi_failure_reason() + ")";
        return out;
    }
    ImageData img;
    img.name = std::move(name);
    img.width = width;
    img.height = height;
    img.channels = channels;
    img.pixels.assign(data, data + pixels * std::size_t(channels));
    stbi_image_free(data);
    out.image = std::move(img);
    return out;
}
#else
namespace {

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

}  // namespace

DecodedImage decodeImage(std::span<std::uint8_t const> bytes, std::string name, std::string_view nameHint,
                         std::size_t maxPixels) {
    namespace OIIO = OIIO_NAMESPACE;
    DecodedImage out;
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
    OIIO::ImageSpec const& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 || spec.deep) {
        out.error = "the image has no usable pixels";
        return out;
    }
    std::size_t const pixels = std::size_t(spec.width) * std::size_t(spec.height);
    if (pixels > maxPixels || spec.width > (1 << 16) || spec.height > (1 << 16)) {
        out.overLimit = true;
        out.error = "an image is " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                    " pixels, more than the limit of " + std::to_string(maxPixels) + " pixels";
        return out;
    }
    int const channels = std::min(spec.nchannels, 4);
    ImageData img;
    img.name = std::move(name);
    img.width = spec.width;
    img.height = spec.height;
    img.channels = channels;
    img.pixels.resize(pixels * std::size_t(channels));
    if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, img.pixels.data())) {
        std::string const e = in->geterror();
        out.error = "the image data is corrupt" + (e.empty() ? std::string() : " (" + e + ")");
        return out;
    }
    in->close();
    out.image = std::move(img);
    return out;
}

#endif

ImageData placeholderImage(std::string name) {
    ImageData img;
    img.name = std::move(name);
    img.width = 8;
    img.height = 8;
    img.channels = 4;
    img.srgb = true;
    img.pixels.resize(8 * 8 * 4);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            bool const magenta = ((x / 2) + (y / 2)) % 2 == 0;
            std::uint8_t* p = &img.pixels[std::size_t(y * 8 + x) * 4];
            p[0] = magenta ? 255 : 0;
            p[1] = 0;
            p[2] = magenta ? 255 : 0;
            p[3] = 255;
        }
    }
    return img;
}

namespace {

// Channel c of the texel nearest to (u, v) in [0,1]^2, as 0..1; missing channels read as 1
// except when the image has one or two channels (grey, grey+alpha), where grey fills RGB.
float sampleNearest(ImageData const& img, float u, float v, int c) {
    int const x = std::clamp(int(u * float(img.width)), 0, img.width - 1);
    int const y = std::clamp(int(v * float(img.height)), 0, img.height - 1);
    std::uint8_t const* p = &img.pixels[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * img.channels];
    int src = c;
    if (img.channels <= 2)
        src = c == 3 ? (img.channels == 2 ? 1 : -1) : 0;
    else if (c >= img.channels)
        src = -1;
    return src < 0 ? 1.0f : float(p[src]) / 255.0f;
}

}  // namespace

ImageData bakeSpecularImage(ImageData const* metallicRoughness, ImageData const* specular, float metallicFactor,
                            float roughnessFactor, float specularWeightFactor, std::string name) {
    ImageData out;
    out.name = std::move(name);
    out.channels = 1;
    out.srgb = false;
    out.width = std::max(metallicRoughness ? metallicRoughness->width : 1, specular ? specular->width : 1);
    out.height = std::max(metallicRoughness ? metallicRoughness->height : 1, specular ? specular->height : 1);
    out.pixels.resize(std::size_t(out.width) * std::size_t(out.height));
    for (int y = 0; y < out.height; ++y) {
        float const v = (float(y) + 0.5f) / float(out.height);
        for (int x = 0; x < out.width; ++x) {
            float const u = (float(x) + 0.5f) / float(out.width);
            float metallic = metallicFactor, roughness = roughnessFactor, weight = specularWeightFactor;
            if (metallicRoughness) {
                roughness *= sampleNearest(*metallicRoughness, u, v, 1);
                metallic *= sampleNearest(*metallicRoughness, u, v, 2);
            }
            if (specular) weight *= sampleNearest(*specular, u, v, 3);
            float const s = specularFromMetallicRoughness(metallic, roughness, weight);
            out.pixels[std::size_t(y) * std::size_t(out.width) + std::size_t(x)] =
                std::uint8_t(std::lround(s * 255.0f));
        }
    }
    return out;
}

}  // namespace gbl
