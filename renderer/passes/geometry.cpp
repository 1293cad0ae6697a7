// Geometry pass.
#include "passes/geometry.h"

namespace gbl {

// Blending must be off: the alpha channels carry data (specular, coverage).
GeometryOutput geometryPass(GeometryInput const& in, GeometryConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    in.program.use();
    in.program.set("uViewProj", config.viewProj);
    drawScene(in.scene, in.program, MaterialFilter::Opaque, config.normalMaps);
    return {in.target};
}

}  // namespace gbl
