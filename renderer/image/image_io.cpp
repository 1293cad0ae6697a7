// The parts of image_io.h that both implementations share.
#include "image/image_io.h"

#include <limits>

namespace gbl {

std::optional<std::string> checkWritable(FloatImage const& image, int first, int count) {
    if (image.width <= 0 || image.height <= 0 || image.channels <= 0) return "the image is empty";
    if (count <= 0) count = image.channels - first;
    if (first < 0 || count <= 0 || first + count > image.channels) return "channel range out of bounds";
    if (image.pixels.size() < std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
        return "the image has fewer values than its size needs";
    return std::nullopt;
}

std::optional<FloatImage> readImage(std::string const& path, std::string* error) {
    DecodedPixels read = readImageFile(path, std::numeric_limits<std::size_t>::max());
    if (!read.ok()) {
        if (error) *error = "cannot read " + path + ": " + read.error;
        return std::nullopt;
    }
    return FloatImage{read.width, read.height, read.channels, std::move(read.floats)};
}

}  // namespace gbl
