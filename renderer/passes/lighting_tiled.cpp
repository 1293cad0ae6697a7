// Tiled lighting pass.
#include "passes/lighting_tiled.h"
#include "gl/draw_count.h"

#include "core/tile_math.h"
#include "gl/shader_bindings.h"

namespace gbl {

LightingOutput lightingTiledPass(LightingTiledInput const& in, LightingTiledConfig const& c) {
    if (!c.binned)
        tileBinPass({in.bin, in.deferred.lights, in.deferred.gbuffer.depth, in.bins, in.caps},
                    {c.view, c.projection, c.width, c.height, c.nearPlane, c.farPlane});
    gl::Program const& p = in.program;
    p.use();
    bindDeferredInputs(p, in.deferred);
    bindTextureUnit(slot::BIND_DEPTH, GL_TEXTURE_2D, in.deferred.gbuffer.depth.id());
    p.set("uView", c.view);
    p.set("uInverseProjection", glm::inverse(c.projection));
    glUniform2i(p.uniform("uScreenSize"), c.width, c.height);
    p.set("uShade", c.shade ? 1 : 0);
    p.set("uWriteCoverage", c.coverage ? 1 : 0);
    p.set("uBinCap", in.bins.cap);
    // The bins and the tiles' depth ranges, as tileBinPass left them.
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_COUNTS, in.bins.counts.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_LIGHTS, in.bins.lights.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_DEPTH, in.bins.depth.id());
    bindLightImages(in.hdr, in.specular, in.coverage);
    TileGrid const grid = tileGrid(c.width, c.height);
    glDispatchCompute(GLuint(grid.tilesX), GLuint(grid.tilesY), 1);
    gl::countDispatch();
    // Later passes read the images as textures and framebuffer attachments.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    unbindLightImages();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_COUNTS, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_BIN_LIGHTS, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, slot::BIND_SSBO_TILE_DEPTH, 0);
    return {in.hdr};
}

}  // namespace gbl
