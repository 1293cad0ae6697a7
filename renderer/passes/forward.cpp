// Forward shading pass.
#include "passes/forward.h"

#include "gl/shader_bindings.h"

namespace gbl {

LightingOutput forwardPass(ForwardInput const& in, ForwardConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    in.program.use();
    in.program.set("uViewProj", config.viewProj);
    // Material textures use their own units (BIND_MATERIAL_*); the light buffer keeps BIND_LIGHTS.
    bindLights(in.program, in.lights);
    setShadingUniforms(in.program, config.shading);
    if (in.tiles) {
        in.program.set("uBinCap", in.tiles->cap);
        in.program.set("uTilesX", config.tilesX);
        // The blended surfaces read the lists binned from the near plane (TileBins::blended*).
        bool const blended = config.filter == MaterialFilter::Blended;
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_COUNTS,
                         (blended ? in.tiles->blendedCounts : in.tiles->counts).id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_LIGHTS,
                         (blended ? in.tiles->blendedLights : in.tiles->lights).id());
    }
    // Opaque: written depth; blended: alpha over, depth read only (config.states), farthest first.
    drawScene(in.scene, in.program, config.filter, config.normalMaps, config.states,
              config.backToFront ? std::optional(config.viewProj) : std::nullopt);
    if (in.tiles) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_COUNTS, 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_LIGHTS, 0);
    }
    return {in.target.hdr};
}

}  // namespace gbl
