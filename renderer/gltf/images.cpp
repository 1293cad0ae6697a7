// Decoding images from memory (image/image_io.h), placeholder textures and CPU-baked specular maps.
#include "gltf/images.h"

#include "gltf/mapping.h"

#include "image/image_io.h"

#include <algorithm>
#include <cmath>

namespace gbl {

DecodedImage decodeImage(std::span<std::uint8_t const> bytes, std::string name, std::string_view nameHint,
                         std::size_t maxPixels) {
    DecodedImage out;
    DecodedPixels decoded = decodeImage8(bytes, nameHint, maxPixels);
    if (decoded.overLimit && decoded.width > 0 && decoded.height > 0) {
        out.overLimit = true;
        out.error = "an image is " + std::to_string(decoded.width) + " x " + std::to_string(decoded.height) +
                    " pixels, more than the limit of " + std::to_string(maxPixels) + " pixels";
        return out;
    }
    if (!decoded.ok()) {
        out.error = std::move(decoded.error);
        return out;
    }
    ImageData img;
    img.name = std::move(name);
    img.width = decoded.width;
    img.height = decoded.height;
    img.channels = decoded.channels;
    img.pixels = std::move(decoded.bytes);
    out.image = std::move(img);
    return out;
}

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
