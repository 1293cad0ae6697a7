// The passes of a deferred frame, in the order RendererImpl::render() calls them.
#include "renderer_impl.h"

#include <algorithm>

namespace gbl {

// --- geometry -------------------------------------------------------------------------------
// Fills the G-buffer. Blending must be off: the alpha channels carry data (specular, coverage).
void RendererImpl::geometryPass(FrameContext const& f) {
    glBindFramebuffer(GL_FRAMEBUFFER, targets.gbuffer.fbo.id());
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    gl::Program const& p = shaders.get("geometry");
    p.use();
    p.set("uViewProj", f.viewProj);
    drawScene(scene, p, MaterialFilter::Opaque, f.settings.normalMaps);
}

void RendererImpl::bindLightingInputs(gl::Program const& p, FrameContext const& f) const {
    GBuffer const& g = targets.gbuffer;
    GLuint const units[] = {g.position.id(), g.normal.id(), g.albedoSpec.id()};
    for (int i = 0; i < 3; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, units[i]);
    }
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_BUFFER, lights.texture.id());
    glActiveTexture(GL_TEXTURE0);
    p.set("uPosition", 0);
    p.set("uNormal", 1);
    p.set("uAlbedoSpec", 2);
    p.set("uLights", 3);
    p.set("uLightCount", lights.count);
    p.set("uViewPos", f.camera.position);
    p.set("uShininess", f.settings.shininess);
    p.set("uAmbient", f.settings.ambient);
}

