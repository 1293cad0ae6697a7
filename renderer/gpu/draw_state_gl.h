// Fixed-function state from its description: apply(DrawState) is the one place the renderer's
// passes get depth, blend, cull, stencil and colour-write state from (sokol's sg_apply_pipeline).
#pragma once

#include "core/frame_passes.h"
#include "gl/gl_api.h"

#include <cstddef>
#include <span>

namespace gbl {

// Sets every piece of state a DrawState describes, whatever was set before.
void apply(DrawState const& state);

// Applies draw group `i` of a pass's declared states; a pass handed fewer groups than it draws is
// wired wrongly (the executor passes PassDecl::states).
void applyGroup(std::span<DrawState const> states, std::size_t i);

// The state of a blit or a clear: every write mask open, no test, no blend (what glClear and
// glBlitFramebuffer need to reach every bit).
inline constexpr DrawState kWriteAll{"write all",   DepthTest::Off,  true, Blend::Off,
                                     FaceCull::Off, StencilUse::Off, true};

// Clears `bits` (GL_COLOR_BUFFER_BIT, ...) of `fbo`: colour to zero, depth to 1, stencil to 0.
void clearFramebuffer(GLuint fbo, GLbitfield bits);

}  // namespace gbl
