// Geometry pass.
#include "passes/geometry.h"

namespace gbl {

// Blending must be off: the alpha channels carry data (specular, coverage).
GeometryOutput geometryPass(GeometryInput const& in, GeometryConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
    in.program.use();  // cleared by the executor (PassDecl::clears)
    in.program.set("uViewProj", config.viewProj);
    drawScene(in.scene, in.program, MaterialFilter::Opaque, config.normalMaps, config.states);
    return {in.target};
}

}  // namespace gbl
