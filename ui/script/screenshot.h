// Reading back the window and writing it as a PNG.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gbl::ui {

// 8-bit RGB image, rows top to bottom.
struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;
};

// Reads the current draw framebuffer's back buffer (the whole window) before the swap.
RgbImage readWindow(int framebufferWidth, int framebufferHeight);

// Writes a PNG through image/image_io.h. Returns an error sentence naming the file on failure.
std::optional<std::string> writePng(RgbImage const& image, std::string const& path);

// Mean absolute difference per channel value (0..255) and the count of pixels that differ;
// images of different sizes compare as completely different.
struct ImageDifference {
    double mean = 0.0;
    long pixelsDiffering = 0;
};
ImageDifference compareImages(RgbImage const& a, RgbImage const& b);

}  // namespace gbl::ui
