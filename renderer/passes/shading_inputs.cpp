// Binding the inputs shared by the lighting passes.
#include "passes/shading_inputs.h"

#include "gl/shader_bindings.h"

namespace gbl {

void bindTextureUnit(int unit, GLenum target, GLuint texture) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(target, texture);
    glActiveTexture(GL_TEXTURE0);
}

void bindGBuffer(GBuffer const& g) {
    bindTextureUnit(slot::BIND_GBUFFER_POSITION, GL_TEXTURE_2D, g.position.id());
    bindTextureUnit(slot::BIND_GBUFFER_NORMAL, GL_TEXTURE_2D, g.normal.id());
    bindTextureUnit(slot::BIND_GBUFFER_ALBEDO_SPEC, GL_TEXTURE_2D, g.albedoSpec.id());
    bindTextureUnit(slot::BIND_GBUFFER_EMISSIVE, GL_TEXTURE_2D, g.emissive.id());
    bindTextureUnit(slot::BIND_DEPTH, GL_TEXTURE_2D, g.depth.id());
}

void bindLights(gl::Program const& p, LightBuffer const& lights) {
    bindTextureUnit(slot::BIND_LIGHTS, GL_TEXTURE_BUFFER, lights.texture.id());
    p.set("uLightCount", lights.count);
    p.set("uDirectionalCount", int(lights.directional.size()));
    if (!lights.directional.empty())
        glUniform1iv(p.uniform("uDirectionalLights[0]"), GLsizei(lights.directional.size()), lights.directional.data());
}

void setShadingUniforms(gl::Program const& p, ShadingUniforms const& s) {
    p.set("uViewPos", s.viewPosition);
    p.set("uShininess", s.shininess);
    p.set("uAmbient", s.ambient);
    p.set("uEmissiveWeight", s.emissiveWeight);
    p.set("uInverseViewProj", s.inverseViewProj);
}

void bindDeferredInputs(gl::Program const& p, DeferredInputs const& in) {
    bindGBuffer(in.gbuffer);
    bindLights(p, in.lights);
    setShadingUniforms(p, in.shading);
}

}  // namespace gbl
