// The blit step: brings the G-buffer depth into the lit target so forward-drawn things are
// hidden by the scene. Off leaves the lit target's depth cleared: light cubes then show
// through walls.
#pragma once

#include "core/pipeline_settings.h"
#include "gl/framebuffer.h"
#include "gl/fullscreen_triangle.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gpu/draw_state_gl.h"

#include <span>

namespace gbl {

struct DepthCopyInput {
    gl::Framebuffer const& source;  // Blit: the G-buffer's framebuffer, whose depth is read
    gl::Texture const& depth;       // Shader: the G-buffer's depth-stencil, sampled
    gl::Program const& program;     // ProgramId::DepthCopy (the shader variant)
    gl::FullscreenTriangle const& triangle;
    gl::Framebuffer const& target;  // its depth-stencil is cleared, then written
};
struct DepthCopyConfig {
    DepthCopy mode = DepthCopy::Blit;
    int width = 0;
    int height = 0;
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};

void depthCopyPass(DepthCopyInput const& in, DepthCopyConfig const& config);

}  // namespace gbl
