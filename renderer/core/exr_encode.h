// An OpenEXR file of 32-bit float channels, uncompressed scanlines, as bytes: the browser build's
// EXR writer (renderer/image_io_stb.cpp), where OpenImageIO is not available. No files here.
#pragma once

#include "core/frame_types.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace gbl {

// The channels [first, first + count) of `image` (count 0: from first to the last) as a
// single-part scanline EXR, FLOAT pixels, no compression, rows top to bottom. Channels are named
// as OpenImageIO names them natively, so both builds' files read alike: one channel "Y", else R,
// G, B, A. nullopt with `error` set when the image is empty or the range is out of bounds.
std::optional<std::vector<std::uint8_t>> encodeExr(FloatImage const& image, int first = 0, int count = 0,
                                                   std::string* error = nullptr);

}  // namespace gbl
