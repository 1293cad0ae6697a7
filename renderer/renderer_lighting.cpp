// The lighting modes' run functions: the light lists of tiled and clustered, the lighting pass of
// each mode and the coverage counts behind the heat-map views. Each draws into what its declaration
// (core/frame_passes.cpp) names, resolved by the executor (PassRun).
#include "renderer_impl.h"

#include "passes/coverage.h"
#include "passes/light_volumes.h"
#include "passes/lighting_quad.h"
#include "passes/lighting_tiled.h"

#include <algorithm>
#include <array>

namespace gbl {

LightingClusteredInput RendererImpl::clusteredInput(FrameContext const& f, FrameResources const& io,
                                                    gl::Texture const& image) {
    return {deferredInputs(f, io),
            shaders.get(ProgramId::ClusterBuild),
            binPrograms(ProgramId::ClusterBin),
            tileBins,
            shaders.get(ProgramId::ClusterShade),
            clusters,
            image,
            io.texture(Resource::SpecularLight),
            io.texture(Resource::Coverage),
            caps};
}

LightingClusteredConfig RendererImpl::clusteredConfig(FrameContext const& f, bool shade) const {
    return {f.view, f.projection, targets.width, targets.height, f.camera.nearPlane, f.camera.farPlane, shade, !shade};
}

TileBinPrograms RendererImpl::binPrograms(ProgramId bin) const {
    return {shaders.get(ProgramId::TileDepth), shaders.get(bin)};
}

// Tiled bins each tile's candidate lights, clustered also builds its clusters' lists: a pass of
// their own, so bench reports the lists apart from the shading that reads them.
void RendererImpl::runLightLists(FrameRecord& frame, PassRun const& r) {
    FrameContext const& f = frame.f;
    if (f.settings.mode == LightingMode::Clustered) {
        clusterListsPass(clusteredInput(f, r.io, r.io.texture(Resource::Lighting)), clusteredConfig(f, true));
        return;
    }
    // The depth it declares: the G-buffer's (tiled), or the depth pre-pass's (forward+, which also
    // bins the blended surfaces' lists when the scene has any: docs/transparency.md).
    bool const blended = f.settings.mode == LightingMode::ForwardPlus && hasBlended(scene);
    tileBinPass({binPrograms(ProgramId::TileBin), lights, r.io.texture(r.decl.samples.front()), tileBins, caps},
                {f.view, f.projection, targets.width, targets.height, f.camera.nearPlane, f.camera.farPlane, blended});
}

void RendererImpl::runLighting(FrameRecord& frame, PassRun const& r) {
    FrameContext const& f = frame.f;
    DeferredInputs const deferred = deferredInputs(f, r.io);
    // The lit image, or the diffuse light target of a split frame (the specular one beside it).
    Resource const out = r.decl.kind == PassKind::Compute ? r.decl.writes.front() : r.decl.color.front();
    gl::Texture const& image = r.io.texture(out);
    // msaa: the pass reads the multisampled G-buffer (as declared).
    bool const msaa =
        std::find(r.decl.samples.begin(), r.decl.samples.end(), Resource::MsaaNormal) != r.decl.samples.end();
    switch (f.settings.mode) {
        case LightingMode::Volumes:
            if (msaa) {  // the samples lit and averaged in the shader (docs/msaa.md)
                runMsaaVolumes(frame, r);
                break;
            }
            lightingVolumesPass({deferred,
                                 volumes,
                                 shaders.get(ProgramId::LightingQuad),
                                 shaders.get(ProgramId::LightVolume),
                                 shaders.get(ProgramId::LightVolumeStencil),
                                 triangle,
                                 {*r.fbo, image}},
                                {f.viewProj, f.settings.cull, r.decl.states});
            break;
        case LightingMode::Tiled:  // the tiles' candidates were binned in the frame's light_lists pass
            lightingTiledPass(
                {deferred, shaders.get(ProgramId::LightingTiled), binPrograms(ProgramId::TileBin), tileBins, image,
                 r.io.texture(Resource::SpecularLight), r.io.texture(Resource::Coverage), caps},
                {f.view, f.projection, targets.width, targets.height, f.camera.nearPlane, f.camera.farPlane, true,
                 false, true});
            break;
        case LightingMode::Clustered:  // the lists were built in the frame's light_lists pass
            clusterShadePass(clusteredInput(f, r.io, image), clusteredConfig(f, true));
            break;
        case LightingMode::Prepass:  // the thin G-buffer into the diffuse and specular light targets
            runPrepassLight(frame, r);
            break;
        default:
            if (msaa) {  // every sample, or sample 0 of the simple pixels (edges)
                bool const simple = f.settings.msaaLighting == MsaaLighting::Edges;
                lightingQuadPass({{gbufferTextures(r.io.targets.msaa.gbuffer), deferred.lights, deferred.shading},
                                  msaaProgram(simple ? "SAMPLE0" : ""),
                                  triangle,
                                  {*r.fbo, image},
                                  r.decl.states});
                break;
            }
            lightingQuadPass(
                {deferred, shaders.get(ProgramId::LightingQuad), triangle, {*r.fbo, image}, r.decl.states});
            break;
    }
}

void RendererImpl::runCoverage(FrameRecord& frame, PassRun const& r) {
    FrameContext const& f = frame.f;
    coverageView = f.settings.view;
    coverageMode = f.settings.mode;
    FrameResources const& io = r.io;
    if (f.settings.mode == LightingMode::Clustered && f.settings.view != DebugView::TileLights) {
        // x = the pixel's cluster list, y = lights that lit it: the heat map's scale, as tiles.
        clusterListsPass(clusteredInput(f, io, io.texture(Resource::Lighting)), clusteredConfig(f, false));
        clusterShadePass(clusteredInput(f, io, io.texture(Resource::Lighting)), clusteredConfig(f, false));
        return;
    }
    bool const forwardPlus = f.settings.mode == LightingMode::ForwardPlus;
    bool const tiles =
        f.settings.view == DebugView::TileLights || f.settings.mode == LightingMode::Tiled || forwardPlus;
    bool const volumeCounts = !tiles && f.settings.mode == LightingMode::Volumes && volumesReady();
    if (volumeCounts) prepareVolumeInstances(volumes, {f.camera, f.aspect, f.lights});
    bool const tiled = tiles && tiledReady();
    // forward+ counts the lists its frame binned over the pre-pass depth (the G-buffer is empty).
    LightingTiledConfig const t{
        f.view, f.projection, targets.width, targets.height, f.camera.nearPlane, f.camera.farPlane,
        false,  true,         forwardPlus};
    TileBinPrograms const bin = binPrograms(ProgramId::TileBin);
    // A compute count has no framebuffer of its own; the coverage target's is bound around it.
    std::array<Resource, 1> const counts{Resource::Coverage};
    gl::Framebuffer const& target = r.fbo ? *r.fbo : io.framebuffer(counts, std::nullopt);
    coveragePass(
        {deferredInputs(f, io), triangle, shaders.get(ProgramId::CoverageAllLights), volumeCounts ? &volumes : nullptr,
         volumeCounts ? &shaders.get(ProgramId::LightVolumeCoverage) : nullptr,
         volumeCounts ? &shaders.get(ProgramId::LightVolumeStencil) : nullptr,
         tiled ? &shaders.get(ProgramId::LightingTiled) : nullptr, tiled ? &bin : nullptr, tiled ? &tileBins : nullptr,
         target, io.texture(Resource::Coverage), io.texture(Resource::Lighting), caps},
        {f.settings.mode, f.settings.cull, f.settings.view, t, f.viewProj, r.decl.states});
}

}  // namespace gbl
