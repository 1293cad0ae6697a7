// Every screen-sized target of the frame, rebuilt together by resizeTargets().
#pragma once

#include "gl/framebuffer.h"
#include "gl/texture.h"

#include <optional>
#include <string>

namespace gbl {

struct GBuffer {
    gl::Texture position;    // RGBA16F world position, w = 1 where drawn
    gl::Texture normal;      // RGBA16F world normal, w = 1 where drawn
    gl::Texture albedoSpec;  // RGBA8 albedo rgb + specular a
    gl::Texture depth;       // DEPTH32F_STENCIL8, sampled by the depth views and the shader copy
    gl::Framebuffer fbo;
};

struct RenderTargets {
    int width = 0;
    int height = 0;
    GBuffer gbuffer;
    gl::Texture lighting;    // RGBA16F HDR
    gl::Texture litDepth;    // DEPTH32F_STENCIL8: same format as the G-buffer depth so blits work
    gl::Framebuffer litFbo;  // lighting + litDepth: lighting passes and the forward pass
    // lighting + the G-buffer's depth-stencil: light volumes test against the scene depth (and
    // use its stencil) without needing the blit step.
    gl::Framebuffer volumeFbo;
    gl::Texture coverage;  // RG32F: x = volumes that covered the pixel, y = lights that lit it
    gl::Framebuffer coverageFbo;
    gl::Texture display;  // RGBA8 final image
    gl::Framebuffer displayFbo;

    bool empty() const { return width == 0 || height == 0; }
};

// Creates all targets at w x h (0 x 0 gives empty targets). Returns the first incomplete
// framebuffer's error, if any.
std::optional<std::string> createRenderTargets(int width, int height, RenderTargets& out);

}  // namespace gbl
