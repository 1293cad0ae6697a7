// Full-screen lighting: every pixel loops over every light (cost = pixels x lights).
#pragma once

#include "gl/fullscreen_triangle.h"
#include "gpu/draw_state_gl.h"
#include "passes/shading_inputs.h"

#include <span>

namespace gbl {

struct LightingQuadInput {
    DeferredInputs deferred;
    gl::Program const& program;  // ProgramId::LightingQuad
    gl::FullscreenTriangle const& triangle;
    LitTarget target;                   // the HDR image is cleared, then written
    std::span<DrawState const> states;  // its declared draw groups (PassDecl::states), applied in order
};

LightingOutput lightingQuadPass(LightingQuadInput const& in);

}  // namespace gbl
