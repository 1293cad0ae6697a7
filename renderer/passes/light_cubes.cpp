// Light cubes pass: an overlay on the display image.
#include "passes/light_cubes.h"
#include "gl/draw_count.h"

#include "core/frame_types.h"

namespace gbl {

void lightCubesPass(LightCubesInput const& in, LightCubesConfig const& config) {
    if (in.lights.count == 0) return;
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
    applyGroup(config.states, 0);
    in.program.use();
    in.program.set("uViewProj", config.viewProj);
    in.program.set("uCubeSize", config.halfSize);
    in.program.set("uEmissive", kLightCubeEmissive);
    setTonemapUniforms(in.program, config.tonemap);
    bindLights(in.program, in.lights);
    glBindVertexArray(in.cube.id());
    glDrawArraysInstanced(GL_TRIANGLES, 0, 36, in.lights.count);
    gl::countDraw(12u * std::uint64_t(in.lights.count));  // 36 vertices a cube
    glBindVertexArray(0);
}

}  // namespace gbl
