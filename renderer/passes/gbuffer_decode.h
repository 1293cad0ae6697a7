// G-buffer decode pass: the position and normal the lighting reads, as RGBA32F images, for
// read-back, the pixel inspector and export (shaders/gbuffer_decode.frag). Its msaa variants decode
// one sample (with its material too) or count the distinct surfaces among the samples (docs/msaa.md).
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

// RGBA32F textures (position, normal; with `material`, albedo + specular and emissive + occlusion
// as well, which the msaa sample variant writes) and their framebuffer, of any size. The counts
// variant writes its count to position's red channel.
struct DecodedGBuffer {
    gl::Texture position;
    gl::Texture normal;
    gl::Texture albedoSpec;  // empty without `material`
    gl::Texture emissiveAo;  // empty without `material`
    gl::Framebuffer fbo;
    int width = 0;
    int height = 0;
};
DecodedGBuffer createDecodedGBuffer(int width, int height, bool material = false);

struct GBufferDecodeInput {
    GBufferTextures gbuffer;
    gl::Program const& program;  // ProgramId::GBufferDecode, or its msaa variant (msaa G-buffer textures)
    gl::FullscreenTriangle const& triangle;
    DecodedGBuffer const& target;
};
struct GBufferDecodeConfig {
    glm::mat4 inverseViewProj{1.0f};    // of the frame the G-buffer holds
    glm::ivec2 pixelOffset{0};          // G-buffer pixel written to the target's (0, 0)
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
    int sample = 0;                     // msaa variant: the sample decoded (uSample)
    glm::vec3 eye{0.0f};                // msaa counts variant: the eye its position threshold is relative to
};

void gbufferDecodePass(GBufferDecodeInput const& in, GBufferDecodeConfig const& config);

}  // namespace gbl
