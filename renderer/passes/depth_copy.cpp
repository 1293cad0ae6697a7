// The blit step.
#include "passes/depth_copy.h"

#include "gl/shader_bindings.h"
#include "passes/shading_inputs.h"

namespace gbl {

void depthCopyPass(DepthCopyInput const& in, DepthCopyConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());  // depth and stencil cleared by the executor
    switch (config.mode) {
        case DepthCopy::Blit:
            glBindFramebuffer(GL_READ_FRAMEBUFFER, in.source.id());
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, in.target.id());
            // Both depth attachments are DEPTH32F_STENCIL8: blits require matching depth formats.
            glBlitFramebuffer(0, 0, config.width, config.height, 0, 0, config.width, config.height, GL_DEPTH_BUFFER_BIT,
                              GL_NEAREST);
            glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
            break;
        case DepthCopy::Shader:
            // Writes depth from a full-screen pass: works whatever the two depth formats are.
            applyGroup(config.states, 0);  // depth always written, no colour
            in.program.use();
            bindTextureUnit(slot::BIND_DEPTH, GL_TEXTURE_2D, in.depth.id());
            in.triangle.draw();
            break;
        case DepthCopy::Off:
            break;
    }
}

}  // namespace gbl
