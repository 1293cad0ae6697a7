// prepass mode's run functions (deferred lighting, docs/deferred_lighting.md): each draws into what
// its declaration (core/frame_passes_prepass.cpp) names, resolved by the executor (PassRun).
#include "renderer_impl.h"

#include "passes/prepass.h"

namespace gbl {

void RendererImpl::runThinGBuffer(FrameRecord& frame, PassRun const& r) {
    prepassGeometryPass({scene, shaders.get(ProgramId::PrepassGeometry), *r.fbo},
                        {frame.f.viewProj, frame.shading, frame.f.settings.normalMaps, r.decl.states});
}

// The lighting pass of a prepass frame (runLighting hands it over).
void RendererImpl::runPrepassLight(FrameRecord& frame, PassRun const& r) {
    prepassLightPass({r.io.texture(Resource::PrepassNormal), r.io.texture(Resource::LitDepth), lights,
                      shaders.get(ProgramId::PrepassLight), triangle, *r.fbo, r.decl.states},
                     frame.shading);
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
