// Tiled lighting: a compute pass over 16x16 tiles (OpenGL 4.3), see shaders/lighting_tiled.comp.
#include "renderer_impl.h"

#include "core/tile_math.h"

namespace gbl {

void RendererImpl::lightingTiledPass(FrameContext const& f, bool shade, bool coverage) {
    if (!caps.computeShaders) return;  // callers check; a 3.3 context has no compute stage
    initLightVolumes();
    gl::Program const& p = shaders.get("lighting_tiled");
    p.use();
    bindLightingInputs(p, f);
    glActiveTexture(GL_TEXTURE4);
    glBindTexture(GL_TEXTURE_2D, targets.gbuffer.depth.id());
    glActiveTexture(GL_TEXTURE0);
    p.set("uDepth", 4);
    p.set("uView", f.view);
    p.set("uInverseProjection", glm::inverse(f.projection));
    glUniform2i(p.uniform("uScreenSize"), targets.width, targets.height);
    p.set("uNear", f.camera.nearPlane);
    p.set("uFar", f.camera.farPlane);
    p.set("uShade", shade ? 1 : 0);
    p.set("uWriteCoverage", coverage ? 1 : 0);
    // Both image units are bound whatever the flags, so the program's declared images are valid.
    glBindImageTexture(0, targets.lighting.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(1, targets.coverage.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
    TileGrid const grid = tileGrid(targets.width, targets.height);
    glDispatchCompute(GLuint(grid.tilesX), GLuint(grid.tilesY), 1);
    // Later passes read the images as textures and framebuffer attachments.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
}

}  // namespace gbl
