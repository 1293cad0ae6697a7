// The passes of prepass mode (deferred lighting).
#include "passes/prepass.h"

#include "gl/shader_bindings.h"
#include "passes/light_volumes.h"

namespace gbl {

void prepassGeometryPass(PrepassGeometryInput const& in, PrepassSceneConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
    in.program.use();  // cleared by the executor (PassDecl::clears)
    in.program.set("uViewProj", config.viewProj);
    in.program.set("uShininess", config.shading.shininess);
    drawScene(in.scene, in.program, MaterialFilter::Opaque, config.normalMaps, config.states);
}

void prepassLightPass(PrepassLightInput const& in, ShadingUniforms const& shading, PrepassLightVolumes const* volumes) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.id());
    applyGroup(in.states, 0);  // cleared by the executor (PassDecl::clears)
    in.program.use();
    bindTextureUnit(slot::BIND_PREPASS_NORMAL, GL_TEXTURE_2D, in.normalExponent.id());
    bindTextureUnit(slot::BIND_DEPTH, GL_TEXTURE_2D, in.depth.id());
    bindLights(in.program, in.lights);
    setShadingUniforms(in.program, shading);
    // With volumes the full-screen draw adds only the directional lights, which have none.
    if (volumes) in.program.set("uLightCount", 0);
    in.triangle.draw();
    if (!volumes) return;
    drawLightVolumes({volumes->deferred, volumes->volumes, volumes->program, volumes->stencilMark}, volumes->viewProj,
                     volumes->cull, in.states.subspan(1));
}

LightingOutput prepassShadingPass(PrepassShadingInput const& in, PrepassSceneConfig const& config) {
    glBindFramebuffer(GL_FRAMEBUFFER, in.target.fbo.id());
    in.program.use();  // cleared by the executor (PassDecl::clears)
    in.program.set("uViewProj", config.viewProj);
    setShadingUniforms(in.program, config.shading);
    bindTextureUnit(slot::BIND_DIFFUSE_LIGHT, GL_TEXTURE_2D, in.diffuseLight.id());
    bindTextureUnit(slot::BIND_SPECULAR_LIGHT, GL_TEXTURE_2D, in.specularLight.id());
    drawScene(in.scene, in.program, MaterialFilter::Opaque, config.normalMaps, config.states);
    return {in.target.hdr};
}

}  // namespace gbl
