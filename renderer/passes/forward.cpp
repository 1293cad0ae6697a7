// Forward shading pass.
#include "passes/forward.h"

namespace gbl {

LightingOutput forwardPass(ForwardInput const& in, ForwardConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    if (config.filter == MaterialFilter::Opaque) {
        glClearColor(0, 0, 0, 0);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    } else {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    in.program.use();
    in.program.set("uViewProj", config.viewProj);
    // Material textures use their own units (BIND_MATERIAL_*); the light buffer keeps BIND_LIGHTS.
    bindLights(in.program, in.lights);
    setShadingUniforms(in.program, config.shading);
    drawScene(in.scene, in.program, config.filter, config.normalMaps);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    return {in.target.hdr};
}

}  // namespace gbl
