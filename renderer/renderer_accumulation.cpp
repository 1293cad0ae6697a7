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
    int const split = splitAccumulation(f) ? 1 : 0;
    if (!split && splitTargetsWritten) {
        // Their views and read-backs show zero after a single-target frame, not a stale split one.
        glBindFramebuffer(GL_FRAMEBUFFER, targets.splitFbo.id());
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    splitTargetsWritten = split != 0;
    // Every program that adds lights reads the flag (shaders/light_accumulation.glsl); the optional
    // ones only once their mode has built them.
    std::vector<ProgramId> ids{ProgramId::LightingQuad};
    if (f.settings.mode == LightingMode::Volumes) ids.push_back(ProgramId::LightVolume);
    if (f.settings.mode == LightingMode::Tiled) ids.push_back(ProgramId::LightingTiled);
    if (f.settings.mode == LightingMode::Clustered) ids.push_back(ProgramId::ClusterShade);
    for (ProgramId id : ids) {
        gl::Program const& p = shaders.get(id);
        p.use();
        p.set("uSplitAccumulation", split);
    }
    // The compute modes write specular light to image unit 2 (diffuse light to unit 0, as the
    // lit image in single frames); bound in both cases so the declared image is always valid.
    if (caps.computeShaders)
        glBindImageTexture(slot::BIND_IMAGE_SPECULAR_LIGHT, targets.specularLight.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                           GL_RGBA16F);
}

void RendererImpl::combineLights(FrameContext const& f) {
    lightCombinePass({targets.gbuffer, shadingUniforms(f), targets.diffuseLight, targets.specularLight,
                      shaders.get(ProgramId::LightCombine), triangle, litTarget()});
}

}  // namespace gbl
