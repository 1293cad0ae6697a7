// The browser build's image files (issue 29): OpenImageIO does not build for the web, so PNG goes
// through stb_image_write, EXR through our own writer of uncompressed float scanlines
// (core/exr_encode.h) and reading through stb_image (PNG, JPEG, HDR, ...; not EXR). image_io.cpp is
// the native version of the same three functions.
#include "image_io.h"

#include "core/exr_encode.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <vector>

namespace gbl {

std::optional<std::string> writePng(std::string const& path, FloatImage const& image, int channels) {
    if (image.width <= 0 || image.height <= 0) return "cannot write " + path + ": the image is empty";
    if (channels <= 0) channels = image.channels;
    if (channels > image.channels || channels > 4) return "cannot write " + path + ": channel range out of bounds";
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
    std::string why;
    std::optional<std::vector<std::uint8_t>> const bytes = encodeExr(image, first, count, &why);
    if (!bytes) return "cannot write " + path + ": " + why;
    std::ofstream file(path, std::ios::binary);
    file.write(reinterpret_cast<char const*>(bytes->data()), std::streamsize(bytes->size()));
    file.close();
    if (!file) return "cannot write " + path + ": the file could not be written";
    return std::nullopt;
}

std::optional<FloatImage> readImage(std::string const& path, std::string* error) {
    int width = 0, height = 0, channels = 0;
    FloatImage img;
    if (stbi_is_hdr(path.c_str())) {
        float* data = stbi_loadf(path.c_str(), &width, &height, &channels, 0);
        if (!data) {
            if (error) *error = "cannot read " + path + ": " + stbi_failure_reason();
            return std::nullopt;
        }
        img.pixels.assign(data, data + std::size_t(width) * std::size_t(height) * std::size_t(channels));
        stbi_image_free(data);
    } else {
        std::uint16_t* data = stbi_load_16(path.c_str(), &width, &height, &channels, 0);
        if (!data) {
            if (error) *error = "cannot read " + path + ": " + stbi_failure_reason();
            return std::nullopt;
        }
        std::size_t const count = std::size_t(width) * std::size_t(height) * std::size_t(channels);
        img.pixels.resize(count);
        for (std::size_t i = 0; i < count; ++i) img.pixels[i] = float(data[i]) / 65535.0f;
        stbi_image_free(data);
    }
    img.width = width;
    img.height = height;
    img.channels = channels;
    return img;
}

}  // namespace gbl
