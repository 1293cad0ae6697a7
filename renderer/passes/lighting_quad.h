// Full-screen lighting: every pixel loops over every light (cost = pixels x lights).
#pragma once

#include "gl/fullscreen_triangle.h"
#include "passes/shading_inputs.h"

namespace gbl {

struct LightingQuadInput {
    DeferredInputs deferred;
    gl::Program const& program;  // ProgramId::LightingQuad
    gl::FullscreenTriangle const& triangle;
    LitTarget target;  // the HDR image is cleared, then written
};

LightingOutput lightingQuadPass(LightingQuadInput const& in);

}  // namespace gbl
