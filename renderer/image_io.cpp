// OpenImageIO output of read-back frame images.
#include "image_io.h"

#include <OpenImageIO/imageio.h>

namespace gbl {

namespace {

std::optional<std::string> write(std::string const& path, FloatImage const& image, int first, int count,
                                 OIIO::TypeDesc format) {
    if (image.width <= 0 || image.height <= 0) return "cannot write " + path + ": the image is empty";
    if (count <= 0) count = image.channels - first;
    if (first < 0 || first + count > image.channels) return "cannot write " + path + ": channel range out of bounds";
    // Pack the chosen channels contiguously.
    std::vector<float> packed(std::size_t(image.width) * image.height * count);
    for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p)
        for (int c = 0; c < count; ++c) packed[p * count + c] = image.pixels[p * image.channels + first + c];
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return "cannot write " + path + ": " + OIIO::geterror();
    OIIO::ImageSpec spec(image.width, image.height, count, format);
    if (!out->open(path, spec)) return "cannot write " + path + ": " + out->geterror();
    bool const ok = out->write_image(OIIO::TypeDesc::FLOAT, packed.data());
    std::string err = ok ? "" : out->geterror();
    out->close();
    if (!ok) return "cannot write " + path + ": " + err;
    return std::nullopt;
}

}  // namespace

std::optional<std::string> writePng(std::string const& path, FloatImage const& image, int channels) {
    return write(path, image, 0, channels, OIIO::TypeDesc::UINT8);
}

std::optional<std::string> writeExr(std::string const& path, FloatImage const& image, int first, int count) {
    return write(path, image, first, count, OIIO::TypeDesc::FLOAT);
}

std::optional<FloatImage> readImage(std::string const& path, std::string* error) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        if (error) *error = "cannot read " + path + ": " + OIIO::geterror();
        return std::nullopt;
    }
    OIIO::ImageSpec const& spec = in->spec();
    FloatImage img;
    img.width = spec.width;
    img.height = spec.height;
    img.channels = spec.nchannels;
    img.pixels.resize(std::size_t(img.width) * img.height * img.channels);
    if (!in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.pixels.data())) {
        if (error) *error = "cannot read " + path + ": " + in->geterror();
        return std::nullopt;
    }
    return img;
}

}  // namespace gbl
