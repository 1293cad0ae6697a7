// Window read-back and PNG output.
#include "script/screenshot.h"

#include "gl/gl_api.h"
#include "image/image_io.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace gbl::ui {

RgbImage readWindow(int width, int height) {
    RgbImage image;
    if (width <= 0 || height <= 0) return image;
    image.width = width;
    image.height = height;
    image.pixels.resize(std::size_t(width) * height * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    // Rows of 3 bytes per pixel are not 4-byte aligned in general.
#ifdef __EMSCRIPTEN__
    // WebGL2 reads the canvas only as RGBA bytes.
    std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    for (std::size_t p = 0; p < std::size_t(width) * height; ++p) std::memcpy(&image.pixels[p * 3], &rgba[p * 4], 3);
#else
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.pixels.data());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
#endif
    // GL returns the bottom row first; images are stored top row first.
    std::size_t const rowBytes = std::size_t(width) * 3;
    std::vector<std::uint8_t> row(rowBytes);
    for (int y = 0; y < height / 2; ++y) {
        std::uint8_t* a = image.pixels.data() + std::size_t(y) * rowBytes;
        std::uint8_t* b = image.pixels.data() + std::size_t(height - 1 - y) * rowBytes;
        std::memcpy(row.data(), a, rowBytes);
        std::memcpy(a, b, rowBytes);
        std::memcpy(b, row.data(), rowBytes);
    }
    return image;
}

std::optional<std::string> writePng(RgbImage const& image, std::string const& path) {
    if (image.width <= 0 || image.height <= 0) return "cannot write " + path + ": the window has no pixels (0x0)";
    // Through the one image seam (image/image_io.h): each byte as k / 255, which its 8-bit PNG
    // writer rounds back to k exactly.
    FloatImage pixels{image.width, image.height, 3, std::vector<float>(image.pixels.size())};
    for (std::size_t i = 0; i < image.pixels.size(); ++i) pixels.pixels[i] = float(image.pixels[i]) / 255.0f;
    return gbl::writePng(path, pixels, 3);
}

ImageDifference compareImages(RgbImage const& a, RgbImage const& b) {
    if (a.width != b.width || a.height != b.height)
        return {255.0, long(std::max(a.pixels.size(), b.pixels.size()) / 3)};
    ImageDifference d;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); i += 3) {
        int const dr = std::abs(int(a.pixels[i]) - int(b.pixels[i]));
        int const dg = std::abs(int(a.pixels[i + 1]) - int(b.pixels[i + 1]));
        int const db = std::abs(int(a.pixels[i + 2]) - int(b.pixels[i + 2]));
        sum += dr + dg + db;
        if (dr + dg + db > 0) ++d.pixelsDiffering;
    }
    d.mean = a.pixels.empty() ? 0.0 : sum / double(a.pixels.size());
    return d;
}

}  // namespace gbl::ui
