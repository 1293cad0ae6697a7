// Views of the frame into a ViewTarget: the target sized to the frame, the display image copied,
// and drawView (data views, coverage views recounted from the frame they describe).
#include "renderer_impl.h"

#include "passes/view.h"
#include "passes/volume_depth.h"

namespace gbl {

// Allocates `target` at the frame size when it is not already.
void RendererImpl::sizeViewTarget(ViewTarget& target) const {
    if (!target.texture || target.texture.width() != targets.width || target.texture.height() != targets.height) {
        target.texture = gl::Texture::create2D(GL_RGBA8, targets.width, targets.height, "view");
        target.fbo = gl::Framebuffer::create({&target.texture}, nullptr, "view");
    }
}

void RendererImpl::copyDisplay(ViewTarget& target) {
    if (targets.empty()) return;
    sizeViewTarget(target);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.displayFbo.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.fbo.id());
    glBlitFramebuffer(0, 0, targets.width, targets.height, 0, 0, targets.width, targets.height, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// A view of the frame `frame` describes (the last one rendered): coverage views recount from
// it, so nothing here depends on what the last render() happened to compute. No overlays: they
// belong to the frame's own display image (copyDisplay).
void RendererImpl::drawView(ViewParams const& params, FrameInput const& frame, ViewTarget& target) {
    if (targets.empty()) return;
    sizeViewTarget(target);
    FrameContext f = frameContext(frame);
    if (modeUnavailable(f.settings.mode)) f.settings.mode = LightingMode::Quad;  // as render() ran it
    if (viewNeedsCoverage(params.view)) {
        f.settings.view = params.view;
        lights.upload(f.lights);
        // The volume counts test against the copy, which only a volumes frame refreshed.
        if (f.settings.mode == LightingMode::Volumes && targets.volumeDepth)
            volumeDepthPass({targets.gbuffer, targets.volumeFbo}, {targets.width, targets.height});
        if (shaderChecks) shaderChecks.begin();
        runCoverage(f);
        if (shaderChecks) shaderChecks.collect();
    }
    viewPass({targets.gbuffer, targets.lighting, targets.coverage, targets.diffuseLight, targets.specularLight,
              viewProgram(params.view), triangle, target.fbo},
             {params, f.settings.tonemap, f.settings.exposure, f.camera.nearPlane, f.camera.farPlane, targets.width,
              targets.height, glm::inverse(f.viewProj)});
}

}  // namespace gbl