// --- lighting: full-screen ---------------------------------------------------------------------
// Every pixel loops over every light: the cost is pixels x lights, whatever the radii.
void RendererImpl::lightingQuadPass(FrameContext const& f) {
    glBindFramebuffer(GL_FRAMEBUFFER, targets.litFbo.id());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    gl::Program const& p = shaders.get("lighting_quad");
    p.use();
    bindLightingInputs(p, f);
    glBindVertexArray(emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

// --- forward shading ---------------------------------------------------------------------------
// Opaque: the `forward` lighting mode (no G-buffer). Blended: transparent materials after the
// deferred lighting, depth-tested against the scene and not writing depth.
void RendererImpl::forwardShadingPass(FrameContext const& f, MaterialFilter filter) {
    glBindFramebuffer(GL_FRAMEBUFFER, targets.litFbo.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    if (filter == MaterialFilter::Opaque) {
        glClearColor(0, 0, 0, 0);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    } else {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    gl::Program const& p = shaders.get("forward");
    p.use();
    p.set("uViewProj", f.viewProj);
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_BUFFER, lights.texture.id());
    glActiveTexture(GL_TEXTURE0);
    p.set("uLights", 3);
    p.set("uLightCount", lights.count);
    p.set("uViewPos", f.camera.position);
    p.set("uShininess", f.settings.shininess);
    p.set("uAmbient", f.settings.ambient);
    // drawScene uses units 0..2 for material textures; the light buffer stays on unit 3.
    drawScene(scene, p, filter, f.settings.normalMaps);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

// --- the blit step -----------------------------------------------------------------------------
// Brings the G-buffer depth into the lit target so forward-drawn things are hidden by the
// scene. Off leaves the lit target's depth cleared: light cubes then show through walls.
void RendererImpl::depthCopyPass(FrameContext const& f) {
    glBindFramebuffer(GL_FRAMEBUFFER, targets.litFbo.id());
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    switch (f.settings.depthCopy) {
    case DepthCopy::Blit:
        glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.gbuffer.fbo.id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.litFbo.id());
        // Both depth attachments are DEPTH32F_STENCIL8: blits require matching depth formats.
        glBlitFramebuffer(0, 0, targets.width, targets.height, 0, 0, targets.width, targets.height,
                          GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, targets.litFbo.id());
        break;
    case DepthCopy::Shader: {
        // Writes depth from a full-screen pass: works whatever the two depth formats are.
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        glDepthMask(GL_TRUE);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        gl::Program const& p = shaders.get("depth_copy");
        p.use();
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, targets.gbuffer.depth.id());
        p.set("uDepth", 0);
        glBindVertexArray(emptyVao.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthFunc(GL_LESS);
        break;
    }
    case DepthCopy::Off: break;
    }
}

// --- light cubes -------------------------------------------------------------------------------
void RendererImpl::lightCubesPass(FrameContext const& f) {
    if (lights.count == 0) return;
    glBindFramebuffer(GL_FRAMEBUFFER, targets.litFbo.id());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    gl::Program const& p = shaders.get("light_cube");
    p.use();
    p.set("uViewProj", f.viewProj);
    p.set("uCubeSize", lightCubeHalfSize());
    p.set("uEmissive", kLightCubeEmissive);
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_BUFFER, lights.texture.id());
    glActiveTexture(GL_TEXTURE0);
    p.set("uLights", 3);
    glBindVertexArray(cubeVao.id());
    glDrawArraysInstanced(GL_TRIANGLES, 0, 36, lights.count);
    glBindVertexArray(0);
}

// --- display -----------------------------------------------------------------------------------
void RendererImpl::displayPass(FrameContext const& f) {
    ViewParams params;
    params.view = f.settings.view;
    glBindFramebuffer(GL_FRAMEBUFFER, targets.displayFbo.id());
    drawViewInto(params, f.camera, f.settings, targets.width, targets.height);
}

void RendererImpl::drawView(ViewParams const& params, Camera const& camera, ViewTarget& target) {
    if (targets.empty()) return;
    if (!target.texture || target.texture.width() != targets.width || target.texture.height() != targets.height) {
        target.texture = gl::Texture::create2D(GL_RGBA8, targets.width, targets.height, "view");
        target.fbo = gl::Framebuffer::create({&target.texture}, nullptr, "view");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
    drawViewInto(params, camera, lastFrame.settings, targets.width, targets.height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void RendererImpl::drawViewInto(ViewParams const& params, Camera const& camera, PipelineSettings const& settings,
                                int width, int height) {
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    gl::Program const& p = shaders.get("view");
    p.use();
    GLuint const textures[] = {targets.gbuffer.position.id(), targets.gbuffer.normal.id(), targets.gbuffer.albedoSpec.id(),
                               targets.gbuffer.depth.id(),    targets.lighting.id(),       targets.coverage.id()};
    char const* names[] = {"uPosition", "uNormal", "uAlbedoSpec", "uDepth", "uLighting", "uCoverage"};
    for (int i = 0; i < 6; ++i) {
        glActiveTexture(GLenum(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        p.set(names[i], i);
    }
    glActiveTexture(GL_TEXTURE0);
    p.set("uView", int(params.view));
    p.set("uTonemap", int(settings.tonemap));
    p.set("uExposure", settings.exposure);
    p.set("uChannelMask", glm::vec4(params.channelMask & 1 ? 1 : 0, params.channelMask & 2 ? 1 : 0,
                                    params.channelMask & 4 ? 1 : 0, params.channelMask & 8 ? 1 : 0));
    p.set("uRangeMin", params.rangeMin);
    p.set("uRangeMax", params.rangeMax);
    p.set("uNormalDisplay", int(params.normalDisplay));
    p.set("uNear", camera.nearPlane);
    p.set("uFar", camera.farPlane);
    p.set("uHeatMax", params.heatMax);
    p.set("uColormap", int(params.colormap));  // viewer tools (shaders/view_tools.glsl)
    p.set("uOverlays", int(params.overlays));
    glBindVertexArray(emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glEnable(GL_CULL_FACE);
}

float RendererImpl::lightCubeHalfSize() const {
    // Small against the scene so cubes mark positions without hiding what they light.
    return std::max(sceneRadius * 0.006f, 1e-4f);
}

}  // namespace gbl
