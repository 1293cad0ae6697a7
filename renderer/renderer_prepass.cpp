// prepass mode's run functions (deferred lighting, docs/deferred_lighting.md): each draws into what
// its declaration (core/frame_passes_prepass.cpp) names, resolved by the executor (PassRun).
#include "renderer_impl.h"

#include "passes/prepass.h"

namespace gbl {

void RendererImpl::runThinGBuffer(FrameRecord& frame, PassRun const& r) {
    prepassGeometryPass({scene, shaders.get(ProgramId::PrepassGeometry), *r.fbo},
                        {frame.f.viewProj, frame.shading, frame.f.settings.normalMaps, r.decl.states});
}

// The lighting pass of a prepass frame (runLighting hands it over): full screen, or with a declared
// depth-stencil (the copy of the thin depth) the light volumes after the directional lights.
void RendererImpl::runPrepassLight(FrameRecord& frame, PassRun const& r) {
    gl::Texture const& depth = r.io.texture(Resource::LitDepth);
    PrepassLightInput const in{r.io.texture(Resource::PrepassNormal),
                               depth,
                               lights,
                               shaders.get(ProgramId::PrepassLight),
                               triangle,
                               *r.fbo,
                               r.decl.states};
    if (!r.decl.depthStencil) {
        prepassLightPass(in, frame.shading);
        return;
    }
    // The volumes' programs sample the thin pass's depth on the G-buffer depth's unit; the rest of the
    // G-buffer bound beside it is never read.
    GBufferTextures const g = r.io.gbuffer();
    PrepassLightVolumes const v{{{g.position, g.normal, g.albedoSpec, g.emissive, depth}, lights, frame.shading},
                                volumes,
                                shaders.get(ProgramId::PrepassLightVolume),
                                shaders.get(ProgramId::LightVolumeStencil),
                                frame.f.viewProj,
                                frame.f.settings.cull};
    prepassLightPass(in, frame.shading, &v);
}

void RendererImpl::runPrepassShading(FrameRecord& frame, PassRun const& r) {
    prepassShadingPass({scene,
                        shaders.get(ProgramId::PrepassShade),
                        r.io.texture(Resource::DiffuseLight),
                        r.io.texture(Resource::SpecularLight),
                        {*r.fbo, r.io.texture(r.decl.color.front())}},
                       {frame.f.viewProj, frame.shading, frame.f.settings.normalMaps, r.decl.states});
}

}  // namespace gbl
