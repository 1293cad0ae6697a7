// View pass.
#include "passes/view.h"

#include "core/cluster_math.h"
#include "gl/shader_bindings.h"
#include "passes/shading_inputs.h"

namespace gbl {

void viewPass(ViewInput const& in, ViewConfig const& c) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
    glViewport(0, 0, c.width, c.height);
    applyGroup(c.states, 0);
    gl::Program const& p = in.program;
    p.use();
    bindGBuffer(in.gbuffer);
    bool const thin = in.thinNormal && in.thinDepth;
    bindTextureUnit(slot::BIND_DEPTH, GL_TEXTURE_2D, thin ? in.thinDepth->id() : in.gbuffer.depth.id());
    bindTextureUnit(slot::BIND_PREPASS_NORMAL, GL_TEXTURE_2D, thin ? in.thinNormal->id() : 0);
    bindTextureUnit(slot::BIND_LIGHTING, GL_TEXTURE_2D, in.hdr.id());
    bindTextureUnit(slot::BIND_COVERAGE, GL_TEXTURE_2D, in.coverage.id());
    bindTextureUnit(slot::BIND_DIFFUSE_LIGHT, GL_TEXTURE_2D, in.diffuseLight.id());
    bindTextureUnit(slot::BIND_SPECULAR_LIGHT, GL_TEXTURE_2D, in.specularLight.id());
    ViewParams const& v = c.params;
    p.set("uView", int(v.view));
    p.set("uThinGBuffer", thin ? 1 : 0);
    setTonemapUniforms(p, {c.tonemap, c.exposure});
    p.set("uChannelMask", glm::vec4(v.channelMask & 1 ? 1 : 0, v.channelMask & 2 ? 1 : 0, v.channelMask & 4 ? 1 : 0,
                                    v.channelMask & 8 ? 1 : 0));
    p.set("uRangeMin", v.rangeMin);
    p.set("uRangeMax", v.rangeMax);
    p.set("uNormalDisplay", int(v.normalDisplay));
    p.set("uNear", c.nearPlane);
    p.set("uFar", c.farPlane);
    p.set("uClusterSlices", kClusterSlices);
    p.set("uInverseViewProj", c.inverseViewProj);
    p.set("uColormap", int(v.colormap));  // viewer tools (shaders/view_tools.glsl)
    p.set("uOverlays", int(v.overlays));
    in.triangle.draw();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace gbl
