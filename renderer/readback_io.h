// Read-back helpers shared by the renderer's read-back files (renderer_readback.cpp,
// renderer_readback_thin.cpp): images come back as floats, rows top to bottom.
#pragma once

#include "renderer_impl.h"

namespace gbl {

// A whole framebuffer attachment: one channel reads depth (in the browser: the red channel of a
// colour attachment), two read RG, four RGBA.
FloatImage readFramebuffer(GLuint fbo, GLenum attachment, int width, int height, int channels);
// The window-space depth of `fbo`'s depth attachment, whose texture is `depth` (the browser reads
// no depth: it draws the texture into a float target and reads that).
FloatImage readDepthImage(ReadbackContext const& r, GLuint fbo, gl::Texture const& depth);
// ... of one pixel, x and glY in GL's bottom-left origin.
float readDepthTexel(ReadbackContext const& r, GLuint fbo, gl::Texture const& depth, int x, int glY);
// One pixel of `fbo`'s colour `attachment` as RGBA floats, x and glY in GL's bottom-left origin.
void readPixelColor(GLuint fbo, GLenum attachment, int x, int glY, glm::vec4& out);
#ifdef __EMSCRIPTEN__
// The bound read framebuffer's colour `attachment` over a rectangle as RGBA floats, rows bottom to
// top (WebGL2 reads each format only in the type it implies).
std::vector<float> readRgbaAsFloats(GLenum attachment, int x, int y, int width, int height);
#endif

}  // namespace gbl
