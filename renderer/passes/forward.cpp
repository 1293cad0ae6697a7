// Forward shading pass.
#include "passes/forward.h"

namespace gbl {

LightingOutput forwardPass(ForwardInput const& in, ForwardConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    in.program.use();
    in.program.set("uViewProj", config.viewProj);
    // Material textures use their own units (BIND_MATERIAL_*); the light buffer keeps BIND_LIGHTS.
    bindLights(in.program, in.lights);
    setShadingUniforms(in.program, config.shading);
    // Opaque: written depth; blended: alpha over, depth read only (config.states), farthest first.
    drawScene(in.scene, in.program, config.filter, config.normalMaps, config.states,
              config.backToFront ? std::optional(config.viewProj) : std::nullopt);
    return {in.target.hdr};
}

}  // namespace gbl
