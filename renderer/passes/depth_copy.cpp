// The blit step.
#include "passes/depth_copy.h"

#include "gl/shader_bindings.h"
#include "passes/shading_inputs.h"

namespace gbl {

void depthCopyPass(DepthCopyInput const& in, DepthCopyConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    switch (config.mode) {
        case DepthCopy::Blit:
            glBindFramebuffer(GL_READ_FRAMEBUFFER, in.gbuffer.fbo.id());
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, in.target.id());
            // Both depth attachments are DEPTH32F_STENCIL8: blits require matching depth formats.
            glBlitFramebuffer(0, 0, config.width, config.height, 0, 0, config.width, config.height, GL_DEPTH_BUFFER_BIT,
                              GL_NEAREST);
            glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
            break;
        case DepthCopy::Shader:
            // Writes depth from a full-screen pass: works whatever the two depth formats are.
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
            glDepthMask(GL_TRUE);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            in.program.use();
            bindTextureUnit(slot::BIND_DEPTH, GL_TEXTURE_2D, in.gbuffer.depth.id());
            in.triangle.draw();
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glDepthFunc(GL_LESS);
            break;
        case DepthCopy::Off:
            break;
    }
}

}  // namespace gbl
