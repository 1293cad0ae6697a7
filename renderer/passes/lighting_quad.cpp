// Full-screen lighting pass.
#include "passes/lighting_quad.h"

namespace gbl {

LightingOutput lightingQuadPass(LightingQuadInput const& in) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    applyGroup(in.states, 0);  // cleared by the executor (PassDecl::clears)
    in.program.use();
    bindDeferredInputs(in.program, in.deferred);
    in.triangle.draw();
    return {in.target.hdr};
}

}  // namespace gbl
