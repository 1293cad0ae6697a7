// The combine pass of `accumulation: split`.
#include "passes/light_combine.h"

#include "gl/shader_bindings.h"

namespace gbl {

LightingOutput lightCombinePass(LightCombineInput const& in) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    applyGroup(in.states, 0);
    in.program.use();
    bindGBuffer(in.gbuffer);
    setShadingUniforms(in.program, in.shading);
    bindTextureUnit(slot::BIND_DIFFUSE_LIGHT, GL_TEXTURE_2D, in.diffuseLight.id());
    bindTextureUnit(slot::BIND_SPECULAR_LIGHT, GL_TEXTURE_2D, in.specularLight.id());
    in.triangle.draw();
    return {in.target.hdr};
}

}  // namespace gbl
