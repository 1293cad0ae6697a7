// Image files, the one seam: reading (from a file or from memory), writing PNG and EXR. Natively
// OpenImageIO implements it (image_io_oiio.cpp); in the browser stb_image, stb_image_write and tinyexr
// (image_io_stb.cpp), over zlib compiled for the browser (cmake/web.cmake). No GL.
#pragma once

#include "core/frame_types.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gbl {

// How a file stores its samples: what limits the precision of the values read from it.
enum class SampleStorage { Uint8, Uint16, Half, Float, Other };

// Wider or taller than this is refused before decoding, as is more than the caller's maxPixels.
inline constexpr int kMaxImageSide = 1 << 16;

// An image as decoded: rows top to bottom, channels interleaved; straight (unassociated) alpha.
struct DecodedPixels {
    int width = 0, height = 0, channels = 0;       // channels: decoded (all the file has unless a range is asked)
    int firstChannel = 0;                          // the first decoded channel of the file
    int fileChannels = 0;                          // all the file has
    SampleStorage storage = SampleStorage::Other;  // the file's sample type
    std::vector<float> floats;                     // readImageFile: the values as floats (8/16 bits: 0..1)
    std::vector<std::uint8_t> bytes;               // decodeImage8: the values as 8 bits
    std::string error;                             // why not, without the file's name; empty when decoded
    bool missing = false;                          // the file does not exist or cannot be opened
    bool overLimit = false;                        // no usable size or too large: nothing was decoded
    bool ok() const { return error.empty(); }
};

// Every channel of a file (PNG, JPEG, HDR, EXR: ZIP-compressed and half-float included; natively any
// format OpenImageIO reads) as floats. EXR channels come R, G, B, A first, then the others in the
// file's order, as OpenImageIO orders them.
// With `channelCount` > 0 only the file's channels [firstChannel, firstChannel + channelCount) are
// decoded (clamped to the file's; natively the others are never decoded, in the browser they are dropped).
DecodedPixels readImageFile(std::string const& path, std::size_t maxPixels, int firstChannel = 0, int channelCount = 0);
// The file's size, channels and sample type from its header, nothing decoded where the format allows
// (natively always; the browser decodes EXR files to learn theirs). floats stays empty.
DecodedPixels probeImageFile(std::string const& path);
// PNG or JPEG (natively any format OpenImageIO reads) from memory as 8 bits, 1 to 4 channels.
// `nameHint` (a URI or a mime type) helps pick the format when the bytes' signature does not.
DecodedPixels decodeImage8(std::span<std::uint8_t const> bytes, std::string_view nameHint, std::size_t maxPixels);

// Writes the image as 8-bit PNG; values are clamped to 0..1 and rounded. `channels` selects how many of
// the image's channels to write (1 = the first, 3 = RGB); 0 writes them all.
std::optional<std::string> writePng(std::string const& path, FloatImage const& image, int channels = 0);
// Writes the channels [first, first + count) (count 0: to the last) as a ZIP-compressed EXR of 32-bit
// floats, values exactly as given, named as OpenImageIO names them: one channel "Y", else R, G, B, A.
std::optional<std::string> writeExr(std::string const& path, FloatImage const& image, int first = 0, int count = 0);
// readImageFile as a FloatImage; on failure *error says "cannot read PATH: why".
std::optional<FloatImage> readImage(std::string const& path, std::string* error = nullptr);

// What writeExr and writePng check before writing: nullopt when [first, first + count) of the image can be
// written, else why not ("the image is empty", "channel range out of bounds", ...). count 0: to the last.
std::optional<std::string> checkWritable(FloatImage const& image, int first, int count);

}  // namespace gbl
