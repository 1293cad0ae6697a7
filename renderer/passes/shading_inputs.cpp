// Binding the inputs shared by the lighting passes.
#include "passes/shading_inputs.h"

#include "gl/shader_bindings.h"

namespace gbl {

void bindTextureUnit(int unit, GLenum target, GLuint texture) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(target, texture);
    glActiveTexture(GL_TEXTURE0);
}

void bindGBuffer(GBufferTextures const& g) {
    // Each on its own target: GL_TEXTURE_2D, or GL_TEXTURE_2D_MULTISAMPLE for the msaa G-buffer.
    bindTextureUnit(slot::BIND_GBUFFER_POSITION, g.position.target(), g.position.id());
    bindTextureUnit(slot::BIND_GBUFFER_NORMAL, g.normal.target(), g.normal.id());
    bindTextureUnit(slot::BIND_GBUFFER_ALBEDO_SPEC, g.albedoSpec.target(), g.albedoSpec.id());
    bindTextureUnit(slot::BIND_GBUFFER_EMISSIVE, g.emissive.target(), g.emissive.id());
    bindTextureUnit(slot::BIND_DEPTH, g.depth.target(), g.depth.id());
}

void bindLights(gl::Program const& p, LightBuffer const& lights) {
    bindTextureUnit(slot::BIND_LIGHTS, lights.texture.target(), lights.texture.id());
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
    p.set("uSplitAccumulation", s.splitAccumulation ? 1 : 0);
    p.set("uShadingModel", int(s.model));
    p.set("uCutAtRadius", s.cutAtRadius ? 1 : 0);
}

void setTonemapUniforms(gl::Program const& p, DisplayTonemap const& t) {
    p.set("uTonemap", int(t.tonemap));
    p.set("uExposure", t.exposure);
}

void bindLightImages(gl::Texture const& lit, gl::Texture const& specular, gl::Texture const& coverage) {
    glBindImageTexture(slot::BIND_IMAGE_LIGHTING, lit.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(slot::BIND_IMAGE_SPECULAR_LIGHT, specular.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(slot::BIND_IMAGE_COVERAGE, coverage.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
}

void unbindLightImages() {
    glBindImageTexture(slot::BIND_IMAGE_LIGHTING, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(slot::BIND_IMAGE_SPECULAR_LIGHT, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(slot::BIND_IMAGE_COVERAGE, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32F);
}

void bindDeferredInputs(gl::Program const& p, DeferredInputs const& in) {
    bindGBuffer(in.gbuffer);
    bindLights(p, in.lights);
    setShadingUniforms(p, in.shading);
}

}  // namespace gbl
