// Views of the frame into a ViewTarget: the target sized to the frame, the display image copied,
// and drawView (data views, coverage views recounted from the frame they describe).
#include "renderer_impl.h"

#include <algorithm>

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

// A view of the frame `input` describes (the last one rendered): its declared view passes
// (viewPasses), so coverage views recount from it and nothing here depends on what the last
// render() happened to compute. No overlays: they belong to the frame's own display image
// (copyDisplay).
void RendererImpl::drawView(ViewParams const& params, FrameInput const& input, ViewTarget& target) {
    if (targets.empty()) return;
    sizeViewTarget(target);
    FrameRecord frame;
    frame.f = frameContext(input);
    if (modeUnavailable(frame.f.settings.mode)) frame.f.settings.mode = LightingMode::Quad;  // as render() ran it
    frame.f.settings.view = params.view;
    frame.shading = shadingUniforms(frame.f);
    frame.view = params;
    std::vector<PassDecl> const passes = viewPasses(frame.f.settings);
    bool const lit = std::any_of(passes.begin(), passes.end(), [](PassDecl const& p) {
        return std::find(p.samples.begin(), p.samples.end(), Resource::Lights) != p.samples.end();
    });
    if (lit) lights.upload(frame.f.lights, caps);
    if (shaderChecks) shaderChecks.begin();
    glViewport(0, 0, targets.width, targets.height);
    runPasses(passes, frame, {targets, &target.fbo});
    if (shaderChecks) shaderChecks.collect();
}

}  // namespace gbl
