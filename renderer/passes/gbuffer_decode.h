// G-buffer decode pass: the position and normal the lighting reads, as RGBA32F images, for
// read-back, the pixel inspector and export (shaders/gbuffer_decode.frag).
#pragma once

#include "gl/framebuffer.h"
#include "gl/fullscreen_triangle.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gpu/draw_state_gl.h"
#include "gpu/frame_resources.h"

#include <glm/glm.hpp>

#include <span>

namespace gbl {

// Two RGBA32F textures (position, normal) and their framebuffer, of any size.
struct DecodedGBuffer {
    gl::Texture position;
    gl::Texture normal;
    gl::Framebuffer fbo;
    int width = 0;
    int height = 0;
};
DecodedGBuffer createDecodedGBuffer(int width, int height);

struct GBufferDecodeInput {
    GBufferTextures gbuffer;
    gl::Program const& program;  // ProgramId::GBufferDecode
    gl::FullscreenTriangle const& triangle;
    DecodedGBuffer const& target;
};
struct GBufferDecodeConfig {
    glm::mat4 inverseViewProj{1.0f};    // of the frame the G-buffer holds
    glm::ivec2 pixelOffset{0};          // G-buffer pixel written to the target's (0, 0)
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};

void gbufferDecodePass(GBufferDecodeInput const& in, GBufferDecodeConfig const& config);

}  // namespace gbl
