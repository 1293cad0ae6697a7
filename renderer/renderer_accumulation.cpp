// Accumulation targets: where the lighting modes add their lights, and the combine pass of
// `accumulation: split` (docs/lighting.md, "Accumulation targets").
#include "renderer_impl.h"

#include "gl/shader_bindings.h"
#include "passes/light_combine.h"

namespace gbl {

bool RendererImpl::splitAccumulation(FrameContext const& f) const {
    return f.settings.accumulation == LightAccumulation::Split && f.settings.mode != LightingMode::Forward;
}

LitTarget RendererImpl::quadTarget(FrameContext const& f) const {
    return splitAccumulation(f) ? LitTarget{targets.splitFbo, targets.diffuseLight} : litTarget();
}

LitTarget RendererImpl::volumeTarget(FrameContext const& f) const {
    return splitAccumulation(f) ? LitTarget{targets.splitVolumeFbo, targets.diffuseLight}
                                : LitTarget{targets.volumeFbo, targets.lighting};
}

gl::Texture const& RendererImpl::lightingImage(FrameContext const& f) const {
    return splitAccumulation(f) ? targets.diffuseLight : targets.lighting;
}

void RendererImpl::prepareAccumulation(FrameContext const& f) {
    bool const split = splitAccumulation(f);
    if (!split && splitTargetsWritten) {
        // Their views and read-backs show zero after a single-target frame, not a stale split one.
        glBindFramebuffer(GL_FRAMEBUFFER, targets.splitFbo.id());
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    splitTargetsWritten = split;
}

void RendererImpl::combineLights(FrameContext const& f) {
    lightCombinePass({targets.gbuffer, shadingUniforms(f), targets.diffuseLight, targets.specularLight,
                      shaders.get(ProgramId::LightCombine), triangle, litTarget()});
}

}  // namespace gbl
