// Light-volume wireframes pass.
#include "passes/wireframes.h"

#include "gl/shader_bindings.h"

namespace gbl {

void wireframesPass(WireframesInput const& in, WireframesConfig const& config) {
    int const total = in.volumes.outsideCount + in.volumes.insideCount;
    if (total == 0) return;
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    gl::Program const& p = in.program;
    p.use();
    bindLights(p, in.lights);
    bindTextureUnit(slot::BIND_VOLUME_INSTANCES, GL_TEXTURE_BUFFER, in.volumes.instancesTbo.id());
    p.set("uViewProj", config.viewProj);
    p.set("uEnclosingScale", in.volumes.enclosingScale);
    p.set("uFirstInstance", 0);
    p.set("uWireIntensity", config.intensity);
    glBindVertexArray(in.volumes.lineVao.id());
    glDrawElementsInstanced(GL_LINES, in.volumes.lineIndexCount, GL_UNSIGNED_INT, nullptr, total);
    glBindVertexArray(0);
    glEnable(GL_CULL_FACE);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

}  // namespace gbl
