// Full-screen lighting pass.
#include "passes/lighting_quad.h"

namespace gbl {

LightingOutput lightingQuadPass(LightingQuadInput const& in) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    in.program.use();
    bindDeferredInputs(in.program, in.deferred);
    in.triangle.draw();
    return {in.target.hdr};
}

}  // namespace gbl
