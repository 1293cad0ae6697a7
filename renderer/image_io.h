// Writing frame images to disk through OpenImageIO (PNG for display, EXR for float data).
#pragma once

#include "core/frame_types.h"

#include <optional>
#include <string>

namespace gbl {

// Writes the image as 8-bit PNG; values are clamped to 0..1. `channels` selects how many of
// the image's channels to write (1 = the first, 3 = RGB); 0 writes them all.
std::optional<std::string> writePng(std::string const& path, FloatImage const& image, int channels = 0);
// Writes the channels [first, first + count) as a 32-bit float EXR, values exactly as given.
std::optional<std::string> writeExr(std::string const& path, FloatImage const& image, int first = 0, int count = 0);
// Reads any image OpenImageIO understands as floats, rows top to bottom.
std::optional<FloatImage> readImage(std::string const& path, std::string* error = nullptr);

}  // namespace gbl
