// Image work for the glTF loader: decoding from memory (image/image_io.h), placeholders, specular bakes.
#pragma once

#include "scene/scene_data.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace gbl {

struct DecodedImage {
    std::optional<ImageData> image;
    std::string error;       // why decoding failed (the caller decides: placeholder or refusal)
    bool overLimit = false;  // the image is larger than maxPixels; error states the limit
};

// Decodes PNG or JPEG (natively any format OpenImageIO reads) from memory into 8 bits per channel,
// keeping 1..4 channels and straight (unassociated) alpha as glTF requires. `nameHint`
// (a URI or a mime type) helps pick the format when the bytes' signature does not.
DecodedImage decodeImage(std::span<std::uint8_t const> bytes, std::string name, std::string_view nameHint,
                         std::size_t maxPixels);

// 8x8 magenta/black checker that stands in for a texture that could not be loaded.
ImageData placeholderImage(std::string name);

// Single-channel specular image (red = specular intensity) baked from a glTF
// metallic-roughness texture (G = roughness, B = metallic) and a KHR_materials_specular
// texture (A = weight), either of which may be null, times their factors, through
// specularFromMetallicRoughness(). The result has the larger of the two sizes; the smaller
// input is sampled nearest-neighbour.
ImageData bakeSpecularImage(ImageData const* metallicRoughness, ImageData const* specular, float metallicFactor,
                            float roughnessFactor, float specularWeightFactor, std::string name);

}  // namespace gbl
