// Geometry pass.
#include "passes/geometry.h"

namespace gbl {

// Blending must be off: the alpha channels carry data (specular, coverage).
GeometryOutput geometryPass(GeometryInput const& in, GeometryConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    applyGroup(config.states, 0);  // cleared by the executor (PassDecl::clears)
    in.program.use();
    in.program.set("uViewProj", config.viewProj);
    drawScene(in.scene, in.program, MaterialFilter::Opaque, config.normalMaps);
    return {in.target};
}

void depthPrepass(GeometryInput const& in, GeometryConfig const& config, gl::Framebuffer const& depthTarget) {
    glBindFramebuffer(GL_FRAMEBUFFER, depthTarget.id());
    applyGroup(config.states, 0);  // depth only; cleared by the executor (PassDecl::clears)
    in.program.use();
    in.program.set("uViewProj", config.viewProj);
    drawScene(in.scene, in.program, MaterialFilter::Opaque, config.normalMaps);
}

}  // namespace gbl
